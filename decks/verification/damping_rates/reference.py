"""Golden values of damping_rates: connector damping in *STATIC (behaviors.md §8).

Closed form: in an increment the velocity is v = (u_{n+1} - u_n)/dt, the viscous force is
CVF1 = c v (element 1) or table(v) (element 2, piecewise linear with LINEAR extrapolation,
behaviors.md §1.2), CEF1 = k u and CTF1 = CEF1 + CVF1 = RF1 at the driven node (+x). Row 0 has
no velocity (CVF1 = 0) and no reaction.
"""
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import golden_lib as g  # noqa: E402

K, C = 1000.0, 50.0
TABLE = [(-1.0, -10.0), (0.0, 0.0), (0.2, 3.0), (0.5, 7.0)]  # (velocity, force)


def table_force(v):
    """Piecewise linear in v, LINEAR extrapolation beyond both ends (the end segments' slopes)."""
    k = 0
    while k < len(TABLE) - 2 and v > TABLE[k + 1][0]:
        k += 1
    (v0, f0), (v1, f1) = TABLE[k], TABLE[k + 1]
    return f0 + (f1 - f0) / (v1 - v0) * (v - v0)


# (step, increments, step period, displacement at the step's start and end); the boundary
# ramps linearly over the step, so every increment of a step has the same velocity.
STEPS = [(1, 4, 1.0, 0.0, 0.1), (2, 4, 0.5, 0.1, 0.3), (3, 4, 0.25, 0.3, 0.0)]

names = []
for e in (1, 2):
    names += [f"CU1@{e}", f"CEF1@{e}", f"CVF1@{e}", f"CTF1@{e}"]
names += ["RF1@2", "RF1@4"]

rows = [(1, 0, 0.0, 0.0, [0.0] * len(names))]
total = 0.0
for step, count, period, start, end in STEPS:
    dt = period / count
    v = (end - start) / period
    for inc in range(1, count + 1):
        u = start + (end - start) * inc / count
        t = period * inc / count
        viscous = [C * v, table_force(v)]
        values = []
        for f_v in viscous:
            values += [u, K * u, f_v, K * u + f_v]
        values += [K * u + viscous[0], K * u + viscous[1]]
        rows.append((step, inc, t, total + t, values))
    total += period

assert abs(table_force(0.1) - 1.5) < 1e-15
assert abs(table_force(0.4) - (7.0 - 4.0 / 3.0 * 1.0)) < 1e-12  # inside the last segment
assert abs(table_force(-1.2) + 12.0) < 1e-12  # LINEAR below the first point, slope 10

g.write_golden(__file__, [
    "damping_rates: AXIAL, k = 1000; element 1 linear damping c = 50, element 2 NONLINEAR table",
    "closed form: v = du/dt per increment, CVF1 = c v or table(v) (LINEAR extrapolation),",
    "CEF1 = k CU1, CTF1 = RF1 = CEF1 + CVF1; row 0 has v = 0 (behaviors.md §8, §1.2)",
], names, rows)
