"""Golden values of iftomm_simple_pendulum: the IFToMM multibody benchmark A01 (simple pendulum,
L = 1, m = 1, g = 9.81, released at rest from the horizontal) over 5 s. The exact motion is that
of dynamic_pendulum's reference (Jacobi's elliptic functions, Abramowitz and Stegun 16.4 and 17.6),
reused here; U1, U2 are the motion of P1 from (1, 0), so that x = 1 + U1 and y = U2 are the
benchmark's reference quantities. Rows every 0.1 s.
"""
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import golden_lib as g  # noqa: E402

pendulum = g.case_reference("dynamic_pendulum")
# The same pendulum: the benchmark's data are those of dynamic_pendulum's reference.
assert (pendulum.L, pendulum.GRAV, pendulum.MASS) == (1.0, 9.81, 1.0)

rows = [(1, 0, 0.0, 0.0, [0.0, 0.0])]
for i in range(1, 51):
    t = 0.1 * i
    u1, u2, _, _ = pendulum.state(t)
    rows.append((1, i, t, t, [u1, u2]))

g.write_golden(__file__, [
    "iftomm_simple_pendulum: IFToMM benchmark A01, simple pendulum L = 1, m = 1, g = 9.81,",
    "released at rest from the horizontal; exact motion from Jacobi's elliptic functions",
    "(dynamic_pendulum's reference); rows every 0.1 s over 5 s",
], ["U1@2", "U2@2"], rows)
