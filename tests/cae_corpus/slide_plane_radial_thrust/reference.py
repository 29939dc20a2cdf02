"""Golden values of slide_plane_radial_thrust: SLIDE-PLANE and RADIAL-THRUST, global datum axes."""
import os
import sys

sys.dont_write_bytecode = True  # keep the deck directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from cae_lib import g, ramp_rows  # noqa: E402

F1 = [40.0, 10.0, -16.0]  # SLIDE-PLANE node b (coincident nodes, normal e1 = x)
F2 = [60.0, 0.0, 30.0]    # RADIAL-THRUST node b at radius 1 along x, axis e3 = z; u2 held
names = ["CU2@1", "CU3@1", "CTF1@1", "CTF2@1", "CTF3@1", "CRF1@1", "CU1@2", "CU3@2", "CTF1@2",
         "CTF3@2", "U1@Point-2.1", "U2@Point-2.1", "U3@Point-2.1",
         "U1@Point-4.1", "U2@Point-4.1", "U3@Point-4.1"]
rows = []
for step, inc, st, tt, tau in [(1, 0, 0.0, 0.0, 0.0)] + ramp_rows(1, 0.0, 2):
    a = g.scale(tau, F1)
    b = g.scale(tau, F2)
    # SLIDE-PLANE: f1 is the constraint force, u2 = f2/500, u3 = f3/800.
    # RADIAL-THRUST (NLGEOM=NO): u1 = e_r0.(u_b - u_a) with e_r0 = x, u3 = z.(u_b - u_a).
    sp = [a[1] / 500.0, a[2] / 800.0, a[0], a[1], a[2], a[0]]
    rt = [b[0] / 2000.0, b[2] / 1000.0, b[0], b[2]]
    rows.append((step, inc, st, tt, sp + rt + [0.0, sp[0], sp[1], rt[0], 0.0, rt[1]]))
g.write_golden(__file__, [
    "slide_plane_radial_thrust: SLIDE-PLANE k2 = 500, k3 = 800 (normal x); RADIAL-THRUST k1 = 2000, k3 = 1000",
    "closed form: SLIDE-PLANE CTF1 = CRF1 = Fx, CU2 = Fy/k2, CU3 = Fz/k3; RADIAL-THRUST (r0 = 1 along x,",
    "circumferential u2 held) CU1 = Fx/k1 (radial), CU3 = Fz/k3 (axial)",
], names, rows)
