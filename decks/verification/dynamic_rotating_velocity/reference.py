"""Golden values of dynamic_rotating_velocity (docs/dynamics.md "Velocities at the start").

*INITIAL CONDITIONS, TYPE=ROTATING VELOCITY with omega = 3 about the axis from a = (1, 2, -1) to
b = (2, 4, 1) and the translational velocity c = (0.5, 0, -0.25): every node starts at
v = c + w x (x - a), w = omega (b - a)/|b - a|, and a node with rotational DOFs at VR = w. No
force or moment acts, so the motion is uniform: U = v t, V = v, UR = w t, VR = w (exactly, also
for the scheme, whose accelerations stay zero). Nodes 4-6 form a rigid body (small
displacements): its tie nodes move as v_ref + w x (x - x_ref) = c + w x (x - a), the same field."""
import math
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import golden_lib as g  # noqa: E402

A, B, C, OMEGA = [1.0, 2.0, -1.0], [2.0, 4.0, 1.0], [0.5, 0.0, -0.25], 3.0
NODES = {1: [0.0, 0.0, 0.0], 2: [3.0, -1.0, 2.0], 3: [2.0, 0.0, 0.0],
         4: [0.0, 1.0, 1.0], 5: [1.0, 1.0, 0.0], 6: [-1.0, 2.0, 3.0]}
# The node with a ROTARYI and the rigid body's nodes (reference 4, ties 5 and 6) have rotations.
ROTATING = {3, 4, 5, 6}
DT, OUTPUT_EVERY, T_END = 0.1, 5, 1.0

axis = g.sub(B, A)
w = g.scale(OMEGA / math.sqrt(g.dot(axis, axis)), axis)
v = {n: g.add(C, g.cross(w, g.sub(x, A))) for n, x in NODES.items()}

names, pick = [], []
for n in NODES:
    names += [f"U{i}@{n}" for i in (1, 2, 3)]
    pick.append(lambda t, n=n: g.scale(t, v[n]))
    if n in ROTATING:
        names += [f"UR{i}@{n}" for i in (1, 2, 3)]
        pick.append(lambda t: g.scale(t, w))
for n in NODES:
    names += [f"V{i}@{n}" for i in (1, 2, 3)]
    pick.append(lambda t, n=n: v[n])
    if n in ROTATING:
        names += [f"VR{i}@{n}" for i in (1, 2, 3)]
        pick.append(lambda t: w)

rows = []
for k in range(0, round(T_END / DT) + 1, OUTPUT_EVERY):
    t = k * DT
    rows.append((1, k, t, t, [value for f in pick for value in f(t)]))

g.write_golden(__file__, [
    "dynamic_rotating_velocity: omega = 3 about a = (1, 2, -1) -> b = (2, 4, 1), translation",
    "(0.5, 0, -0.25); free nodes: U = v t, V = v = c + w x (x - a), UR = w t, VR = w",
    "(docs/dynamics.md \"Velocities at the start\")",
], names, rows)
