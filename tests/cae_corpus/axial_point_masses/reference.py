"""Golden values of axial_point_masses: AXIAL, k = 1000, l0 = 10, displacement driven, with
MASS and ROTARYI elements on both connector nodes, which a *STATIC step does not use: the
closed form is that of the same connector without them."""
import os
import sys

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from cae_lib import g, AXIAL_PULL_COLUMNS, axial_pull_rows  # noqa: E402

K, L0 = 1000.0, 10.0
# (step, increment, step_time, total_time, u of node Point-2.1)
states = [(1, 0, 0.0, 0.0, 0.0)]
states += [(1, i, 0.25 * i, 0.25 * i, 0.2 * 0.25 * i) for i in (1, 2, 3, 4)]
rows = axial_pull_rows(K, L0, states)
g.write_golden(__file__, [
    "axial_point_masses: AXIAL k = 1000, l0 = 10 along x, NLGEOM=NO, u1(b) prescribed;",
    "MASS 2.5 at both nodes and ROTARYI at b carry no stiffness and are not used by *STATIC",
    "closed form: CU1 = u1(b), CP1 = l0 + CU1, CTF1 = CEF1 = k CU1, RF1(a) = -k CU1, RF1(b) = +k CU1",
], AXIAL_PULL_COLUMNS, rows)
