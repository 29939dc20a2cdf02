"""Golden values of friction_slide_plane_circle (friction.md §7.2).

Radial return in closed form per increment (friction.md §4.1: P = sqrt(f2^2 + f3^2), K_s = k I,
rate-independent, F_N = |f1| = 500 constant after step 1):
    f_tr = k (u - u_s,n),  stick if |f_tr| <= F_lim = mu F_N = 100,
    else f = F_lim f_tr/|f_tr|,  dgamma = (|f_tr| - F_lim)/k,  u_s += dgamma f_tr/|f_tr|.
Element 20 (circular potential, CONTACT FORCE=PRESS = NORM of f1) and element 21 (PREDEFINED)
give the same numbers. The prescribed positions are the deck's amplitude values (TABULAR, points
at the increment ends). Asserted: the §7.2 table and the listed properties to their digits.
"""
import math
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import golden_lib as g  # noqa: E402
import friction_lib as fl  # noqa: E402

K, MU, LOAD = 1.0e5, 0.2, -500.0
C30 = 0.866025403784439  # the amplitude values of the deck
COSA = [(0., 1.), (1., C30), (2., 0.5), (3., 0.), (4., -0.5), (5., -C30), (6., -1.), (7., -C30),
        (8., -0.5), (9., 0.), (10., 0.5), (11., C30), (12., 1.)]
SINA = [(0., 0.), (1., 0.5), (2., C30), (3., 1.), (4., C30), (5., 0.5), (6., 0.), (7., -0.5),
        (8., -C30), (9., -1.), (10., -C30), (11., -0.5), (12., 0.)]


class Radial:
    """Closed-form radial return (independent of friction_lib)."""

    def __init__(self):
        self.us, self.gamma = [0.0, 0.0], 0.0

    def update(self, u, fn):
        flim = MU * fn
        ftr = [K * (a - b) for a, b in zip(u, self.us)]
        m = math.hypot(*ftr)
        if m <= flim:
            return ftr, 0, 0.0
        dg = (m - flim) / K
        self.us = [s + dg * x / m for s, x in zip(self.us, ftr)]
        self.gamma += dg
        return [flim * x / m for x in ftr], 1, dg


closed = Radial()
lib = fl.Friction(K, fl.Constant(MU), ncomp=2)

ids20 = ["CSF2", "CSF3", "CNF2", "CNF3", "CSLIPST2", "CSLIPST3", "CASU2", "CASU3", "CTF1",
         "CSFC", "CNFC", "CASUC", "CDERF-PRESS"]
ids21 = ["CSF2", "CSF3", "CNF2", "CNF3", "CSLIPST2", "CSLIPST3", "CASU2", "CASU3", "CTF1"]
names = (fl.columns(ids20, [20]) + fl.columns(ids21, [21])
         + fl.columns(["RF2", "RF3"], [2, 4]))
rows = [(1, 0, 0.0, 0.0, [0.0] * len(names))]
table = {}


def emit(step, inc, t, total, u, load):
    f1 = load  # SLIDE-PLANE constraint force = load on the free dof 1 of node b
    fn = abs(f1)
    f, st, dg = closed.update(u, fn)
    f_lib = lib.update(u, fn, 1.0)
    assert max(abs(a - b) for a, b in zip(f, f_lib)) <= 1e-12 * 100.0 and st == lib.status
    assert abs(closed.gamma - lib.gamma) <= 1e-14
    p = math.hypot(*f)
    v = {"CSF2": f[0], "CSF3": f[1], "CNF2": fn, "CNF3": fn, "CSLIPST2": float(st),
         "CSLIPST3": float(st), "CASU2": closed.gamma, "CASU3": closed.gamma, "CTF1": f1,
         "CSFC": p, "CNFC": fn, "CASUC": closed.gamma, "CDERF-PRESS": abs(f1)}
    values = [v[i] for i in ids20] + [v[i] for i in ids21]
    values += [f[0], f[0], f[1], f[1]]  # RF2@2, RF2@4, RF3@2, RF3@4 = CSF2, CSF3 (node b)
    rows.append((step, inc, t, total, values))
    table[(step, inc)] = (u, f, st, dg, closed.gamma)


# Step 1: load ramped to -500 in one increment, u = 0.
emit(1, 1, 1.0, 1.0, [0.0, 0.0], LOAD)
# Step 2: u2 0 -> 1 in 10 increments.
for inc, t in enumerate(fl.increments(0.1, 1.0), start=1):
    emit(2, inc, t, 1.0 + t, [fl.ramp(0.0, 1.0, t, 1.0), 0.0], LOAD)
# Step 3: around the circle, u = (COSA(t), SINA(t)), t = 1..12.
for inc, t in enumerate(fl.increments(1.0, 12.0), start=1):
    emit(3, inc, t, 2.0 + t, [g.tabular(t, COSA), g.tabular(t, SINA)], LOAD)
fl.check_margins([("slide-plane", lib)])

# friction.md §7.2.
assert table[(1, 1)][2] == 0
assert abs(table[(2, 1)][4] - 0.099) <= 1e-15 and abs(table[(2, 10)][4] - 0.999) <= 1e-14
for inc in range(1, 11):
    assert table[(2, inc)][2] == 1 and table[(2, inc)][1] == [100.0, 0.0]
spec = {1: (-25.7015, 96.6407, 1.51538), 2: (-70.6422, 70.7791, 2.03288),
        3: (-96.5675, 25.9752, 2.55039), 6: (-25.9752, -96.5675, 4.10290),
        12: (25.9752, 96.5675, 7.20792)}
for inc, (f2, f3, casu) in spec.items():
    u, f, st, dg, gam = table[(3, inc)]
    assert st == 1
    assert abs(f[0] - f2) <= 5e-5 and abs(f[1] - f3) <= 5e-5 and abs(gam - casu) <= 5e-6, inc
lags = {}
for inc in range(1, 13):
    u, f, st, dg, gam = table[(3, inc)]
    assert st == 1 and abs(math.hypot(*f) - 100.0) <= 1e-12 * 100.0
    theta = math.radians(30.0 * inc)
    lag = math.degrees(theta + math.pi / 2 - math.atan2(f[1], f[0]))
    lags[inc] = (lag + 180.0) % 360.0 - 180.0
    if inc >= 3:
        assert abs(dg - 0.517504) <= 5e-7, (inc, dg)
assert abs(lags[1] - 15.1070) <= 5e-5 and abs(lags[2] - 15.0554) <= 5e-5
assert all(abs(lags[i] - 15.0553) <= 5e-5 for i in range(3, 13)), lags

g.write_golden(__file__, [
    "friction_slide_plane_circle: friction.md §7.2, SLIDE-PLANE, mu = 0.2, k = 1e5, normal load",
    "-500 (F_N = 500, F_lim = 100). Step 2: u2 0 -> 1 in 10 increments; step 3: unit circle in",
    "12 increments of 30 degrees. Element 20: circular potential, CONTACT FORCE=PRESS; element",
    "21: PREDEFINED. Radial return in closed form; the §7.2 table and properties are asserted.",
], names, rows)
