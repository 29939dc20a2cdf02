"""Golden values of axial_encastre_pull: AXIAL, k = 1000, l0 = 10, displacement driven."""
import os
import sys

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from cae_lib import g, AXIAL_PULL_COLUMNS, axial_pull_rows  # noqa: E402

K, L0 = 1000.0, 10.0
# (step, increment, step_time, total_time, u of node Point-2.1)
states = [(1, 0, 0.0, 0.0, 0.0)]
states += [(1, i, 0.25 * i, 0.25 * i, 0.2 * 0.25 * i) for i in (1, 2, 3, 4)]
# Step 2 ramps the prescribed u1 from 0.2 to 0.05 (RAMP amplitude, keywords.md §13).
states += [(2, i, 0.5 * i, 1.0 + 0.5 * i, 0.2 + (0.05 - 0.2) * 0.5 * i) for i in (1, 2)]
rows = axial_pull_rows(K, L0, states)
g.write_golden(__file__, [
    "axial_encastre_pull: AXIAL k = 1000, l0 = 10 along x, NLGEOM=NO, u1(b) prescribed",
    "closed form: CU1 = u1(b), CP1 = l0 + CU1, CTF1 = CEF1 = k CU1, RF1(a) = -k CU1, RF1(b) = +k CU1",
], AXIAL_PULL_COLUMNS, rows)
