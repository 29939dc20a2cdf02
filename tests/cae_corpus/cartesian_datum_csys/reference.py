"""Golden values of cartesian_datum_csys: CARTESIAN in a rotated datum system, force and connector
load, one linear increment (NLGEOM=NO)."""
import os
import sys

sys.dont_write_bytecode = True  # keep the deck directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from cae_lib import g  # noqa: E402

# "Datum csys-1": a = (1,0,0), b = (0,1,0), additional rotation 30 degrees about local axis 3.
E = g.orientation([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], axis=3, angle_deg=30.0)
K = [1000.0, 2000.0, 4000.0]
F = [100.0, 50.0, 0.0]  # *Cload on node b (global)
P3 = 40.0  # *Connector Load on component 3
names = ["CU1@1", "CU2@1", "CU3@1", "CEF1@1", "CEF2@1", "CEF3@1", "CTF1@1", "CTF2@1", "CCF3@1",
         "RF1@Point-1.1", "RF2@Point-1.1", "RF3@Point-1.1",
         "U1@Point-2.1", "U2@Point-2.1", "U3@Point-2.1"]
rows = []
for tau in (0.0, 1.0):
    f = [g.dot(E[0], F) * tau, g.dot(E[1], F) * tau, P3 * tau]  # CEF_i: generalised forces
    c = [f[i] / K[i] for i in range(3)]
    u = [0.0, 0.0, 0.0]
    for i in range(3):
        u = g.add(u, g.scale(c[i], E[i]))
    # RF at a = internal force - applied load there: -(sum CEF_i e_i) - (-P3 e3) = -F.
    rf = g.scale(-tau, F)
    rows.append((1, 1 if tau else 0, tau, tau, c + f + [f[0], f[1], P3 * tau] + rf + u))
g.write_golden(__file__, [
    "cartesian_datum_csys: CARTESIAN, orientation a=(1,0,0) b=(0,1,0) + 30 deg about 3, k = 1000/2000/4000",
    "closed form: CEF_i = e_i.F (i = 1, 2), CEF3 = connector load 40, CU_i = CEF_i/k_i, u_b = sum CU_i e_i,",
    "CTF_i = CEF_i (i = 1, 2), CCF3 = 40, RF(a) = -F (the connector load is an equal and opposite pair)",
], names, rows)
