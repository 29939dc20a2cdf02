"""Golden values of hinge_cylindrical_ujoint: HINGE, CYLINDRICAL and UJOINT under F and M on b."""
import os
import sys

sys.dont_write_bytecode = True  # keep the deck directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from cae_lib import g, coincident_response  # noqa: E402

E = g.orientation([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], axis=3, angle_deg=30.0)  # "Datum csys-1"
ELEMENTS = [  # label, stiffnesses (0-based component index), node b
    (1, {3: 100.0}, "Point-2.1"),               # HINGE
    (2, {0: 1000.0, 3: 100.0}, "Point-4.1"),    # CYLINDRICAL
    (3, {3: 100.0, 5: 300.0}, "Point-6.1"),     # UJOINT
]
F, M = [10.0, 20.0, 30.0], [1.0, 2.0, 3.0]
names = []
for label, _, _ in ELEMENTS:
    names += [f"CTF{k}@{label}" for k in range(1, 7)] + [f"CU4@{label}"]
names += ["CU1@2", "CU6@3"]
names += [f"{v}{k}@{e[2]}" for e in ELEMENTS for v in ("U", "UR") for k in (1, 2, 3)]
rows = []
for tau in (0.0, 1.0):
    values, motion, extra = [], [], []
    for label, stiff, node in ELEMENTS:
        f, c, u, ur = coincident_response(E, g.scale(tau, F), g.scale(tau, M), stiff)
        values += f + [c[3]]
        motion += u + ur
        if label == 2:
            extra.append(c[0])
        if label == 3:
            extra.append(c[5])
    rows.append((1, 1 if tau else 0, tau, tau, values + extra + motion))
g.write_golden(__file__, [
    "hinge_cylindrical_ujoint: datum turned 30 deg about 3, F = (10, 20, 30), M = (1, 2, 3) on each node b",
    "closed form: f_i = e_i.F, f_{3+k} = e_k.M = CTF; available components move by f/k (HINGE 4;",
    "CYLINDRICAL 1, 4; UJOINT 4, 6), u_b and ur_b are the sums of CU_i e_i",
], names, rows)
