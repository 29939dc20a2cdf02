"""Golden values of connection_to_ground (connection-types.md §1.2, §2.2, §3.1, §3.4)."""
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import golden_lib as g  # noqa: E402

C30 = 0.8660254037844387
ORI30 = g.orientation([C30, 0.5, 0.0], [-0.5, C30, 0.0])
GLOBAL = g.orientation([1.0, 0.0, 0.0], [0.0, 1.0, 0.0])
K = [1000.0, 2000.0, 4000.0]
F = [10.0, 20.0, 30.0]
names, v = [], []


def put(cols, vals):
    names.extend(cols)
    v.extend(vals)


# 1: ground at b (fixed at node 1's initial position), global frame: c_i = e_i . (0 - u_a).
# Node a's force is -sum f_i e_i = F, so f = -F; u_a = -c.
f1 = [-x for x in F]
c1 = [f / k for f, k in zip(f1, K)]
put([f"CTF{i}@1" for i in (1, 2, 3)] + [f"CU{i}@1" for i in (1, 2, 3)], f1 + c1)
# node 1: U1-3 = -c, UR = 0 (held); RF1-3 = 0 (free), RM = sum f_i (e_i x d0) = 0 (d0 = 0).
put([f"U{i}@1" for i in (1, 2, 3)] + [f"UR{i}@1" for i in (1, 2, 3)], [-x for x in c1] + [0.0] * 3)
put([f"RF{i}@1" for i in (1, 2, 3)] + [f"RM{i}@1" for i in (1, 2, 3)], [0.0] * 6)
# 2: ground at a with ORI30 (fixed directions): c_i = e_i . u_b, f_i = e_i . F.
f2 = [g.dot(e, F) for e in ORI30]
c2 = [f / k for f, k in zip(f2, K)]
u2 = [0.0] * 3
for ci, e in zip(c2, ORI30):
    u2 = g.add(u2, g.scale(ci, e))
put([f"CTF{i}@2" for i in (1, 2, 3)] + [f"CU{i}@2" for i in (1, 2, 3)], f2 + c2)
put([f"U{i}@2" for i in (1, 2, 3)] + [f"RF{i}@2" for i in (1, 2, 3)], u2 + [0.0] * 3)
# 3: AXIAL, zero length, fixed axis n = e1 of ORI30 (§2.2): c = n . (d - d0) = -n . u_a.
n = ORI30[0]
ua3 = [0.01, 0.0, 0.0]
c3 = -g.dot(n, ua3)
f3 = 1000.0 * c3
put(["CTF1@3", "CU1@3"], [f3, c3])
# node a's internal force is -f n (row [-n ; 0 ; n ; 0] with b grounded); RF = internal.
put([f"U{i}@3" for i in (1, 2, 3)] + [f"RF{i}@3" for i in (1, 2, 3)], ua3 + g.scale(-f3, n))
# 4: ROTATION, ground at a: c = theta_b (global frame), m = M, c = M / k.
m4 = [1.0, 2.0, 3.0]
c4 = [m / k for m, k in zip(m4, [100.0, 200.0, 400.0])]
put([f"CTF{i}@4" for i in (4, 5, 6)] + [f"CU{i}@4" for i in (4, 5, 6)], m4 + c4)
put([f"U{i}@4" for i in (1, 2, 3)] + [f"UR{i}@4" for i in (1, 2, 3)], [0.0] * 3 + c4)
put([f"RF{i}@4" for i in (1, 2, 3)] + [f"RM{i}@4" for i in (1, 2, 3)], [0.0] * 6)
rows = [(1, 0, 0.0, 0.0, [0.0] * len(names)), (1, 1, 1.0, 1.0, v)]
g.write_golden(__file__, [
    "connection_to_ground: the ground point starts on the live node and never moves; its",
    "directions are the initial ones at that end. 1: c = -u_a, f = -F; 2: c_i = e_i . u_b,",
    "f_i = e_i . F (ORI30); 3: AXIAL of zero length along e1 of ORI30, c = -n . u_a;",
    "4: ROTATION, c = theta_b (connection-types.md §1.2, §2.2, §3.1, §3.4)",
], names, rows)
