"""Golden values of plastic_kinematic_uncoupled (behaviors.md §6.2, §6.3, §6.7: E8 and E9).

Backward Euler of uncoupled plasticity with kinematic hardening and a constant yield size. With
alpha(dl) = (alpha_n + C s dl)/(1 + gamma dl) the consistency equation
    |xi_tr| - k dl - s (alpha(dl) - alpha_n) - F_y = 0
becomes, multiplied by (1 + gamma dl), the quadratic
    k gamma dl^2 + (k + C - s gamma alpha_n - gamma phi_tr) dl - phi_tr = 0,  phi_tr = |xi_tr| - F_y,
whose positive root is taken in the cancellation-free form 2 phi_tr / (b + sqrt(b^2 + 4 a phi_tr)).
For gamma = 0 (Ziegler) it is dl = phi_tr / (k + C).
"""
import math
import os
import sys
from fractions import Fraction

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import golden_lib as g  # noqa: E402

K = 1000.0


class Element:
    def __init__(self, fy, c, gamma):
        self.fy, self.c, self.gamma = fy, c, gamma
        self.up = self.ubar = self.alpha = 0.0

    def update(self, u):
        ftr = K * (u - self.up)
        xi = ftr - self.alpha
        phi = abs(xi) - self.fy
        if phi <= 0.0:
            return ftr, 0.0
        s = 1.0 if xi > 0.0 else -1.0
        a = K * self.gamma
        b = K + self.c - s * self.gamma * self.alpha - self.gamma * phi
        dl = 2.0 * phi / (b + math.sqrt(b * b + 4.0 * a * phi))
        alpha_n = self.alpha
        self.alpha = (alpha_n + self.c * s * dl) / (1.0 + self.gamma * dl)
        self.up += s * dl
        self.ubar += dl
        f = ftr - K * s * dl
        # Discrete equations: yield condition on the shifted force, flow direction unchanged,
        # backward-Euler AF update of alpha, elastic law.
        assert abs(abs(f - self.alpha) - self.fy) <= 1e-12 * self.fy
        assert (f - self.alpha) * s > 0.0
        r_alpha = self.alpha - alpha_n - (self.c * s - self.gamma * self.alpha) * dl
        assert abs(r_alpha) <= 1e-12 * max(1.0, abs(self.alpha))
        assert abs(f - K * (u - self.up)) <= 1e-12 * abs(f)
        return f, dl


def ramp(v0, m, tau):
    return v0 + (m - v0) * tau


# (step, increment, step time, total time, U@2, U@4), RAMP from the value at the start of the step.
rows_t = [(1, 0, 0.0, 0.0, 0.0, 0.0)]
rows_t += [(1, i, 0.25 * i, 0.25 * i, ramp(0.0, 0.2, 0.25 * i), 0.0) for i in range(1, 5)]
rows_t += [(2, i, 0.125 * i, 1.0 + 0.125 * i, ramp(0.2, -0.2, 0.125 * i), 0.0) for i in range(1, 9)]
rows_t += [(3, 1, 1.0, 3.0, -0.2, 0.3)]
rows_t += [(4, i, 0.2 * i, 3.0 + 0.2 * i, -0.2, ramp(0.3, -0.3, 0.2 * i)) for i in range(1, 6)]

e8 = Element(110.0, 500.0, 0.0)
e9 = Element(100.0, 2000.0, 20.0)
names = []
for el in (1, 2):
    names += [f"{v}@{el}" for v in ("CU1", "CTF1", "CUP1", "CALPHAF1", "CUPEQ")]
names += ["RF1@2", "RF1@4"]
rows, seen = [], {1: {}, 2: {}}
for step, inc, st, tt, u2, u4 in rows_t:
    values, forces = [], []
    for label, el, u in ((1, e8, u2), (2, e9, u4)):
        f, dl = (0.0, 0.0) if inc == 0 else el.update(u)
        seen[label][tt] = (f, el.up, el.alpha, el.ubar, dl)
        values += [u, f, el.up, el.alpha, el.ubar]
        forces.append(f)
    values += forces
    rows.append((step, inc, st, tt, values))

# E8 table of §6.7 (printed digits), E9 numbers of §6.7.
e8_spec = {
    0.75: (Fraction(370, 3), 0.0266667, 13.333333, 0.0266667),
    1.0: (140.0, 0.06, 30.0, 0.06),
    1.5: (-60.0, 0.06, 30.0, 0.06),
    1.625: (-90.0, 0.04, 20.0, 0.08),
    1.75: (-106.666667, 0.00666667, 3.333333, 0.113333),
    1.875: (-123.333333, -0.0266667, -13.333333, 0.146667),
    2.0: (-140.0, -0.06, -30.0, 0.18),
}
for tt, want in e8_spec.items():
    f, up, alpha, ubar, _ = seen[1][tt]
    for x, y in zip((f, up, alpha, ubar), want):
        assert abs(x - float(y)) <= 5e-7 * max(1.0, abs(float(y))), (tt, x, y)
assert abs(seen[1][1.0][0] - 140.0) < 1e-12 and abs(seen[1][2.0][3] - 0.18) < 1e-15
f9, up9, alpha9, ubar9, dl9 = seen[2][3.0]
assert abs(dl9 - (10.0 + math.sqrt(1700.0)) / 400.0) < 1e-15
assert abs(dl9 - 0.128077641) < 5e-10 and abs(f9 - 171.922359) < 5e-7
assert abs(alpha9 - 71.922359) < 5e-7 and up9 == ubar9 == dl9
h_alpha = 2000.0 / (1.0 + 20.0 * dl9) ** 2
assert abs(h_alpha - 157.670781) < 5e-7 and abs(K * h_alpha / (K + h_alpha) - 136.196562) < 5e-7

g.write_golden(__file__, [
    "plastic_kinematic_uncoupled: AXIAL k = 1000. Element 1 = E8 (Ziegler: F_0 = 110, C = 500,",
    "gamma = 0): U@2 0 -> 0.2 (4 incr.), 0.2 -> -0.2 (8 incr.), held. Element 2 = E9",
    "(Armstrong-Frederick: F_0 = 100, C = 2000, gamma = 20): U@4 held 0, 0 -> 0.3 (1 incr.),",
    "0.3 -> -0.3 (5 incr.). Backward Euler (behaviors.md §6.3) in closed form: the consistency",
    "equation is a quadratic in dl; E8 matches the §6.7 table, E9 dl = (10 + sqrt(1700))/400",
], names, rows)
