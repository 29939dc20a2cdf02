"""Golden values of planar_bushing: PLANAR and BUSHING under F and M on b (small displacement)."""
import os
import sys

sys.dont_write_bytecode = True  # keep the deck directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from cae_lib import g, coincident_response  # noqa: E402

E = g.orientation([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], axis=3, angle_deg=30.0)  # "Datum csys-1"
PLANAR = {1: 500.0, 2: 800.0, 3: 100.0}
BUSHING = {0: 1000.0, 1: 2000.0, 2: 3000.0, 3: 100.0, 4: 200.0, 5: 300.0}
F, M = [10.0, 20.0, 30.0], [1.0, 2.0, 3.0]
names = ["CU2@1", "CU3@1", "CU4@1"] + [f"CTF{k}@1" for k in range(1, 7)]
names += [f"CU{k}@2" for k in range(1, 7)] + [f"CTF{k}@2" for k in range(1, 7)]
names += [f"{v}{k}@{n}" for n in ("Point-2.1", "Point-4.1") for v in ("U", "UR") for k in (1, 2, 3)]
rows = []
for tau in (0.0, 1.0):
    fp, cp, up, rp = coincident_response(E, g.scale(tau, F), g.scale(tau, M), PLANAR)
    fb, cb, ub, rb = coincident_response(E, g.scale(tau, F), g.scale(tau, M), BUSHING)
    values = cp[1:4] + fp + cb + fb + up + rp + ub + rb
    rows.append((1, 1 if tau else 0, tau, tau, values))
g.write_golden(__file__, [
    "planar_bushing: datum turned 30 deg about 3, F = (10, 20, 30), M = (1, 2, 3) on each node b",
    "closed form: f_i = e_i.F, f_{3+k} = e_k.M = CTF; PLANAR moves in 2, 3 (500, 800) and turns about 1 (100);",
    "BUSHING (projection types, mid frame = frame a at zero rotation) c_i = f_i/k_i for all six",
], names, rows)
