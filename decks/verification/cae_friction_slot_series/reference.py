"""Golden values of cae_friction_slot_series (friction.md §2.3, §4.1; connection-types.md §4).

Node a of the SLOT (node 1) is held, node c (3, the far end of the CARTESIAN spring) is driven
along X by U_c(t), node b (2, the slider) is free in X and Y and loaded across the slot by P(t).
Small displacements, coincident nodes, global axes: the SLOT holds b's Y (V = 0) and its
constraint force carries the load, f2 = P, so F_N = |P| (§2.3) and F_lim = mu |P|, whatever the
friction force does. Along X, b is in equilibrium between the friction force f1 of the slot and
the spring, f1 = k_d (U_c - u), with u = U1 of b = CU1 of the slot. The friction force is the
backward-Euler update of §4.1 from the committed slip u_s (friction_lib.Friction), a
nondecreasing function of u, so the equation has one root per increment; it is found in closed
form: the stick candidate u = (k_d U_c + k u_s)/(k_d + k) if |k (u - u_s)| <= F_lim, else slip
with f1 = sgn(k (u - u_s)) F_lim and u = U_c - f1/k_d; the update is then committed through
friction_lib and the equilibrium asserted. With P = 0 (lift-off) the capacity is zero, f1 = 0,
u = U_c and every motion is slip (§4.1 step 5).
"""
import math
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import golden_lib as g  # noqa: E402
import friction_lib as fl  # noqa: E402

K, KD, MU = 11000.0, 16357.0, 0.5856
PRESS = [(0.0, 0.0), (0.014258, 0.0), (0.280393, -227.237), (0.559104, 386.917),
         (0.791772, 0.0), (0.890704, 0.0), (0.931771, 0.0), (0.942285, 0.0), (1.0, 256.348)]
SLIDE = [(0.0, 0.0), (0.014258, -0.0986531), (0.280393, -0.0720333), (0.559104, -0.125670),
         (0.791772, -0.0393104), (0.890704, 0.0667223), (0.931771, 0.177009),
         (0.942285, 0.205070), (1.0, 0.231774)]

slot = fl.Friction(K, fl.Constant(MU))
names = fl.columns(["CU1", "CSF1", "CNF1", "CSLIPST1", "CASU1", "CTF2"], [1]) + ["U1@2"]
rows = [(1, 0, 0.0, 0.0, [0.0] * len(names))]
status = []
for inc, t in enumerate(fl.increments(0.01, 1.0), start=1):
    uc, p = g.tabular(t, SLIDE), g.tabular(t, PRESS)
    flim = MU * abs(p)
    us = slot.us[0]
    u = (KD * uc + K * us) / (KD + K)
    if abs(K * (u - us)) > flim:
        u = uc - math.copysign(flim, K * (u - us)) / KD
    f1 = slot.update([u], abs(p), 0.01)[0]
    assert abs(f1 - KD * (uc - u)) <= 1e-9 * max(1.0, flim), (t, f1, KD * (uc - u))
    status.append(slot.status)
    rows.append((1, inc, t, t, [u, f1, slot.fn, float(slot.status), slot.gamma, p, u]))
# No stick/slip decision is a near-tie that round-off could flip (trials at least 1e-6 from the
# surface, relative).
fl.check_margins([("slot", slot)])
# The path sticks and slips in both directions, slips through the lift-off (P = 0 from
# t = 0.79 to 0.94) and the normal force changes sign twice while the slider slides.
assert 0 < sum(status) < len(status), status
assert any(r[4][1] > 0 and r[4][3] == 1 for r in rows) and any(r[4][1] < 0 and r[4][3] == 1
                                                              for r in rows)

g.write_golden(__file__, [
    "cae_friction_slot_series: CONN2D2 SLOT with PREDEFINED friction (mu = 0.5856, k = 11000)",
    "pushed through a CARTESIAN spring (k_d = 16357) driven at its far end, the force across the",
    "slot changing sign through a lift-off; F_N = |P|, one root per increment of",
    "f1(u) = k_d (U_c - u), closed form (stick or slip), committed through friction_lib.",
], names, rows)
