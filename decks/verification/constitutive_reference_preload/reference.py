"""Golden values of constitutive_reference_preload (behaviors.md §3, R1)."""
import math
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import golden_lib as g  # noqa: E402

K1, L0, REF1, U = 1000.0, 10.0, 9.9, 0.1
K4, REF4, PHI = 200.0, math.radians(5.0), 0.05  # reference angles are degrees (§3)

names = ["CTF1@1", "CEF1@1", "CU1@1", "CCU1@1", "CP1@1",
         "CTF4@2", "CEF4@2", "CU4@2", "CCU4@2", "CP4@2", "CTF5@2", "CTF6@2",
         "RF1@1", "RF2@1", "RF3@1", "RF1@2", "RF2@2", "RF3@2",
         "RF1@4", "RF2@4", "RF3@4", "RM1@4", "RM2@4", "RM3@4"]
rows = []
for inc, t in ((0, 0.0), (1, 1.0)):
    c1 = U * t
    p1 = L0 + c1
    u1 = p1 - REF1          # constitutive motion u = p - ref (behaviors.md §1.1)
    f1 = K1 * u1
    c4 = PHI * t            # ROTATION, aligned frames: p4 = phi_1 of node b
    u4 = c4 - REF4
    f4 = K4 * u4
    solved = inc > 0        # row 0: reactions are 0, forces are the preload (output-variables §1.4)
    rf1 = [-f1 if solved else 0.0, 0.0, 0.0]
    rf2 = [f1 if solved else 0.0, 0.0, 0.0]
    # ROTATION row for node b is [0 ; -e_k ; 0 ; e_k] (aligned frames): RM1@4 = +m4.
    rf4 = [0.0, 0.0, 0.0, f4 if solved else 0.0, 0.0, 0.0]
    rows.append((1, inc, t, t, [f1, f1, c1, u1, p1, f4, f4, c4, u4, c4, 0.0, 0.0]
                 + rf1 + rf2 + rf4))
g.write_golden(__file__, [
    "constitutive_reference_preload: u = p - ref; AXIAL k = 1000, l0 = 10, ref = 9.9:",
    "row 0 CCU1 = 0.1, CTF1 = 100; t = 1 CU1 = 0.1, CCU1 = 0.2, CTF1 = 200, RF1@2 = 200.",
    "ROTATION k = 200, ref4 = 5 deg: CTF4 = 200 (c4 - 5 pi/180) (behaviors.md §3, R1)",
], names, rows)
