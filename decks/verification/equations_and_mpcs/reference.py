"""Golden values of equations_and_mpcs: every constraint written as linear equations C u = 0 on
the nodes' own DOFs and solved with Lagrange multipliers (the KKT system of the springs), an
independent route from clinch's elimination (small displacements)."""
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import golden_lib as g  # noqa: E402

X = {1: [0, 0, 0], 2: [1, 0, 0], 3: [0, 1, 0], 4: [1, 1, 0], 5: [2, 1, 0], 11: [1, 0.5, 0],
     12: [0, 0, 0], 21: [0, 3, 0], 22: [0.5, 3, 0], 31: [2, 3, 1], 32: [2, 3, 0], 41: [1, 2, 0],
     42: [0, 0, 0]}
SPRINGS = [(1, 1, 100.0), (2, 1, 100.0), (3, 2, 100.0), (4, 2, 100.0), (5, 2, 100.0)]
for node in (12, 22, 32, 42, 41):
    SPRINGS += [(node, 1, 1000.0), (node, 2, 2000.0), (node, 3, 3000.0)]
for node in (12, 32):
    SPRINGS += [(node, 4, 500.0), (node, 5, 600.0), (node, 6, 700.0)]
LOADS = {(2, 1): 30.0, (4, 2): 10.0, (5, 2): 20.0, (11, 2): 10.0, (11, 3): 5.0, (21, 1): 7.0,
         (21, 3): -4.0, (31, 1): 6.0, (31, 5): 3.0, (41, 1): 4.0, (41, 2): 10.0}
DOFS = [(n, d) for n in sorted(X) for d in range(1, 7)]
INDEX = {key: i for i, key in enumerate(DOFS)}

equations = [{(1, 1): 1.0, (2, 1): -2.0}, {(3, 2): 1.0, (4, 2): -0.5, (5, 2): -0.25}]
# BEAM 11 -> 12: u11 = u12 + theta12 x r, theta11 = theta12, r = X11 - X12.
r = g.sub(X[11], X[12])
for k in range(3):
    row = {(11, k + 1): 1.0, (12, k + 1): -1.0}
    for i in range(3):  # (theta x r)_k = theta . (r x e_k)
        c = g.cross(r, [1.0 if j == k else 0.0 for j in range(3)])[i]
        if c:
            row[(12, 4 + i)] = -c
    equations.append(row)
    equations.append({(11, 4 + k): 1.0, (12, 4 + k): -1.0})
for k in range(1, 4):  # PIN 21 -> 22: translations equal
    equations.append({(21, k): 1.0, (22, k): -1.0})
for k in range(1, 7):  # TIE 31 -> 32: every DOF equal
    equations.append({(31, k): 1.0, (32, k): -1.0})
n0 = g.unit(g.sub(X[41], X[42]))  # LINK 41 - 42, linearised: n0 . (u41 - u42) = 0
equations.append({(41, k + 1): n0[k] for k in range(3)} | {(42, k + 1): -n0[k] for k in range(3)})

size = len(DOFS) + len(equations)
a = [[0.0] * size for _ in range(size)]
b = [0.0] * size
for node, dof, k in SPRINGS:
    a[INDEX[(node, dof)]][INDEX[(node, dof)]] += k
for key, f in LOADS.items():
    b[INDEX[key]] += f
for m, row in enumerate(equations):
    for key, c in row.items():
        a[len(DOFS) + m][INDEX[key]] = c
        a[INDEX[key]][len(DOFS) + m] = c
# DOFs that neither a spring nor a constraint reaches stay zero (their rows are 0 = 0).
used = {INDEX[(n, d)] for n, d, _ in SPRINGS} | {INDEX[key] for row in equations for key in row}
for i in range(len(DOFS)):
    if i not in used:
        a[i][i] = 1.0
u = g.solve(a, b)

# The columns clinch writes: the DOFs active at each node (output-variables.md §3).
ACTIVE = {1: [1], 2: [1], 3: [2], 4: [2], 5: [2]}
names, picks = [], []
for node in (1, 2, 3, 4, 5, 11, 12, 21, 22, 31, 32, 41, 42):
    for dof in ACTIVE.get(node, [1, 2, 3]):
        names.append(f"U{dof}@{node}")
        picks.append(INDEX[(node, dof)])
rows = [(1, 0, 0.0, 0.0, [0.0] * len(picks)), (1, 1, 1.0, 1.0, [u[i] for i in picks])]
# Hand checks of the first two systems: u2 = 30/(4 k + k) with u1 = 2 u2.
g.assert_close([u[INDEX[(2, 1)]], u[INDEX[(1, 1)]]], [30.0 / 500.0, 60.0 / 500.0], 1e-14,
               "lever ratio 2")
g.write_golden(__file__, [
    "equations_and_mpcs: *EQUATION u1 = 2 u2 and u3 = 0.5 u4 + 0.25 u5, MPC BEAM (rigid arm),",
    "PIN, TIE and LINK (n0 . (u41 - u42) = 0) on nodes held by SPRING1s; solved as a KKT system",
    "with Lagrange multipliers (reference.py), one linear increment",
], names, rows)
