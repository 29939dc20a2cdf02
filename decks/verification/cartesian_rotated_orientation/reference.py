"""Golden values of cartesian_rotated_orientation (connection-types.md §1.3, §3.4, §5.1)."""
import math
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import golden_lib as g  # noqa: E402

C30 = 0.8660254037844387
E30 = g.orientation([C30, 0.5, 0.0], [-0.5, C30, 0.0])
E30B = g.orientation([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], axis=3, angle_deg=30.0)
# Second route: the extra rotation must reproduce the triad given by points.
for a, b in zip(E30, E30B):
    g.assert_close(a, b, 1e-15, "ORI30 vs ORI30B")
g.assert_close(E30[0], [math.cos(math.pi / 6), math.sin(math.pi / 6), 0.0], 1e-15, "e1")

K = [1000.0, 2000.0, 4000.0]
D0 = [1.0, 0.0, 0.0]
LOADS = {1: [C30, 0.5, 0.0], 2: [-0.5, C30, 0.0], 3: [0.0, 0.0, 1.0]}
LOADS = {el: g.scale(100.0, v) for el, v in LOADS.items()}
LOADS[4] = [10.0, 20.0, 30.0]
FRAMES = {1: E30, 2: E30, 3: E30, 4: E30B}
NODE_A = {1: 1, 2: 3, 3: 5, 4: 7}
NODE_B = {1: 2, 2: 4, 3: 6, 4: 8}


def solve(el, t):
    """Node a fixed: equilibrium at b is sum f_i e_i = F, so f_i = e_i . F (orthonormal
    triad); c_i = f_i / k_i; u_b = sum c_i e_i; node a: RF = -F, RM = sum f_i (e_i x d0)."""
    e = FRAMES[el]
    load = g.scale(t, LOADS[el])
    f = [g.dot(ei, load) for ei in e]
    c = [fi / ki for fi, ki in zip(f, K)]
    ub = [0.0, 0.0, 0.0]
    rm = [0.0, 0.0, 0.0]
    for ci, fi, ei in zip(c, f, e):
        ub = g.add(ub, g.scale(ci, ei))
        rm = g.add(rm, g.scale(fi, g.cross(ei, D0)))
    # Second route for the reaction moment: it must balance the moment of F applied at d0.
    g.assert_close(rm, g.scale(-1.0, g.cross(D0, load)), 1e-12, "moment balance")
    return f, c, ub, g.scale(-1.0, load), rm


names = []
for el in (1, 2, 3, 4):
    names += [f"CTF{i}@{el}" for i in (1, 2, 3)] + [f"CU{i}@{el}" for i in (1, 2, 3)]
    names += [f"U{i}@{NODE_B[el]}" for i in (1, 2, 3)]
    names += [f"RF{i}@{NODE_A[el]}" for i in (1, 2, 3)] + [f"RM{i}@{NODE_A[el]}" for i in (1, 2, 3)]
rows = []
for inc, t in enumerate([0.0, 0.5, 1.0]):
    values = []
    for el in (1, 2, 3, 4):
        f, c, ub, rf, rm = solve(el, t)
        values += f + c + ub + rf + rm
    rows.append((1, inc, t, t, values))
g.write_golden(__file__, [
    "cartesian_rotated_orientation: CARTESIAN, k = (1000, 2000, 4000), ORI30 (e1 = (cos30,",
    "sin30, 0)); node a fixed, load F at node b: CTF_i = e_i . F, CU_i = CTF_i / k_i,",
    "U_b = sum CU_i e_i, RF_a = -F, RM_a = sum CTF_i (e_i x d0) = F x d0 (NLGEOM=NO)",
    "(connection-types.md §1.3, §3.4, §4, §5.1; keywords.md §6 for the extra rotation)",
], names, rows)
