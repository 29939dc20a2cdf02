"""Golden values of dynamic_stick_slip_rate: the oscillator of dynamic_stick_slip with a
rate-weakening slider, whose slip force is F(rate) = F_int (mu_k + (mu_s - mu_k) exp(-d rate))
(*FRICTION, EXPONENTIAL DECAY; friction.md §3). In the return of an increment the rate is the
increment's slip over its time increment, dl/dt, as in a static step (friction.md §3.3), and the
stick test uses the force at rest, F(0) (friction.md §4.1).

The rows are the HHT-alpha recurrence of dynamic_stick_slip/reference.py (TRANSIENT FIDELITY, the
deck's increments) with this slip force: each slip increment is one equation in dl, solved there
by bisection to round-off.
"""
import math
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import golden_lib as g  # noqa: E402

stick_slip = g.case_reference("dynamic_stick_slip")
F_INTERNAL = stick_slip.F_INTERNAL
MU_STATIC, MU_KINETIC, DECAY = 0.12, 0.1, 1.0


def decaying(rate):
    return F_INTERNAL * (MU_KINETIC + (MU_STATIC - MU_KINETIC) * math.exp(-DECAY * rate))


rows = stick_slip.recurrence(stick_slip.DT, stick_slip.PERIOD, decaying)
# The slider slips and sticks: it slips at a force between the kinetic and the static one, and
# ends stuck below the static one with the accumulated slip unchanged over the last 0.3 s.
forces = [abs(state[3]) for state in rows]
g.assert_close([max(forces)], [MU_STATIC * F_INTERNAL], 0.02 * F_INTERNAL, "largest slip force")
last = round(0.3 / stick_slip.DT)
g.assert_close([rows[-1][5]], [rows[-1 - last][5]], 0.0, "no slip at the end")
g.write_golden(__file__, [
    "dynamic_stick_slip_rate: m = 1, spring k = 100 in parallel with a slider of stick stiffness",
    "1e4 and slip force 100 (0.1 + 0.02 exp(-dl/dt)), released at u = 0 with v = 10; HHT-alpha",
    "(TRANSIENT FIDELITY) on the deck's increments, each increment solved branch by branch",
], ["CSF1@1", "CASU1@1", "U1@2", "V1@2", "A1@2"],
    [(1, inc, inc * stick_slip.DT, inc * stick_slip.DT, [f, slipped, u, v, a])
     for inc, (u, v, a, f, _, slipped) in enumerate(rows)])
