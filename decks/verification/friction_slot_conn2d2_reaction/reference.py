"""Golden values of friction_slot_conn2d2_reaction (friction.md §2.2, §2.3, §4.1, §4.4).

Inclined CONN2D2 SLOT (ORI30: e1 = (c, s), e2 = (-s, c), keywords.md §6), node a fixed, node b
driven in X (U) and free in Y with the load P. Kinematics (connection-types.md §2.1, §3.4, node
a fixed, coincident nodes): the constraint e2 . u_b = 0 gives V = U s/c, and u1 = e1 . u_b.
Statics at node b (internal force = f1 e1 + f2 e2, connection-types.md §4):
    dof 2 (free):       s f1 + c f2 = P          ->  f2 = (P - s f1)/c
    dof 1 (prescribed): RF1 = c f1 - s f2
Friction (predefined SLOT, F_N = |f2|, mu = 0.3, k = 1e4), closed form per increment from the
committed slip u_s,n, f_tr = k (u1 - u_s,n):
    stick: f1 = f_tr, consistent iff |f_tr| <= mu |(P - s f_tr)/c|;
    slip:  f1 = sigma mu |f2| with sigma = sgn(f_tr); then c f2 + s sigma mu |f2| = P, which is
           strictly increasing in f2 (c > s mu), so f2 = P/(c + s sigma mu sgn(P));
           consistent iff |f_tr| > mu |f2|; u_s += sigma (|f_tr| - |f1|)/k.
The map f1 -> mu |f2(f1)| has Lipschitz constant mu s/c = 0.17 < 1, so exactly one of the two is
consistent (asserted: one and only one candidate passes in every increment).
"""
import math
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import golden_lib as g  # noqa: E402
import friction_lib as fl  # noqa: E402

K, MU = 1.0e4, 0.3
E1, E2, _ = g.orientation([0.8660254037844387, 0.5, 0.0], [-0.5, 0.8660254037844387, 0.0])
C, S = E1[0], E1[1]
assert abs(E2[0] + S) <= 1e-16 and abs(E2[1] - C) <= 1e-16
NRM = [(0.0, 1.0), (0.5, 2.0), (1.0, 0.5)]
NRM2 = [(0.0, 0.5), (1.0, 1.5)]

us, gamma = 0.0, 0.0
margins = []


def update(u1, p):
    global us, gamma
    ftr = K * (u1 - us)
    f2_stick = (p - S * ftr) / C
    stick = abs(ftr) - MU * abs(f2_stick) <= fl.STICK_TOL * max(abs(ftr), MU * abs(f2_stick))
    sigma = math.copysign(1.0, ftr)
    sp = math.copysign(1.0, p) if p != 0.0 else 0.0
    f2_slip = p / (C + S * sigma * MU * sp) if p != 0.0 else 0.0
    slip = abs(ftr) > MU * abs(f2_slip)
    scale = max(abs(ftr), MU * abs(f2_stick), 1e-300)
    margins.append(min(abs(abs(ftr) - MU * abs(f2_stick)) / scale,
                       abs(abs(ftr) - MU * abs(f2_slip)) / max(abs(ftr), 1e-300)))
    assert stick != slip, (u1, p, ftr, f2_stick, f2_slip)
    if stick:
        return ftr, f2_stick, 0
    f1 = sigma * MU * abs(f2_slip)
    dg = (abs(ftr) - abs(f1)) / K
    us += sigma * dg
    gamma += dg
    assert abs(S * f1 + C * f2_slip - p) <= 1e-12 * max(1.0, abs(p))  # equilibrium of dof 2
    return f1, f2_slip, 1


steps = [  # (step, dt, U target, load(t))
    (1, 1.0, 0.0, lambda t: fl.ramp(0.0, -1000.0, t, 1.0)),
    (2, 0.0625, 0.1, lambda t: -1000.0 * g.tabular(t, NRM)),
    (3, 0.0625, -0.05, lambda t: -1000.0 * g.tabular(t, NRM2)),
    (4, 0.125, None, lambda t: fl.ramp(-1500.0, -200.0, t, 1.0)),
]
names = fl.columns(["CU1", "CSF1", "CNF1", "CSLIPST1", "CASU1", "CTF1", "CTF2", "CRF2"], [80])
names += ["U2@2", "RF1@2"]
rows = [(1, 0, 0.0, 0.0, [0.0] * len(names))]
U, t0 = 0.0, 0.0
status, forces = [], []
for step, dt, target, load in steps:
    U0 = U
    for inc, t in enumerate(fl.increments(dt, 1.0), start=1):
        U = U0 if target is None else fl.ramp(U0, target, t, 1.0)
        V = U * S / C  # slot constraint e2 . u_b = 0
        u1 = C * U + S * V
        p = load(t)
        f1, f2, st = update(u1, p)
        status.append(st)
        forces.append((step, f1, f2))
        rf1 = C * f1 - S * f2
        rows.append((step, inc, t, t0 + t,
                     [u1, f1, abs(f2), float(st), gamma, f1, f2, f2, V, rf1]))
    t0 += 1.0
assert min(margins) >= 1e-6, min(margins)

# The normal force depends on the friction force: in forward slip F_N = |P|/(c - s mu), in
# backward slip |P|/(c + s mu) (P < 0 throughout).
for step, f1, f2 in forces:
    assert f2 < 0.0
fwd = [abs(f2) / abs(f2 * C + S * f1) for step, f1, f2 in forces if step == 2 and f1 > 0
       and abs(abs(f1) - MU * abs(f2)) <= 1e-9 * abs(f1)]
bwd = [abs(f2) / abs(f2 * C + S * f1) for step, f1, f2 in forces if step == 3 and f1 < 0
       and abs(abs(f1) - MU * abs(f2)) <= 1e-9 * abs(f1)]
assert fwd and bwd
assert all(abs(x - 1.0 / (C - S * MU)) <= 1e-12 for x in fwd)
assert all(abs(x - 1.0 / (C + S * MU)) <= 1e-12 for x in bwd)
# Pattern: step 2 sticks for 9 increments while the load (and the capacity) grows, then slips
# while the capacity rises and falls; step 3 sticks 3 increments on reversal, then slips
# backwards; step 4 slips in every increment without motion (the capacity falls below the force).
assert status == ([0] + [0] * 9 + [1] * 7 + [0] * 3 + [1] * 13 + [1] * 8), status

g.write_golden(__file__, [
    "friction_slot_conn2d2_reaction: CONN2D2 SLOT along ORI30, PREDEFINED friction mu = 0.3,",
    "k = 1e4; node b: X driven, Y loaded by P(t); F_N = |f2| with f2 = (P - f1 sin30)/cos30 from",
    "statics, so the normal force depends on the friction force. Closed form per increment",
    "(stick or slip, exactly one consistent, asserted).",
], names, rows)
