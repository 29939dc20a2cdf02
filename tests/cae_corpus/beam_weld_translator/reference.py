"""Golden values of beam_weld_translator: BEAM, WELD and TRANSLATOR under a force and a moment on b."""
import os
import sys

sys.dont_write_bytecode = True  # keep the deck directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from cae_lib import g, coincident_response  # noqa: E402

X, Y = [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]
GLOBAL = [X, Y, [0.0, 0.0, 1.0]]
ELEMENTS = [  # label, frame, stiffnesses (0-based component index), node b
    (1, GLOBAL, {}, "Point-2.1"),                                       # BEAM, default axes
    (2, g.orientation(X, Y, axis=3, angle_deg=30.0), {}, "Point-4.1"),   # WELD, "Weld csys"
    (3, g.orientation(X, Y, axis=1, angle_deg=30.0), {0: 1000.0}, "Point-6.1"),  # TRANSLATOR
]
F, M = [10.0, 20.0, 30.0], [1.0, 2.0, 3.0]
names = [f"CTF{k}@{e[0]}" for e in ELEMENTS for k in range(1, 7)] + ["CU1@3"]
names += [f"{v}{k}@{e[3]}" for e in ELEMENTS for v in ("U", "UR") for k in (1, 2, 3)]
rows = []
for tau in (0.0, 1.0):
    values, cu, motion = [], 0.0, []
    for label, frame, stiff, node in ELEMENTS:
        f, c, u, ur = coincident_response(frame, g.scale(tau, F), g.scale(tau, M), stiff)
        values += f
        motion += u + ur
        if label == 3:
            cu = c[0]
    rows.append((1, 1 if tau else 0, tau, tau, values + [cu] + motion))
g.write_golden(__file__, [
    "beam_weld_translator: F = (10, 20, 30), M = (1, 2, 3) on each node b, node a fixed",
    "closed form: CTF_i = e_i.F, CTF_{3+k} = e_k.M (JOIN/SLOT rows at b carry F, ALIGN rows carry M);",
    "TRANSLATOR CU1 = e1.F/1000 and u_b = CU1 e1; BEAM (nodes 1 apart) and WELD do not move",
], names, rows)
