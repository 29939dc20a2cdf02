"""Golden values of plastic_coupled_circle (behaviors.md §6.4, §6.7: E11 and E11b).

E11 (K = k I, circle, perfectly plastic): radial return in closed form,
    F = F_y F_tr/|F_tr|,  dl = (|F_tr| - F_y)/k.
E11b (R_2 = 2, h = 200): an independent scalar solve. With mu = dl/P the flow rule gives
F_i = F_tr_i/(1 + mu k/R_i^2); the yield condition P(mu) = F_y(u_bar_n + mu P(mu)) is decreasing
in mu and is solved by bisection (plastic_lib.QuadraticCoupled). Both are checked against the
discrete equations of §6.4 and against the §6.7 tables (forces, plastic motions, CUPEQ, and the
consistent tangent D by central differences of the return map).
"""
import math
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import golden_lib as g  # noqa: E402
import plastic_lib as pl  # noqa: E402

K = 1000.0


class Radial:
    """E11 in closed form."""

    def __init__(self, fy):
        self.fy = fy
        self.up = [0.0, 0.0]
        self.ubar = 0.0

    def solve(self, u, up):
        ftr = [K * (ui - pi) for ui, pi in zip(u, up)]
        m = math.hypot(*ftr)
        if m <= self.fy:
            return ftr, 0.0
        return [self.fy * fi / m for fi in ftr], (m - self.fy) / K

    def update(self, u):
        ftr = [K * (ui - pi) for ui, pi in zip(u, self.up)]
        f, dl = self.solve(u, self.up)
        self.up = [pi + (ti - fi) / K for pi, ti, fi in zip(self.up, ftr, f)]
        self.ubar += dl
        if dl > 0.0:
            p = math.hypot(*f)
            pl.check_coupled(ftr, f, dl, [K, K], [fi / p for fi in f], p, self.fy)
        return f, dl


def tangent(solve, u, h=1e-7):
    """Central-difference consistent tangent of the return map at fixed history (behaviors.md
    §1.4: each evaluation restarts from the committed state)."""
    d = [[0.0, 0.0], [0.0, 0.0]]
    for j in range(2):
        up_, um_ = list(u), list(u)
        up_[j] += h
        um_[j] -= h
        fp, fm = solve(up_)[0], solve(um_)[0]
        for i in range(2):
            d[i][j] = (fp[i] - fm[i]) / (2.0 * h)
    return d


e11 = Radial(100.0)
e11b = pl.QuadraticCoupled([K, K], [1.0, 2.0], [0.0, 0.0],
                           pl.Hardening([(100.0, 0.0), (300.0, 1.0)]))
# Cross-check of the scalar solver against the radial closed form on E11 itself.
e11_scalar = pl.QuadraticCoupled([K, K], [1.0, 1.0], [0.0, 0.0], pl.Hardening([(100.0, 0.0)]))

paths = {1: [(0.1, 0.1), (0.1, 0.2)], 2: [(0.1, 0.1), (0.15, 0.2)]}
spec = {  # §6.7: (CTF1, CTF2, CUP1, CUP2, CUPEQ, D11, D12, D22) per step
    1: [(70.7106781, 70.7106781, 0.0292893219, 0.0292893219, 0.0414213562,
         353.553391, -353.553391, 353.553391),
        (38.2683432, 92.3879533, 0.0617316568, 0.107612047, 0.126197263,
         461.939766, -191.341716, 79.256334)],
    2: [(89.9717441, 97.2890395, 0.0100282559, 0.00271096051, 0.0114001376,
         244.350258, -191.575625, 916.889391),
        (83.2152709, 168.549498, 0.0667847291, 0.0314505024, 0.0921784914,
         318.962043, -200.507683, 708.427055)],
}
names = []
for el in (1, 2):
    names += [f"{v}@{el}" for v in ("CU1", "CU2", "CTF1", "CTF2", "CTF3", "CUP1", "CUP2", "CUP3",
                                   "CUPEQ")]
for node in (2, 4):
    names += [f"RF{i}@{node}" for i in (1, 2, 3)]
rows = [(1, 0, 0.0, 0.0, [0.0] * len(names))]
for step in (1, 2):
    values, rf = [], []
    for el, model in ((1, e11), (2, e11b)):
        u = list(paths[el][step - 1])
        if el == 1:
            d = tangent(lambda v: e11.solve(v, e11.up), u)
            f, dl = e11.update(u)
            f_s, dl_s = e11_scalar.update(u)
            assert max(abs(a - b) for a, b in zip(f, f_s)) <= 1e-11 * 100.0
            assert abs(dl - dl_s) <= 1e-14
        else:
            d = tangent(lambda v: e11b.solve(v), u)
            f, dl = e11b.update(u)
        want = spec[el][step - 1]
        got = (f[0], f[1], model.up[0], model.up[1], model.ubar, d[0][0], d[0][1], d[1][1])
        for x, y in zip(got, want):
            assert abs(x - y) <= 6e-9 * max(1.0, abs(y)) or abs(x - y) <= 5e-7, (el, step, x, y)
        assert abs(d[0][1] - d[1][0]) <= 1e-5
        values += [u[0], u[1], f[0], f[1], 0.0, model.up[0], model.up[1], 0.0, model.ubar]
        rf += [f[0], f[1], 0.0]  # node b: RF = +CTF (CARTESIAN, global axes)
    rows.append((step, 1, 1.0, float(step), values + rf))
# E11b: P at the end of step 2 is 100 + 200 u_bar = 118.435698 (§6.7).
assert abs(e11b.potential(rows[-1][4][names.index("CTF1@2"):][:2]) - 118.435698) < 5e-7

g.write_golden(__file__, [
    "plastic_coupled_circle: CARTESIAN, k = 1000 on 1-3, coincident nodes. Element 1 = E11",
    "(P = sqrt(f1^2 + f2^2), F_y = 100): u = (0.1, 0.1), then (0.1, 0.2), one increment each.",
    "Element 2 = E11b (R_2 = 2, F_y = 100 + 200 u_bar): (0.1, 0.1), then (0.15, 0.2). Radial",
    "return in closed form (E11), scalar bisection on mu = dl/P (E11b); both match behaviors.md",
    "§6.7 (forces, CUP, CUPEQ, and D by central differences) and the discrete equations of §6.4",
], names, rows)
