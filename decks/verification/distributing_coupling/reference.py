"""Golden values of distributing_coupling: the manual's load distribution of a distributing
coupling (Abaqus Theory Guide, "Distributing coupling elements"): with normalised weights
w_n, centroid c = sum w_n x_n, arms r_n = x_n - c and T = sum w_n (|r_n|^2 I - r_n r_n^T),
coupling node n carries F_n = w_n (F + (T^-1 M^) x r_n), M^ = M + (x_ref - c) x F. Each coupling
node is held only by its springs, so a spring's force is that component of F_n. The reference
node moves like the point x_ref of a rigid body through the coupling nodes in the average sense:
u_ref = sum w_n u_n + theta x (x_ref - c), theta = T^-1 sum w_n r_n x u_n."""
import math
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import golden_lib as g  # noqa: E402

STIFFNESS = [100.0, 200.0, 400.0]
FORCE, MOMENT = [10.0, -20.0, 15.0], [5.0, 8.0, -12.0]
COUPLINGS = {
    100: ([0.2, 0.1, 0.5], "uniform", {1: [1.0, 0.0, 0.0], 2: [0.0, 1.5, 0.0],
                                       3: [-1.0, 0.2, 0.0], 4: [0.3, -1.0, 0.0],
                                       5: [0.5, 0.5, 0.4]}),
    200: ([10.0, 0.0, 0.0], "linear", {11: [11.0, 0.0, 0.0], 12: [10.0, 1.0, 0.0],
                                       13: [9.0, 0.0, 0.0], 14: [10.0, -2.0, 0.0]}),
}


def weights(x_ref, method, nodes):
    """UNIFORM: 1; LINEAR: 1 - r/r0, r the distance to the reference node and r0 the largest
    (no INFLUENCE RADIUS); normalised to sum 1."""
    if method == "uniform":
        raw = {n: 1.0 for n in nodes}
    else:
        r = {n: g.norm(g.sub(x, x_ref)) for n, x in nodes.items()}
        r0 = max(r.values())
        raw = {n: 1.0 - r[n] / r0 for n in nodes}
    total = sum(raw.values())
    return {n: w / total for n, w in raw.items()}


def inverse3(t):
    cols = [g.solve3(t, e) for e in ([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0])]
    return [[cols[j][i] for j in range(3)] for i in range(3)]


def distribute(ref):
    x_ref, method, nodes = COUPLINGS[ref]
    w = weights(x_ref, method, nodes)
    c = [sum(w[n] * x[k] for n, x in nodes.items()) for k in range(3)]
    arms = {n: g.sub(x, c) for n, x in nodes.items()}
    t = [[0.0] * 3 for _ in range(3)]
    for n, r in arms.items():
        for i in range(3):
            for j in range(3):
                t[i][j] += w[n] * ((g.dot(r, r) if i == j else 0.0) - r[i] * r[j])
    t_inv = inverse3(t)
    m_hat = g.add(MOMENT, g.cross(g.sub(x_ref, c), FORCE))
    spin = g.matvec(t_inv, m_hat)
    forces = {n: g.scale(w[n], g.add(FORCE, g.cross(spin, arms[n]))) for n in nodes}
    # Statics: the forces add up to F and their moment about x_ref to M.
    total = [sum(f[k] for f in forces.values()) for k in range(3)]
    moment = [0.0] * 3
    for n, f in forces.items():
        moment = g.add(moment, g.cross(g.sub(nodes[n], x_ref), f))
    g.assert_close(total + moment, FORCE + MOMENT, 1e-12, f"statics of coupling {ref}")
    u = {n: [f[k] / STIFFNESS[k] for k in range(3)] for n, f in forces.items()}
    mean = [sum(w[n] * u[n][k] for n in nodes) for k in range(3)]
    turn = [0.0] * 3
    for n in nodes:
        turn = g.add(turn, g.scale(w[n], g.cross(arms[n], u[n])))
    theta = g.matvec(t_inv, turn)
    return forces, g.add(mean, g.cross(theta, g.sub(x_ref, c))), theta


names = [f"{v}{i}@{n}" for n in (100, 200) for v in ("U", "UR") for i in (1, 2, 3)]
labels = []
for axis in range(3):
    for ref in (100, 200):
        labels += [(axis, ref, n) for n in COUPLINGS[ref][2]]
names += [f"S11@{100 * (axis + 1) + n}" for axis, _, n in labels]
solved = {ref: distribute(ref) for ref in COUPLINGS}
values = []
for ref in (100, 200):
    values += solved[ref][1] + solved[ref][2]
values += [solved[ref][0][n][axis] for axis, ref, n in labels]
rows = [(1, 0, 0.0, 0.0, [0.0] * len(names)), (1, 1, 1.0, 1.0, values)]
g.write_golden(__file__, [
    "distributing_coupling: F_n = w_n (F + (T^-1 M^) x r_n) at each coupling node (the manual's",
    "load distribution), F = (10, -20, 15), M = (5, 8, -12); uniform weights (node 100) and",
    "w = 1 - r/r0 (node 200); spring forces S11 = components of F_n; U, UR of the references",
    "from the weighted mean motion and the weighted rigid fit of the coupling nodes",
], names, rows)
