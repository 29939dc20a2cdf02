"""Golden values of kinematic_couplings: each body's reference node moves by q = (u, theta) with
K q = (F, M), K = sum k g g^T over its springs, g = (e, r x e) the gradient of the spring's DOF
(u + theta x r) . e, r the arm from the reference node (small displacements)."""
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import golden_lib as g  # noqa: E402

AXES = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]
STIFFNESS = [100.0, 200.0, 300.0]
LOAD = [50.0, -30.0, 80.0, 20.0, 40.0, -60.0]
BODIES = {  # reference node: (its position, coupling nodes and positions)
    10: ([0.0, 0.0, 0.0], {11: [1.0, 1.0, 0.0], 12: [-1.0, 1.0, 0.0], 13: [-1.0, -1.0, 0.0],
                           14: [1.0, -1.0, 0.0]}),
    20: ([5.0, 0.0, 0.0], {21: [6.0, 0.5, 0.3], 22: [4.0, 0.5, 0.3], 23: [4.0, -0.5, 0.3],
                           24: [6.0, -0.5, 0.3]}),
}


def body_motion(ref, load):
    x_ref, nodes = BODIES[ref]
    k6 = [[0.0] * 6 for _ in range(6)]
    for x in nodes.values():
        r = g.sub(x, x_ref)
        for e, k in zip(AXES, STIFFNESS):
            grad = e + g.cross(r, e)
            for i in range(6):
                for j in range(6):
                    k6[i][j] += k * grad[i] * grad[j]
    return g.solve(k6, load)


def node_motion(ref, q, node):
    x_ref, nodes = BODIES[ref]
    r = g.sub(nodes[node], x_ref)
    return g.add(q[:3], g.cross(q[3:], r))


# Element labels: 1{0,1,2}n on body 10's node 1n, 2{0,1,2}n on body 20's node 2n (x, y, z).
springs_x = [101, 102, 103, 104, 201, 202, 203, 204]
springs_z = [121, 122, 123, 124, 221, 222, 223, 224]
names = [f"U{i}@{n}" for n in (10, 11, 20, 21) for i in (1, 2, 3)]
names += [f"UR{i}@{n}" for n in (10, 20, 21) for i in (1, 2, 3)]
names += [f"S11@{e}" for e in springs_x + springs_z]
rows = []
for inc, t in enumerate([0.0, 0.5, 1.0]):
    q = {ref: body_motion(ref, g.scale(t, LOAD)) for ref in BODIES}
    values = q[10][:3] + node_motion(10, q[10], 11) + q[20][:3] + node_motion(20, q[20], 21)
    # Node 21 follows every DOF of node 20 (*KINEMATIC without data lines); node 11 only the
    # translations, and its rotations take no part.
    values += q[10][3:] + q[20][3:] + q[20][3:]
    for label in springs_x + springs_z:
        ref = 10 if label < 200 else 20
        axis = 0 if label % 100 < 10 else 2
        node = ref + label % 10
        values.append(STIFFNESS[axis] * node_motion(ref, q[ref], node)[axis])
    rows.append((1, inc, t, t, values))
g.write_golden(__file__, [
    "kinematic_couplings: rigid motion q of each reference node from K q = (F, M), K = sum k g g^T",
    "over the SPRING1s (k = 100, 200, 300 along x, y, z) at its coupling nodes, g = (e, r x e);",
    "F = (50, -30, 80), M = (20, 40, -60) at both references; spring force S11 = k (u + theta x r).e",
], names, rows)
