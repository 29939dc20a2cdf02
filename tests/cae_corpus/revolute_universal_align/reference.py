"""Golden values of revolute_universal_align: REVOLUTE, UNIVERSAL and ALIGN under a moment on node b."""
import os
import sys

sys.dont_write_bytecode = True  # keep the deck directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from cae_lib import g, coincident_response  # noqa: E402

E = g.orientation([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], axis=2, angle_deg=30.0)  # "Datum csys-1"
M = [5.0, 3.0, -2.0]
F0 = [0.0, 0.0, 0.0]
names = ["CU4@1", "CTF4@1", "CTF5@1", "CTF6@1", "CRF5@1", "CRF6@1",
         "CU4@2", "CU6@2", "CTF4@2", "CTF5@2", "CTF6@2", "CRF5@2",
         "CTF4@3", "CTF5@3", "CTF6@3", "CRF4@3", "CRF5@3", "CRF6@3"]
for node in ("Point-2.1", "Point-4.1", "Point-6.1"):
    names += [f"UR{k}@{node}" for k in (1, 2, 3)]
rows = []
for tau in (0.0, 1.0):
    m = g.scale(tau, M)
    f1, c1, _, r1 = coincident_response(E, F0, m, {3: 100.0})
    f2, c2, _, r2 = coincident_response(E, F0, m, {3: 100.0, 5: 300.0})
    f3, c3, _, r3 = coincident_response(E, F0, m, {})
    values = [c1[3], f1[3], f1[4], f1[5], f1[4], f1[5],
              c2[3], c2[5], f2[3], f2[4], f2[5], f2[4],
              f3[3], f3[4], f3[5], f3[3], f3[4], f3[5]] + r1 + r2 + r3
    rows.append((1, 1 if tau else 0, tau, tau, values))
g.write_golden(__file__, [
    "revolute_universal_align: datum turned 30 deg about local 2, moment M = (5, 3, -2) on each node b",
    "closed form: f_k = e_k.M; REVOLUTE CU4 = f4/100, CRF5,6 = f5,6; UNIVERSAL CU4 = f4/100, CU6 = f6/300,",
    "CRF5 = f5; ALIGN CRF4..6 = f4..6; UR(b) = sum of CU_k e_k over the available components",
], names, rows)
