"""Golden values of plastic_box_path (behaviors.md §6.2, §6.4): coupled plasticity with linear
isotropic hardening along proportional loading, unloading, reverse loading and a box path.

Backward Euler at the deck's increments, from the committed state of the previous increment.
- Element 1 (K = k I, circle): radial return in closed form per increment,
      dl = (|F_tr| - F_y(u_bar_n)) / (k + h),   F = F_tr (1 - k dl/|F_tr|).
- Element 2 (k1 = 1000, k2 = 600, R = (1, 2)): no closed form; scalar bisection on mu = dl/P with
  F_i = F_tr_i/(1 + mu k_i/R_i^2) (plastic_lib.QuadraticCoupled), a different algorithm from the
  Newton on (F, dl) of §6.4. Element 1 is also run through it and must agree with the closed form.
Every plastic row satisfies the discrete flow rule and yield condition of §6.4 to 1e-12 relative.
"""
import math
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import golden_lib as g  # noqa: E402
import plastic_lib as pl  # noqa: E402

F0, H = 100.0, 100.0  # F_y = F0 + H u_bar (table 100 at 0, 1100 at 10)
STEPS = [((0.2, 0.1), 4), ((0.1, 0.05), 2), ((-0.2, -0.1), 5), ((-0.2, 0.2), 4),
         ((0.2, 0.2), 4), ((0.2, -0.2), 4), ((-0.2, -0.2), 4)]


class RadialLinear:
    def __init__(self, k):
        self.k = k
        self.up = [0.0, 0.0]
        self.ubar = 0.0

    def update(self, u):
        ftr = [self.k * (ui - pi) for ui, pi in zip(u, self.up)]
        m = math.hypot(*ftr)
        phi = m - (F0 + H * self.ubar)
        if phi <= 0.0:
            return ftr, 0.0, phi
        dl = phi / (self.k + H)
        f = [fi * (1.0 - self.k * dl / m) for fi in ftr]
        self.up = [pi + (ti - fi) / self.k for pi, ti, fi in zip(self.up, ftr, f)]
        self.ubar += dl
        p = math.hypot(*f)
        pl.check_coupled(ftr, f, dl, [self.k] * 2, [fi / p for fi in f], p, F0 + H * self.ubar)
        return f, dl, phi


hard = pl.Hardening([(100.0, 0.0), (1100.0, 10.0)])
circle = RadialLinear(1000.0)
circle_scalar = pl.QuadraticCoupled([1000.0, 1000.0], [1.0, 1.0], [0.0, 0.0], hard)
ellipse = pl.QuadraticCoupled([1000.0, 600.0], [1.0, 2.0], [0.0, 0.0], hard)

names = []
for el in (1, 2):
    names += [f"{v}@{el}" for v in ("CU1", "CU2", "CTF1", "CTF2", "CTF3", "CUP1", "CUP2",
                                   "CUPEQ")]
for node in (2, 4):
    names += [f"RF{i}@{node}" for i in (1, 2, 3)]
rows = [(1, 0, 0.0, 0.0, [0.0] * len(names))]
u, total, plastic_rows = (0.0, 0.0), 0.0, {1: 0, 2: 0}
for step, (target, n) in enumerate(STEPS, 1):
    v0 = u
    dt = 1.0 / n
    for inc in range(1, n + 1):
        tau = inc * dt
        u = tuple(a + (b - a) * tau for a, b in zip(v0, target))  # RAMP from the start value
        f1, dl1, phi1 = circle.update(list(u))
        f1s, dl1s = circle_scalar.update(list(u))
        assert max(abs(a - b) for a, b in zip(f1, f1s)) <= 1e-11 * 200.0 and abs(dl1 - dl1s) <= 1e-14
        ftr2 = ellipse.trial(list(u))
        phi2 = ellipse.potential(ftr2) - hard.fy(ellipse.ubar)
        f2, dl2 = ellipse.update(list(u))
        # Keep every trial state clear of the yield surface, so that round-off in the prescribed
        # motions cannot switch an increment between elastic and plastic.
        for phi in (phi1, phi2):
            assert abs(phi) > 1e-6 * F0, (step, inc, phi)
        plastic_rows[1] += dl1 > 0.0
        plastic_rows[2] += dl2 > 0.0
        values = [u[0], u[1], f1[0], f1[1], 0.0, circle.up[0], circle.up[1], circle.ubar]
        values += [u[0], u[1], f2[0], f2[1], 0.0, ellipse.up[0], ellipse.up[1], ellipse.ubar]
        values += [f1[0], f1[1], 0.0, f2[0], f2[1], 0.0]  # node b: RF = +CTF
        rows.append((step, inc, tau, total + tau, values))
    total += 1.0
assert plastic_rows == {1: 20, 2: 14}, plastic_rows  # of 27 increments

g.write_golden(__file__, [
    "plastic_box_path: CARTESIAN coupled plasticity, F_y = 100 + 100 u_bar, node b path",
    "(0,0) -> (0.2,0.1) [4] -> (0.1,0.05) [2] -> (-0.2,-0.1) [5] -> (-0.2,0.2) [4] -> (0.2,0.2) [4]",
    "-> (0.2,-0.2) [4] -> (-0.2,-0.2) [4]. Element 1: k = 1000, circle; radial return in closed",
    "form. Element 2: k = (1000, 600), P = sqrt(f1^2 + (f2/2)^2); bisection on mu = dl/P.",
    "Backward Euler per increment; discrete equations of behaviors.md §6.4 hold to 1e-12",
], names, rows)
