"""Golden values of plastic_isotropic_uncoupled (behaviors.md §6.3, §6.7: E7 and E10).

Backward-Euler return mapping of a single AXIAL component with isotropic hardening, written
independently of the implementation: for the piecewise-linear table the plastic increment is the
exact solution on the segment that holds the end state (a closed form per segment); for the
exponential law the scalar consistency equation is solved by bisection to the last bit.
"""
import math
import os
import sys
from fractions import Fraction

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import golden_lib as g  # noqa: E402

K = 1000.0


class Tabular:
    """F_y(u) through the points, constant beyond the last one (EXTRAPOLATION=CONSTANT)."""

    def __init__(self, points):
        self.points = points

    def segments(self):
        """(u_a, u_b, F_a, slope) for each segment, then the flat tail to infinity."""
        out = []
        for (fa, ua), (fb, ub) in zip(self.points, self.points[1:]):
            out.append((ua, ub, fa, (fb - fa) / (ub - ua)))
        out.append((self.points[-1][1], math.inf, self.points[-1][0], 0.0))
        return out

    def fy(self, u):
        for ua, ub, fa, h in self.segments():
            if u <= ub:
                return fa + h * (u - ua)
        raise AssertionError

    def increment(self, excess_force, u_n):
        """Delta lambda > 0 solving |F_tr| - k dl - F_y(u_n + dl) = 0, excess_force = |F_tr|."""
        for ua, ub, fa, h in self.segments():
            if ub <= u_n:
                continue
            dl = (excess_force - fa - h * (u_n - ua)) / (K + h)
            if u_n + dl <= ub * (1.0 + 1e-15):
                return dl
        raise AssertionError("no segment holds the solution")


class Exponential:
    """F_y(u) = F0 + Q (1 - exp(-b u))."""

    def __init__(self, f0, q, b):
        self.f0, self.q, self.b = f0, q, b

    def fy(self, u):
        return self.f0 + self.q * (1.0 - math.exp(-self.b * u))

    def slope(self, u):
        return self.q * self.b * math.exp(-self.b * u)

    def increment(self, excess_force, u_n):
        def r(dl):
            return excess_force - K * dl - self.fy(u_n + dl)

        lo, hi = 0.0, excess_force / K  # r(lo) > 0 >= r(hi); r strictly decreasing
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            if mid in (lo, hi):
                break
            if r(mid) > 0.0:
                lo = mid
            else:
                hi = mid
        return lo if abs(r(lo)) <= abs(r(hi)) else hi


class Element:
    def __init__(self, law):
        self.law = law
        self.up = 0.0  # u_pl
        self.ubar = 0.0  # equivalent plastic motion

    def update(self, u):
        """Commit the converged state at motion u; returns (F, dl)."""
        ftr = K * (u - self.up)
        phi = abs(ftr) - self.law.fy(self.ubar)
        if phi <= 0.0:
            return ftr, 0.0
        s = 1.0 if ftr > 0.0 else -1.0
        dl = self.law.increment(abs(ftr), self.ubar)
        self.up += s * dl
        self.ubar += dl
        f = ftr - K * s * dl
        # Discrete equations at the converged state: yield condition and flow rule.
        assert abs(abs(f) - self.law.fy(self.ubar)) <= 1e-12 * self.law.fy(self.ubar)
        assert abs(f - K * (u - self.up)) <= 1e-12 * abs(f)
        assert dl > 0.0 and f * s > 0.0
        return f, dl


# Load path: (step, increment, step time, total time, U@2, U@4).
rows_t = [(1, 0, 0.0, 0.0, 0.0, 0.0)]
rows_t += [(1, i, 0.25 * i, 0.25 * i, 0.05 * i, 0.0) for i in range(1, 5)]
rows_t += [(2, i, 0.125 * i, 1.0 + 0.125 * i, 0.2 - 0.05 * i, 0.0) for i in range(1, 9)]
rows_t += [(3, 1, 1.0, 3.0, -0.2, 0.2)]
rows_t += [(4, i, 0.25 * i, 3.0 + 0.25 * i, -0.2, 0.2 - 0.1 * i) for i in range(1, 5)]

e7 = Element(Tabular([(120.0, 0.0), (170.0, 0.1)]))
e10 = Element(Exponential(100.0, 50.0, 20.0))
names = []
for el in (1, 2):
    names += [f"{v}@{el}" for v in ("CU1", "CTF1", "CEF1", "CUP1", "CUE1", "CUPEQ")]
names += ["RF1@2", "RF1@4"]
rows, e7_rows, e10_rows = [], {}, {}
for step, inc, st, tt, u2, u4 in rows_t:
    values, forces = [], []
    for el, u, store in ((e7, u2, e7_rows), (e10, u4, e10_rows)):
        if inc == 0:
            f, dl = 0.0, 0.0
        else:
            f, dl = el.update(u)
        store[tt] = (f, el.up, el.ubar, dl)
        values += [u, f, f, el.up, u - el.up, el.ubar]
        forces.append(f)
    values += forces  # RF at the driven node b = +f (behaviors.md §4.5)
    rows.append((step, inc, st, tt, values))

# The spec tables of §6.7, to their printed digits (E7: exact fractions where given).
e7_spec = {
    0.25: (50.0, 0.0, 0.0), 0.5: (100.0, 0.0, 0.0), 0.75: (130.0, 0.02, 0.02),
    1.0: (Fraction(440, 3), Fraction(4, 75), Fraction(4, 75)),
    1.125: (96.666667, Fraction(4, 75), Fraction(4, 75)),
    1.5: (-53.333333, Fraction(4, 75), Fraction(4, 75)),
    1.625: (-103.333333, Fraction(4, 75), Fraction(4, 75)),
    1.75: (Fraction(-1340, 9), Fraction(11, 225), Fraction(13, 225)),
    1.875: (Fraction(-1490, 9), Fraction(7, 450), Fraction(41, 450)),
    2.0: (-170.0, -0.03, Fraction(41, 300)),
}
for tt, want in e7_spec.items():
    got = e7_rows[tt][:3]
    for x, y in zip(got, want):
        tol = 1e-12 * max(1.0, abs(float(y))) if isinstance(y, Fraction) or y == round(y, 2) else 5e-7
        assert abs(x - float(y)) <= tol, (tt, got, want)
assert abs(e7_rows[2.0][3] - 0.0455556) < 5e-8  # "Delta lambda = 0.0455556" on the flat branch
f10, up10, ub10, dl10 = e10_rows[3.0]
assert abs(dl10 - 0.0639232271) < 5e-11 and abs(f10 - 136.076773) < 5e-7
h10 = e10.law.slope(dl10)
assert abs(h10 - 278.464543) < 5e-7 and abs(K * h10 / (K + h10) - 217.811706) < 5e-7

g.write_golden(__file__, [
    "plastic_isotropic_uncoupled: AXIAL k = 1000. Element 1 = E7 (tabular 120 at 0, 170 at 0.1,",
    "constant beyond): U@2 0 -> 0.2 (4 incr.), 0.2 -> -0.2 (8 incr.), held. Element 2 = E10",
    "(F_y = 100 + 50 (1 - exp(-20 u))): U@4 held 0, then 0 -> 0.2 (1 incr.), 0.2 -> -0.2 (4 incr.).",
    "Backward Euler (behaviors.md §6.3): exact per table segment (E7), bisection to the last bit",
    "(E10); E7 matches the §6.7 table (exact fractions), E10 matches dl = 0.0639232271, F = 136.076773",
], names, rows)
