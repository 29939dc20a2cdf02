"""Golden values of plastic_max_corner (behaviors.md §6.6): coupled plasticity with an
OPERATOR=MAX potential P = max(|f1|/R1, |f2|/R2) on CARTESIAN, diagonal elasticity, linear
isotropic hardening F_y = F0 + h u_bar with u_bar = sum_j lambda_j.

Closed form of the multi-surface return (derived by hand). With x_i = |f_tr_i|/R_i and
a_i = k_i/R_i^2, surface j gives f_j = s_j R_j Y (s_j = sign f_tr_j) and dl_j = (x_j - Y)/a_j, where
Y = F_y(u_bar_n + sum_j dl_j) is the new yield size. So the return is per-component clipping
|f_i|/R_i <= Y, coupled only through Y, which solves the increasing piecewise-linear equation
    Y - Y_n - h sum_i max(0, x_i - Y)/a_i = 0.
For the active set J (the components with x_i > Y) this is
    Y = (Y_n + h sum_J x_i/a_i) / (1 + h sum_J 1/a_i),
and J is found by trying the sets of the m largest x_i (m = 1, 2) and keeping the consistent one.
The result is checked against the discrete equations of §6.6 at every plastic row.
"""
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import golden_lib as g  # noqa: E402

K = (1000.0, 500.0)
R = (1.0, 2.0)
F0, H = 100.0, 50.0  # hardening table 100 at 0, 600 at 10
STEPS = 5  # four increments each
PATHS = {
    1: [(0.22, 0.1), (0.3, 0.7), (0.4, 0.9), (0.39, -0.3), (0.6, -0.5)],
    2: [(0.05, 0.6), (0.3, 0.8), (0.35, 1.0), (0.2, 1.1), (-0.3, 1.2)],
}


class MaxBox:
    def __init__(self):
        self.up = [0.0, 0.0]
        self.ubar = 0.0

    def update(self, u):
        ftr = [k * (ui - pi) for k, ui, pi in zip(K, u, self.up)]
        yn = F0 + H * self.ubar
        x = [abs(f) / r for f, r in zip(ftr, R)]
        a = [k / (r * r) for k, r in zip(K, R)]
        margins = [xi - yn for xi in x]
        if max(x) <= yn:
            return ftr, [0.0, 0.0], margins, []
        order = sorted(range(2), key=lambda i: -x[i])
        for m in (1, 2):
            act = order[:m]
            y = (yn + H * sum(x[i] / a[i] for i in act)) / (1.0 + H * sum(1.0 / a[i] for i in act))
            if all(x[i] > y for i in act) and all(x[i] <= y for i in order[m:]):
                break
        else:
            raise AssertionError("no consistent active set")
        dl = [(x[i] - y) / a[i] if i in act else 0.0 for i in range(2)]
        s = [1.0 if f > 0.0 else -1.0 for f in ftr]
        f = [s[i] * R[i] * y if i in act else ftr[i] for i in range(2)]
        self.up = [self.up[i] + dl[i] * s[i] / R[i] for i in range(2)]
        self.ubar += sum(dl)
        # Discrete equations of §6.6: K^-1 (F - F_tr) + sum_j dl_j n_j = 0 (n_j = s_j/R_j e_j),
        # phi_j = 0 on the active set, phi_i < 0 off it, dl_j > 0, and F = K (u - u_pl).
        fy = F0 + H * self.ubar
        for i in range(2):
            r_f = (f[i] - ftr[i]) / K[i] + dl[i] * s[i] / R[i]
            assert abs(r_f) <= 1e-12 * max(abs(t) / k for t, k in zip(ftr, K))
            assert abs(f[i] - K[i] * (u[i] - self.up[i])) <= 1e-12 * fy
            phi = abs(f[i]) / R[i] - fy
            if i in act:
                assert dl[i] > 0.0 and abs(phi) <= 1e-12 * fy
            else:
                assert phi < -1e-6 * fy, ("inactive surface too close to yield", phi)
        return f, dl, margins, act


elements = {1: MaxBox(), 2: MaxBox()}
names = []
for el in (1, 2):
    names += [f"{v}@{el}" for v in ("CU1", "CU2", "CTF1", "CTF2", "CTF3", "CUP1", "CUP2", "CUPEQ")]
for node in (2, 4):
    names += [f"RF{i}@{node}" for i in (1, 2, 3)]
rows = [(1, 0, 0.0, 0.0, [0.0] * len(names))]
regimes = {1: [], 2: []}
u = {1: (0.0, 0.0), 2: (0.0, 0.0)}
for step in range(1, STEPS + 1):
    v0 = dict(u)
    for inc in range(1, 5):
        tau = 0.25 * inc
        values, rf = [], []
        for el in (1, 2):
            target = PATHS[el][step - 1]
            u[el] = tuple(a + (b - a) * tau for a, b in zip(v0[el], target))
            m = elements[el]
            f, dl, margins, act = m.update(list(u[el]))
            # Trial states stay clear of each surface (round-off cannot change the active set).
            assert min(abs(x) for x in margins) > 1e-6 * F0, (el, step, inc, margins)
            regimes[el].append("".join(str(i + 1) for i in sorted(act)) or "e")
            values += [u[el][0], u[el][1], f[0], f[1], 0.0, m.up[0], m.up[1], m.ubar]
            rf += [f[0], f[1], 0.0]
        rows.append((step, inc, tau, step - 1 + tau, values + rf))
# Active sets per increment (e = elastic): edges (one surface), the corner (both), elastic
# unloading, the reverse edge and the reverse corners.
assert regimes[1] == ["e"] + ["1"] * 5 + ["12"] * 6 + ["e"] * 3 + ["2"] + ["12"] * 4, regimes[1]
assert regimes[2] == ["e"] * 2 + ["2"] * 3 + ["12"] * 7 + ["2"] * 5 + ["12"] * 3, regimes[2]

g.write_golden(__file__, [
    "plastic_max_corner: CARTESIAN, k = (1000, 500, 1000), OPERATOR=MAX potential",
    "P = max(|f1|/1, |f2|/2), F_y = 100 + 50 u_bar, u_bar = sum of the multipliers. Paths of node b",
    "(4 increments per step): element 1 (0.22,0.1) (0.3,0.7) (0.4,0.9) (0.39,-0.3) (0.6,-0.5);",
    "element 2 (0.05,0.6) (0.3,0.8) (0.35,1.0) (0.2,1.1) (-0.3,1.2). Multi-surface return",
    "(behaviors.md §6.6) in closed form: per-component clipping coupled through the yield size",
], names, rows)
