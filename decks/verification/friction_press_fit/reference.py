"""Golden values of friction_press_fit (friction.md §2.2, §2.4, §4.1).

User-defined COMPONENT=1 friction without CONTACT FORCE: F_N = |F_int(gamma)|, with F_int
piecewise linear through (gamma, F_int) = (0, 100), (0.02, 300), (0.05, 400); beyond 0.05
EXTRAPOLATION=CONSTANT (element 60) or LINEAR (element 61, slope 100/0.03). mu = 0.45, k = 1e4.
Per increment from the committed state (gamma_n, u_s,n):
    f_tr = k (u1 - u_s,n);  stick if |f_tr| <= mu F_int(gamma_n);
    slip: |f_tr| - k dg - mu F_int(gamma_n + dg) = 0 on [0, |f_tr|/k], solved by bisection to
    the last bit (strictly decreasing: k + mu dF_int/dgamma > 0); the root may cross a
    breakpoint of the table inside the increment (asserted to happen);
    f1 = sgn(f_tr) mu F_int(gamma_n + dg), u_s += sgn(f_tr) dg, gamma += dg.
CNF1 is reported as F_int(gamma) of the converged state.
"""
import math
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import golden_lib as g  # noqa: E402
import friction_lib as fl  # noqa: E402
import plastic_lib as pl  # noqa: E402

K, MU = 1.0e4, 0.45
POINTS = [(0.0, 100.0), (0.02, 300.0), (0.05, 400.0)]  # (gamma, F_int)
BREAKS = [p[0] for p in POINTS]


def f_int(gamma, linear):
    """The table written out on its own (independent of plastic_lib.Hardening)."""
    if gamma <= 0.0:
        return POINTS[0][1]
    for (ga, fa), (gb, fb) in zip(POINTS, POINTS[1:]):
        if gamma <= gb:
            return fa + (fb - fa) * (gamma - ga) / (gb - ga)
    if not linear:
        return POINTS[-1][1]
    (ga, fa), (gb, fb) = POINTS[-2], POINTS[-1]
    return fb + (fb - fa) / (gb - ga) * (gamma - gb)


class PressFit:
    def __init__(self, linear):
        self.linear = linear
        self.us, self.gamma = 0.0, 0.0
        self.crossings = 0

    def update(self, u1):
        ftr = K * (u1 - self.us)
        if abs(ftr) <= MU * f_int(self.gamma, self.linear):
            return ftr, 0, 0.0
        gn = self.gamma

        def phi(dg):
            return abs(ftr) - K * dg - MU * f_int(gn + dg, self.linear)

        dg = pl.bisect_decreasing(phi, 0.0, abs(ftr) / K)
        assert abs(phi(dg)) <= 1e-12 * abs(ftr)
        self.crossings += sum(1 for b in BREAKS if gn < b < gn + dg)
        self.us += math.copysign(dg, ftr)
        self.gamma = gn + dg
        return math.copysign(MU * f_int(self.gamma, self.linear), ftr), 1, dg


models = {60: (PressFit(False), fl.Friction(K, fl.Constant(MU), f_int=pl.Hardening(
                  [(f, gm) for gm, f in POINTS], linear=False))),
          61: (PressFit(True), fl.Friction(K, fl.Constant(MU), f_int=pl.Hardening(
                  [(f, gm) for gm, f in POINTS], linear=True)))}
steps = [(1, 1.0, 0.1), (2, 1.5, -0.05), (3, 1.5, 0.1)]  # (step, period, target u1); dt = 0.1
ids = ["CU1", "CSF1", "CNF1", "CSLIPST1", "CASU1", "CTF1"]
names = fl.columns(ids, [60, 61]) + fl.columns(["RF1"], [2, 4])
rows, u, t0 = [], 0.0, 0.0
status = {60: [], 61: []}
for step, period, target in steps:
    u0 = u
    for inc, t in enumerate(fl.increments(0.1, period), start=1):
        u = fl.ramp(u0, target, t, period)
        per = {}
        for el in (60, 61):
            ref, lib = models[el]
            f, st, dg = ref.update(u)
            f_lib = lib.update([u], 0.0, 0.1)[0]
            assert abs(f - f_lib) <= 1e-11 * 300.0 and lib.status == st, (el, step, inc)
            assert abs(ref.gamma - lib.gamma) <= 1e-14
            fn = f_int(ref.gamma, ref.linear)
            assert abs(lib.fn - fn) <= 1e-11 * fn
            if st:
                assert abs(abs(f) - MU * fn) <= 1e-12 * fn  # |CSF1| = mu F_N in slip
            per[el] = [u, f, fn, float(st), ref.gamma, f]
            status[el].append(st)
        values = [x for pair in zip(per[60], per[61]) for x in pair]
        values += [per[60][1], per[61][1]]
        rows.append((step, inc, t, t0 + t, values))
    t0 += period
fl.check_margins([("element 60", models[60][1]), ("element 61", models[61][1])])

# Both breakpoints are crossed inside an increment, and gamma ends beyond the table
# (0.05), where the two extrapolations differ.
for el in (60, 61):
    assert models[el][0].crossings >= 2, (el, models[el][0].crossings)
    assert models[el][0].gamma > 0.1
assert abs(rows[-1][4][names.index("CNF1@60")] - 400.0) <= 1e-12
assert rows[-1][4][names.index("CNF1@61")] > 500.0
# Stick/slip pattern: slip from the first increment (100 > mu F_int(0) = 45); stick on each
# reversal until the force has changed by 2 mu F_int (longer for LINEAR, whose F_int is larger).
assert status[60] == [1] * 10 + [0] * 3 + [1] * 12 + [0] * 3 + [1] * 12, status[60]
assert status[61] == [1] * 10 + [0] * 4 + [1] * 11 + [0] * 7 + [1] * 8, status[61]

g.write_golden(__file__, [
    "friction_press_fit: CONN2D2 SLOT, COMPONENT=1, no CONTACT FORCE, F_N = F_int(gamma) through",
    "(0, 100), (0.02, 300), (0.05, 400), EXTRAPOLATION=CONSTANT (element 60) / LINEAR (61);",
    "mu = 0.45, k = 1e4; u1 0 -> 0.1 -> -0.05 -> 0.1 in increments of 0.01. Slip equation",
    "|f_tr| - k dg - mu F_int(gamma_n + dg) = 0 solved by bisection (crosses breakpoints).",
    "Row 0 is not listed (CNF at time 0).",
], names, rows)
