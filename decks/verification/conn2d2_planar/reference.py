"""Golden values of conn2d2_planar (connection-types.md §1.1, §2.1, §3.1, §3.4)."""
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import golden_lib as g  # noqa: E402

C30 = 0.8660254037844387
E = g.orientation([C30, 0.5, 0.0], [-0.5, C30, 0.0])
F = [10.0, 20.0, 0.0]
D0 = [1.0, 0.0, 0.0]


def moment_z(force, d0):
    """z-moment at node a of a force F carried to node b at d0: (F x d0)_z (B0 rows, §3.4)."""
    return g.cross(force, d0)[2]


names, v = [], []


def put(cols, vals):
    names.extend(cols)
    v.extend(vals)


# 1 CARTESIAN (ORI30), k = (1000, 2000): f_i = e_i . F, CU = f/k, U_b = sum CU_i e_i.
f = [g.dot(E[0], F), g.dot(E[1], F)]
cu = [f[0] / 1000.0, f[1] / 2000.0]
ub = g.add(g.scale(cu[0], E[0]), g.scale(cu[1], E[1]))
put(["CTF1@1", "CTF2@1", "CU1@1", "CU2@1", "U1@2", "U2@2"], f + cu + ub[:2])
put(["RF1@1", "RF2@1", "RM3@1"], [-F[0], -F[1], moment_z(F, D0)])
# 2 ROTATION, coincident nodes, k6 = 100, moment 2 at node b.
put(["CTF6@2", "CU6@2", "U1@4", "U2@4", "UR3@4"], [2.0, 0.02, 0.0, 0.0, 0.02])
put(["RF1@3", "RF2@3", "RM3@3"], [0.0, 0.0, -2.0])
# 3 SLOT (ORI30): component 1 elastic (k 1000), component 2 constrained (CU 0, CTF = f2).
cu1 = f[0] / 1000.0
ub = g.scale(cu1, E[0])
put(["CTF1@3", "CTF2@3", "CU1@3", "CU2@3", "U1@6", "U2@6"], f + [cu1, 0.0] + ub[:2])
put(["RF1@5", "RF2@5", "RM3@5"], [-F[0], -F[1], moment_z(F, D0)])
# 4 WELD (global axes): everything constrained; CTF = (F1, F2, M); node a RM3 = (F x d0)_z - M.
put(["CTF1@4", "CTF2@4", "CTF6@4", "CU1@4", "CU2@4", "CU6@4", "U1@8", "U2@8", "UR3@8"],
    [10.0, 20.0, 3.0] + [0.0] * 6)
put(["RF1@7", "RF2@7", "RM3@7"], [-F[0], -F[1], moment_z(F, D0) - 3.0])
rows = [(1, 0, 0.0, 0.0, [0.0] * len(names)), (1, 1, 1.0, 1.0, v)]
g.write_golden(__file__, [
    "conn2d2_planar: CONN2D2 with components 1, 2, 6 (dofs u1, u2, ur3); node a fixed,",
    "F = (10, 20) at node b: CARTESIAN/SLOT in ORI30 f_i = e_i . F, CU = f/k (SLOT: 2 constrained);",
    "ROTATION CTF6 = 2, CU6 = 0.02; WELD CTF = (10, 20, 3); node a RF = -F, RM3 = (F x d0)_z - M",
    "(connection-types.md §1.1, §2.1, §3.1, §3.4)",
], names, rows)
