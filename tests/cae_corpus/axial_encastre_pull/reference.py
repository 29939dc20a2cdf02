"""Golden values of axial_encastre_pull: AXIAL, k = 1000, l0 = 10, displacement driven."""
import os
import sys

sys.dont_write_bytecode = True
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "..", "decks", "verification"))
import golden_lib as g  # noqa: E402

K, L0 = 1000.0, 10.0
names = ["CP1@1", "CTF1@1", "CU1@1", "CEF1@1", "RF1@Point-1.1", "RF1@Point-2.1",
         "U1@Point-1.1", "U1@Point-2.1"]
# (step, increment, step_time, total_time, u of node Point-2.1)
states = [(1, 0, 0.0, 0.0, 0.0)]
states += [(1, i, 0.25 * i, 0.25 * i, 0.2 * 0.25 * i) for i in (1, 2, 3, 4)]
# Step 2 ramps the prescribed u1 from 0.2 to 0.05 (RAMP amplitude, keywords.md §13).
states += [(2, i, 0.5 * i, 1.0 + 0.5 * i, 0.2 + (0.05 - 0.2) * 0.5 * i) for i in (1, 2)]
rows = []
for step, inc, st, tt, u in states:
    f = K * u
    rows.append((step, inc, st, tt, [L0 + u, f, u, f, -f, f, 0.0, u]))
g.write_golden(__file__, [
    "axial_encastre_pull: AXIAL k = 1000, l0 = 10 along x, NLGEOM=NO, u1(b) prescribed",
    "closed form: CU1 = u1(b), CP1 = l0 + CU1, CTF1 = CEF1 = k CU1, RF1(a) = -k CU1, RF1(b) = +k CU1",
], names, rows)
