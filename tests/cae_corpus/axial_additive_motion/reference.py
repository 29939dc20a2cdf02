"""Golden values of axial_additive_motion: linear + nonlinear elasticity on one component (they add),
driven through a series connector by *Connector Motion."""
import os
import sys

sys.dont_write_bytecode = True  # keep the deck directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from cae_lib import g, ramp_rows, local_components  # noqa: E402,F401

TABLE = [(-100.0, -0.1), (0.0, 0.0), (50.0, 0.1), (250.0, 0.2)]  # (force, displacement)


def table(u):
    for (fa, ua), (fb, ub) in zip(TABLE, TABLE[1:]):
        if u <= ub:
            return fa + (fb - fa) * (u - ua) / (ub - ua)
    raise SystemExit("outside the table")


names = ["CU1@1", "CEF1@1", "CTF1@1", "CU1@2", "CRF1@2", "CTF1@2",
         "U1@Point-1.1", "U1@Point-2.1", "U1@Point-3.1",
         "RF1@Point-1.1", "RF1@Point-2.1", "RF1@Point-3.1"]
# Element 2 (no behaviour) has its length change prescribed: -0.2 in step 1, then +0.05 in
# step 2 (RAMP from the current value). Node 2 moves by u = -CU1@2.
states = [(1, 0, 0.0, 0.0, 0.0)]
states += [(s, i, st, tt, -0.2 * tau) for s, i, st, tt, tau in ramp_rows(1, 0.0, 4)]
states += [(s, i, st, tt, -0.2 + 0.25 * tau) for s, i, st, tt, tau in ramp_rows(2, 1.0, 4)]
rows = []
for step, inc, st, tt, cu2 in states:
    u = -cu2
    f = 1000.0 * u + table(u)
    rows.append((step, inc, st, tt, [u, f, f, cu2, f, f, 0.0, u, 0.0, -f, 0.0, f]))
g.write_golden(__file__, [
    "axial_additive_motion: AXIAL with *Connector Elasticity 1000 plus a NONLINEAR table on component 1",
    "(they add, behaviors.md §2), in series with an AXIAL whose CU1 is prescribed by *Connector Motion",
    "closed form: u = -CU1@2, CTF1@1 = CEF1@1 = 1000 u + table(u) = CTF1@2 = CRF1@2, RF1 = -/+ CTF1 at the ends",
], names, rows)
