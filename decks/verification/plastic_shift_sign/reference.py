"""Golden values of plastic_shift_sign (derived-components-and-potentials.md §2.3, §2.6;
behaviors.md §6.2, §6.4): potentials with shifts a_i and a sum-type potential with a negative
sign, on CARTESIAN, k = 1000 on 1-3, F_y = 100 + 100 u_bar, u_bar = lambda. Closed forms:

- Element 1, norm-type with shifts: P = sqrt((f1 - 20)^2 + (f2 + 30)^2), a circle of radius F_y
  centred at c = (20, -30). Radial return about c: G_tr = F_tr - c,
  dl = (|G_tr| - F_y(u_bar_n))/(k + h), F = c + G_tr (1 - k dl/|G_tr|).
- Element 2, sum-type (H = NONE, alpha = beta = 1) with s_2 = -1 and a_2 = 10:
  P = f1/1 - (f2 - 10)/2, linear, n = (1, -1/2) constant; the yield set is a half-plane.
  dl = (P(F_tr) - F_y(u_bar_n))/(n.K.n + h), F = F_tr - dl K n.
- Element 3, MACAULEY with a_1 = -10: P = <f1 + 10>; yields only in tension, at f1 = F_y - 10.
  dl = (f1_tr + 10 - F_y(u_bar_n))/(k + h), F1 = F1_tr - k dl.
"""
import math
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import golden_lib as g  # noqa: E402
import plastic_lib as pl  # noqa: E402

K, F0, H = 1000.0, 100.0, 100.0
PATHS = {
    1: [(0.2, 0.0), (0.2, -0.2), (-0.2, -0.2)],
    2: [(0.2, 0.0), (0.2, -0.2), (-0.2, 0.2)],
    3: [(0.2, 0.0), (-0.3, 0.1), (0.25, 0.0)],
}


class Element:
    def __init__(self, potential, gradient):
        self.potential, self.gradient = potential, gradient
        self.up = [0.0, 0.0]
        self.ubar = 0.0

    def fy(self):
        return F0 + H * self.ubar

    def update(self, u, closed_form):
        ftr = [K * (ui - pi) for ui, pi in zip(u, self.up)]
        phi = self.potential(ftr) - self.fy()
        assert abs(phi) > 1e-6 * F0, ("trial state on the yield surface", u, phi)
        if phi <= 0.0:
            return ftr, 0.0
        f, dl = closed_form(ftr, phi)
        self.up = [pi + (ti - fi) / K for pi, ti, fi in zip(self.up, ftr, f)]
        self.ubar += dl
        pl.check_coupled(ftr, f, dl, [K, K], self.gradient(f), self.potential(f), self.fy())
        return f, dl


C1 = (20.0, -30.0)


def p1(f):
    return math.hypot(f[0] - C1[0], f[1] - C1[1])


def n1(f):
    p = p1(f)
    return [(f[0] - C1[0]) / p, (f[1] - C1[1]) / p]


def cf1(ftr, phi):
    gtr = [ftr[0] - C1[0], ftr[1] - C1[1]]
    m = math.hypot(*gtr)
    dl = phi / (K + H)
    return [c + gi * (1.0 - K * dl / m) for c, gi in zip(C1, gtr)], dl


N2 = (1.0, -0.5)


def p2(f):
    return 1.0 * (f[0] - 0.0) / 1.0 - 1.0 * (f[1] - 10.0) / 2.0


def cf2(ftr, phi):
    dl = phi / (K * (N2[0] ** 2 + N2[1] ** 2) + H)
    return [ti - dl * K * ni for ti, ni in zip(ftr, N2)], dl


def p3(f):
    return max(f[0] + 10.0, 0.0)


def cf3(ftr, phi):
    dl = phi / (K + H)
    return [ftr[0] - K * dl, ftr[1]], dl


elements = {
    1: (Element(p1, n1), cf1),
    2: (Element(p2, lambda f: list(N2)), cf2),
    3: (Element(p3, lambda f: [1.0 if f[0] + 10.0 > 0.0 else 0.0, 0.0]), cf3),
}
check1 = pl.QuadraticCoupled([K, K], [1.0, 1.0], list(C1), pl.Hardening([(100.0, 0.0), (1100.0, 10.0)]))
names = []
for el in elements:
    names += [f"{v}@{el}" for v in ("CU1", "CU2", "CTF1", "CTF2", "CTF3", "CUP1", "CUP2", "CUPEQ")]
rows = [(1, 0, 0.0, 0.0, [0.0] * len(names))]
u = {el: (0.0, 0.0) for el in elements}
plastic = {el: 0 for el in elements}
for step in range(3):
    v0 = dict(u)
    for inc in range(1, 5):
        tau = 0.25 * inc
        values = []
        for el, (m, cf) in elements.items():
            u[el] = tuple(a + (b - a) * tau for a, b in zip(v0[el], PATHS[el][step]))
            f, dl = m.update(list(u[el]), cf)
            plastic[el] += dl > 0.0
            if el == 1:
                fs, dls = check1.update(list(u[el]))
                assert max(abs(a - b) for a, b in zip(f, fs)) <= 1e-11 * 200.0 and abs(dl - dls) <= 1e-14
            values += [u[el][0], u[el][1], f[0], f[1], 0.0, m.up[0], m.up[1], m.ubar]
        rows.append((step + 1, inc, tau, step + tau, values))
assert plastic == {1: 10, 2: 7, 3: 4}, plastic  # plastic increments of 12

g.write_golden(__file__, [
    "plastic_shift_sign: CARTESIAN, k = 1000, F_y = 100 + 100 u_bar, four increments per step.",
    "Element 1: P = sqrt((f1-20)^2 + (f2+30)^2) (ABS, shifts 20, -30); path (0.2,0) (0.2,-0.2)",
    "(-0.2,-0.2). Element 2: sum-type P = f1 - (f2-10)/2 (NONE, s_2 = -1, a_2 = 10); path (0.2,0)",
    "(0.2,-0.2) (-0.2,0.2). Element 3: P = <f1 + 10> (MACAULEY, a_1 = -10); path (0.2,0)",
    "(-0.3,0.1) (0.25,0). Return mappings in closed form (radial about the shifted centre; linear)",
], names, rows)
