"""Golden values of friction_square_path (friction.md §2.3, §4.1, §4.4).

SLIDE-PLANE friction, P = sqrt(f2^2 + f3^2), K_s = k I, F_N = |f1| = 410 (the plane constraint
force balances the normal load), F_lim = 0.25 * 410 = 102.5. Backward-Euler radial return per
increment from the committed state, which is exact for this discretisation (the deck's increments):
    f_tr = k (u - u_s,n);  stick if |f_tr| <= F_lim: f = f_tr;
    slip: f = F_lim f_tr/|f_tr|,  dgamma = (|f_tr| - F_lim)/k,  u_s += dgamma f_tr/|f_tr|.
Asserted properties: |CSF| = F_lim to 1e-12 in every slip row; CSF parallel to and in the sense
of the slip increment du_s; in stick rows CSF changes by k du and CASU does not change; the
dissipation F_lim dgamma equals CSF . du_s; the stick/slip pattern (loop 2: the first three
increments after every corner stick, because the force still carries the component of the leg
before the previous one, which opposes the new direction); no decision within 1e-6 of the
surface. Element 40 (PREDEFINED) and element 41 (circular potential, CONTACT FORCE=1) are equal.
"""
import math
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import golden_lib as g  # noqa: E402
import friction_lib as fl  # noqa: E402

K, MU, LOAD, L = 1.0e4, 0.25, -410.0, 0.02
FLIM = MU * abs(LOAD)
CORNERS = [(L, 0.0), (L, L), (0.0, L), (0.0, 0.0)] * 2

lib = fl.Friction(K, fl.Constant(MU), ncomp=2)
us = [0.0, 0.0]
gamma = 0.0
ids = ["CU2", "CU3", "CSF2", "CSF3", "CNF2", "CNF3", "CSLIPST2", "CSLIPST3", "CASU2", "CASU3",
       "CTF1"]
names = fl.columns(ids, [40, 41]) + fl.columns(["CSFC", "CNFC", "CASUC"], [41])
names += fl.columns(["RF2", "RF3"], [2, 4])
rows = [(1, 0, 0.0, 0.0, [0.0] * len(names))]
pattern = []


def emit(step, inc, t, total, u, load):
    global us, gamma
    fn = abs(load)
    ftr = [K * (a - b) for a, b in zip(u, us)]
    m = math.hypot(*ftr)
    f_prev = list(lib.f)
    f = lib.update(u, fn, 0.125)
    if m <= MU * fn:
        st, dus = 0, [0.0, 0.0]
        assert lib.status == 0 and max(abs(a - b) for a, b in zip(f, ftr)) <= 1e-12 * FLIM
    else:
        st = 1
        dg = (m - MU * fn) / K
        dus = [dg * x / m for x in ftr]
        us = [a + b for a, b in zip(us, dus)]
        gamma += dg
        assert lib.status == 1 and abs(lib.gamma - gamma) <= 1e-15
        assert max(abs(a - b) for a, b in zip(lib.us, us)) <= 1e-15
        assert abs(math.hypot(*f) - FLIM) <= 1e-12 * FLIM  # |CSF| = mu F_N
        cross = f[0] * dus[1] - f[1] * dus[0]
        assert abs(cross) <= 1e-12 * FLIM * dg and f[0] * dus[0] + f[1] * dus[1] > 0.0
        assert abs(f[0] * dus[0] + f[1] * dus[1] - FLIM * dg) <= 1e-12 * FLIM * max(dg, 1e-3)
    if st == 0 and step > 1:  # elastic change k du from the previous converged force
        du = [a - b for a, b in zip(u, emit.u_prev)]
        assert max(abs(f[i] - f_prev[i] - K * du[i]) for i in range(2)) <= 1e-9
    emit.u_prev = list(u)
    pattern.append(st)
    v = {"CU2": u[0], "CU3": u[1], "CSF2": f[0], "CSF3": f[1], "CNF2": fn, "CNF3": fn,
         "CSLIPST2": float(st), "CSLIPST3": float(st), "CASU2": gamma, "CASU3": gamma,
         "CTF1": load}
    values = [v[i] for i in ids for _ in (40, 41)]
    values += [math.hypot(*f), fn, gamma]
    values += [f[0], f[0], f[1], f[1]]  # RF2@2, RF2@4, RF3@2, RF3@4 = CSF2, CSF3
    rows.append((step, inc, t, total, values))


emit.u_prev = [0.0, 0.0]
emit(1, 1, 1.0, 1.0, [0.0, 0.0], LOAD)
u = [0.0, 0.0]
for side, corner in enumerate(CORNERS, start=2):
    u0 = list(u)
    for inc, t in enumerate(fl.increments(0.125, 1.0), start=1):
        u = [fl.ramp(a, b, t, 1.0) for a, b in zip(u0, corner)]
        emit(side, inc, t, side - 1 + t, u, LOAD)
fl.check_margins([("square", lib)])

# Stick/slip pattern: step 1 stick; side 1: 4 stick (from zero force, 102.5/250 per increment)
# then slip; side 2 (first 90-degree corner, force along +2 exactly): slip at once; side 3: two
# stick increments; sides 4-8: three stick increments after the corner, then slip.
sides = [pattern[1 + 8 * i:9 + 8 * i] for i in range(8)]
assert pattern[0] == 0
assert sides[0] == [0, 0, 0, 0, 1, 1, 1, 1] and sides[1] == [1] * 8
assert sides[2] == [0, 0, 1, 1, 1, 1, 1, 1]
assert all(s == [0, 0, 0, 1, 1, 1, 1, 1] for s in sides[3:]), sides

g.write_golden(__file__, [
    "friction_square_path: SLIDE-PLANE, mu = 0.25, k = 1e4, normal load -410 (F_lim = 102.5);",
    "(u2, u3) twice around the square (0,0)-(0.02,0)-(0.02,0.02)-(0,0.02)-(0,0), 8 increments",
    "per side. Element 40 PREDEFINED, element 41 circular potential with CONTACT FORCE=1. Radial",
    "return per increment (backward Euler, exact for these increments); |CSF| = F_lim in slip,",
    "CSF parallel to du_s, three stick increments after every corner of loop 2 (asserted).",
], names, rows)
