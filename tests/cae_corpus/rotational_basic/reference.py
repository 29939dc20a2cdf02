"""Golden values of rotational_basic: CARDAN, EULER and FLEXION-TORSION under a prescribed small
rotation of node b (NLGEOM=NO: c = B0 theta_b with the small-rotation rows of
connection-types.md §3.3)."""
import os
import sys

sys.dont_write_bytecode = True  # keep the deck directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from cae_lib import g, ramp_rows  # noqa: E402

I3 = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]
X, Y = [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]
D4 = g.orientation(X, Y, axis=3, angle_deg=30.0)            # "Datum csys-4" (CARDAN at a and b)
EB = g.orientation(X, [0.0, 0.0, 1.0])                       # "Euler b": 90 deg about x
D5 = g.orientation(X, Y, axis=1, angle_deg=30.0)             # "Datum csys-5" (flexion 30 deg)
ELEMENTS = [  # label, angle function, frame a, frame b
    (1, g.cardan, D4, D4),
    (2, g.euler313, I3, EB),
    (3, g.flexion_torsion, I3, D5),
]
K = [100.0, 200.0, 400.0]
THETA = [0.01, -0.02, 0.015]  # prescribed rotation of every node b at the end of the step
NODES_B = {1: "Point-2.1", 2: "Point-4.1", 3: "Point-6.1"}

names = []
for label, *_ in ELEMENTS:
    names += [f"CU{k}@{label}" for k in (4, 5, 6)] + [f"CTF{k}@{label}" for k in (4, 5, 6)]
for label, *_ in ELEMENTS:
    names += [f"RM{k}@{NODES_B[label]}" for k in (1, 2, 3)]
B = {label: g.angle_rows(fn, ea, eb) for label, fn, ea, eb in ELEMENTS}
rows = []
for step, inc, st, tt, tau in [(1, 0, 0.0, 0.0, 0.0)] + ramp_rows(1, 0.0, 2):
    th = g.scale(tau, THETA)
    values, moments = [], []
    for label, *_ in ELEMENTS:
        c = [g.dot(B[label][k], th) for k in range(3)]
        f = [K[k] * c[k] for k in range(3)]
        values += c + f
        # The moment the connector exerts on node b (= RM at the prescribed rotations): B^T f.
        rm = [sum(B[label][k][j] * f[k] for k in range(3)) for j in range(3)]
        moments += rm if inc else [0.0, 0.0, 0.0]
    rows.append((step, inc, st, tt, values + moments))
g.write_golden(__file__, [
    "rotational_basic: CARDAN (datum turned 30 deg about 3), EULER (b turned 90 deg about x),",
    "FLEXION-TORSION (b turned 30 deg about x), k4/k5/k6 = 100/200/400, theta_b = (0.01, -0.02, 0.015) t",
    "closed form: c = B0 theta_b with B0 the small-rotation rows, evaluated by central differences",
    "of the exact angle functions (golden_lib.angle_rows); CTF = k c; RM(b) = B0^T CTF",
], names, rows)
