"""Golden values of damage_energy (behaviors.md §7.2 ENERGY, §7.5 E13).

Closed form (damage_lib.py): u_0 = 0.09, W = k((u_0 + κ)² − u_0²)/2 = 500 (U² − 0.0081) on the
envelope, d = 1 − exp(−W/G_f), d = 1 once d ≥ 0.99, CTF1 = (1 − d) k U. Asserts the §7.5 E13
table, and that the energy dissipated after initiation, the area under element 2's force–motion
history from u_0 to failure, is G_f: exactly G_f (1 − e^(−W_s/G_f)) for the continuous curve up to
the switch at W_s, and within 1.1 % for the trapezoidal area of the history rows. After its
deletion element 2 has CTF1 = 0, CDMG = 1 and CDIF frozen, while CU1 goes on reporting the
prescribed motion of node 4 up to 0.35 (behaviors.md §7.4, output-variables.md §2).
"""
import math
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import damage_lib as dl  # noqa: E402
import golden_lib as g  # noqa: E402

K, G_F = 1000.0, 10.0
e13, fail = dl.ElasticDamage(K, 90.0, ("ENERGY", G_F)), dl.ElasticDamage(K, 90.0, ("ENERGY", G_F))

path = [(1, 0, 0.0, 0.0, 0.0, 0.0)]
path += [(1, i, 0.25 * i, 0.25 * i, 0.05 * i, 0.0) for i in range(1, 5)]
path += [(2, i, 0.0025 * i, 1.0 + 0.0025 * i, 0.2, 0.0025 * i) for i in range(1, 141)]

names = ["CU1@1", "CU1@2", "CTF1@1", "CTF1@2", "CDMG@1", "CDMG@2", "CDIF@1", "CDIF@2"]
rows, e13_rows, curve = [], {}, [(0.0, 0.0)]
deleted = False
for step, inc, st, tt, u1, u2 in path:
    f1, d1, r1 = e13.update(u1) if inc > 0 else (0.0, 0.0, 0.0)
    if deleted:
        # behaviors.md §7.4, output-variables.md §2: no force, CDMG = 1, CDIF frozen; CU1 goes on
        # reporting the prescribed motion of node 4.
        f2, d2, r2 = 0.0, 1.0, fail.r_max
    else:
        f2, d2, r2 = fail.update(u2) if inc > 0 else (0.0, 0.0, 0.0)
        curve.append((u2, f2))
        deleted = d2 >= 1.0
    e13_rows[round(u1, 6)] = (d1, f1)
    rows.append((step, inc, st, tt, [u1, u2, f1, f2, d1, d2, r1, r2]))

# §7.5 E13: (U, W, CDMG, CTF1).
for u, w, d, f in ((0.10, 0.95, 0.090627066, 90.937293), (0.15, 7.2, 0.513247744, 73.012838),
                   (0.20, 15.95, 0.797091471, 40.581706)):
    dl.check(500.0 * (u * u - 0.0081), w, 1e-12, f"E13 W at {u}")
    dl.check(e13_rows[u][0], d, 5e-10, f"E13 CDMG at {u}")
    dl.check(e13_rows[u][1], f, 5e-7, f"E13 CTF1 at {u}")

# Energy dissipated after initiation: the continuous envelope up to the last state before the
# switch gives G_f (1 − e^(−W_s/G_f)) exactly (∫ e^(−W/G_f) dW), i.e. G_f within the 1 % the
# 0.99 switch leaves; the rows' trapezoidal area (the failed row drops the force to 0) agrees
# with G_f to 1 %.
u_s = max(u for u, f in curve if f > 0.0)
w_s = 0.5 * K * (u_s * u_s - 0.09 ** 2)
exact = G_F * (1.0 - math.exp(-w_s / G_F))
area = sum(0.5 * (fa + fb) * (ub - ua) for (ua, fa), (ub, fb) in zip(curve, curve[1:]) if ua >= 0.09)
dl.check(exact / G_F, 0.99, 0.0015, "continuous dissipated energy / G_f")
dl.check(area / G_F, exact / G_F, 1e-3, "trapezoidal area against the continuous curve")
dl.check(area / G_F, 1.0, 0.011, "trapezoidal area of the history / G_f")
dl.check(rows[-1][4][1], 0.35, 1e-15, "CU1 of the deleted element 2 at the end")

g.write_golden(__file__, [
    "damage_energy: AXIAL k = 1000, FORCE initiation at 90, TYPE=ENERGY G_f = 10 (behaviors.md",
    "§7.2). Element 1 = E13 (U -> 0.2 in 4 incr.); element 2 driven to 0.35 in 140 incr., fails",
    f"(d >= 0.99 -> 1) at U = {u_s + 0.0025:.4f}. W = 500 (U^2 - 0.0081), d = 1 - exp(-W/G_f).",
    f"Dissipated after initiation: continuous {exact:.6f} = {exact / G_F:.6f} G_f; trapezoidal",
    f"area of the history rows {area:.6f} = {area / G_F:.6f} G_f. After deletion: CTF1 = 0, CDMG = 1,",
    "CDIF frozen, CU1 = the motion of node 4 (behaviors.md §7.4)",
], names, rows)
