"""Golden values of slot_friction: predefined SLOT friction at a constant normal load."""
import os
import sys

sys.dont_write_bytecode = True  # keep the deck directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from cae_lib import g, ramp_rows, local_components  # noqa: E402,F401

MU, KS, FN = 0.3, 1.0e4, 1000.0
names = ["CU1@1", "CSF1@1", "CNF1@1", "CASU1@1", "CTF1@1", "CTF2@1", "RF1@Point-2.1", "U2@Point-2.1"]
rows = [(1, 0, 0.0, 0.0, [0.0] * 8)]
rows.append((1, 1, 1.0, 1.0, [0.0, 0.0, FN, 0.0, 0.0, -FN, 0.0, 0.0]))
us = 0.0
for step, inc, st, tt, tau in ramp_rows(2, 1.0, 8):
    u = 0.1 * tau
    trial = KS * (u - us)
    if abs(trial) > MU * FN:
        us = u - MU * FN / KS
    f = KS * (u - us)
    rows.append((step, inc, st, tt, [u, f, FN, us, f, -FN, f, 0.0]))
g.write_golden(__file__, [
    "slot_friction: SLOT, *Connector Friction, predefined, stick stiffness 1e4, mu = 0.3; normal load -1000",
    "(step 1), then u1 -> 0.1 in 8 increments: stick to 0.03, slip after (friction.md §7.1)",
    "closed form: CNF1 = |f2| = 1000, CSF1 = min(1e4 u1, 300), CASU1 = max(0, u1 - 0.03), CTF1 = RF1 = CSF1",
], names, rows)
