"""Golden values of conn2d2_cartesian_rotation: CONN2D2 with CARTESIAN + ROTATION and SLOT."""
import os
import sys

sys.dont_write_bytecode = True  # keep the deck directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from cae_lib import g, ramp_rows, local_components  # noqa: E402,F401

E = g.orientation([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], axis=3, angle_deg=30.0)  # "Datum csys-1"
F1, M1, F2 = [30.0, 40.0, 0.0], 2.0, [10.0, 20.0, 0.0]
names = ["CU1@1", "CU2@1", "CU6@1", "CTF1@1", "CTF2@1", "CTF6@1", "CU1@2", "CTF1@2", "CTF2@2",
         "CRF2@2", "U1@Point-2.1", "U2@Point-2.1", "U1@Point-4.1", "U2@Point-4.1"]
rows = []
for step, inc, st, tt, tau in [(1, 0, 0.0, 0.0, 0.0)] + ramp_rows(1, 0.0, 2):
    f = local_components(E, g.scale(tau, F1))
    c = [f[0] / 1000.0, f[1] / 2000.0, tau * M1 / 100.0]
    u1 = g.add(g.scale(c[0], E[0]), g.scale(c[1], E[1]))
    s = local_components(E, g.scale(tau, F2))
    u2 = g.scale(s[0] / 500.0, E[0])
    rows.append((step, inc, st, tt, c + [f[0], f[1], tau * M1, s[0] / 500.0, s[0], s[1], s[1],
                                         u1[0], u1[1], u2[0], u2[1]]))
g.write_golden(__file__, [
    "conn2d2_cartesian_rotation: CONN2D2, datum turned 30 deg about 3; CARTESIAN+ROTATION k = 1000/2000/100",
    "under F = (30, 40), M = 2; SLOT k1 = 500 under F = (10, 20)",
    "closed form: CTF_i = e_i.F, CU_i = CTF_i/k_i, CU6 = M/k6; SLOT CTF2 = CRF2 = e2.F; u_b = sum CU_i e_i",
], names, rows)
