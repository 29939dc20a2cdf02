"""Independent return mappings shared by the plasticity verification cases (standard library only).

Nothing here follows the Newton on (F, dl) of behaviors.md §6.4: the coupled returns are solved
by bisection on one scalar, with the force recovered in closed form for that scalar, and every
converged state is then checked against the discrete equations of §6.4 written out directly
(residual_coupled), with a gradient of the potential coded from
derived-components-and-potentials.md §2.4 on its own.
"""
import math


class Hardening:
    """Isotropic F_y(u) through (F_y, u) points; EXTRAPOLATION=CONSTANT or LINEAR beyond the end."""

    def __init__(self, points, linear=False):
        self.points = points
        self.linear = linear

    def _segment(self, u):
        pts = self.points
        if len(pts) == 1:
            return pts[0][0], 0.0, 0.0
        for (fa, ua), (fb, ub) in zip(pts, pts[1:]):
            if u <= ub:
                return fa, ua, (fb - fa) / (ub - ua)
        (fa, ua), (fb, ub) = pts[-2], pts[-1]
        if self.linear:
            return fa, ua, (fb - fa) / (ub - ua)
        return fb, ub, 0.0

    def fy(self, u):
        fa, ua, h = self._segment(u)
        return fa + h * (u - ua)

    def slope(self, u):
        return self._segment(u)[2]


def bisect_decreasing(fun, lo, hi, iterations=400):
    """Root of a decreasing function with fun(lo) > 0 >= fun(hi), to the last representable bit."""
    assert fun(lo) > 0.0 >= fun(hi)
    for _ in range(iterations):
        mid = 0.5 * (lo + hi)
        if mid <= lo or mid >= hi:
            break
        if fun(mid) > 0.0:
            lo = mid
        else:
            hi = mid
    return lo if abs(fun(lo)) <= abs(fun(hi)) else hi


def bisect_increasing(fun, lo, hi, iterations=400):
    return bisect_decreasing(lambda x: -fun(x), lo, hi, iterations)


class QuadraticCoupled:
    """Coupled plasticity with P = sqrt(sum_i ((F_i - a_i)/R_i)^2) (SUM, beta = alpha_i = 2, ABS),
    diagonal elasticity K = diag(k), isotropic hardening, u_bar = lambda (behaviors.md §6.2).

    Return: with G = F - a and mu = dl/P(F), the flow rule K^-1 (F - F_tr) + dl n = 0,
    n_i = G_i/(R_i^2 P), gives G_i = G_tr_i/(1 + mu k_i/R_i^2) in closed form. The remaining
    yield condition P(mu) - F_y(u_bar_n + mu P(mu)) = 0 is strictly decreasing in mu and is solved
    by bisection. For R_i and k_i all equal it is the radial return (checked by the callers).
    """

    def __init__(self, k, r, a, hardening):
        self.k, self.r, self.a, self.hard = list(k), list(r), list(a), hardening
        self.n = len(k)
        self.up = [0.0] * self.n
        self.ubar = 0.0

    def potential(self, f):
        return math.sqrt(sum(((fi - ai) / ri) ** 2 for fi, ai, ri in zip(f, self.a, self.r)))

    def gradient(self, f):
        p = self.potential(f)
        return [(fi - ai) / (ri * ri * p) for fi, ai, ri in zip(f, self.a, self.r)]

    def trial(self, u):
        return [ki * (ui - upi) for ki, ui, upi in zip(self.k, u, self.up)]

    def solve(self, u, ubar_n=None, up_n=None):
        """Converged (F, dl) at motion u from the committed history (not modified)."""
        up_n = self.up if up_n is None else up_n
        ubar_n = self.ubar if ubar_n is None else ubar_n
        ftr = [ki * (ui - upi) for ki, ui, upi in zip(self.k, u, up_n)]
        if self.potential(ftr) - self.hard.fy(ubar_n) <= 0.0:
            return ftr, 0.0
        gtr = [fi - ai for fi, ai in zip(ftr, self.a)]

        def force(mu):
            return [ai + gi / (1.0 + mu * ki / (ri * ri))
                    for ai, gi, ki, ri in zip(self.a, gtr, self.k, self.r)]

        def psi(mu):
            p = self.potential(force(mu))
            return p - self.hard.fy(ubar_n + mu * p)

        hi = 1e-12
        while psi(hi) > 0.0:
            hi *= 2.0
        mu = bisect_decreasing(psi, 0.0, hi)
        f = force(mu)
        return f, mu * self.potential(f)

    def update(self, u):
        ftr = self.trial(u)
        f, dl = self.solve(u)
        if dl > 0.0:
            self.up = [upi + (fti - fi) / ki for upi, fti, fi, ki in zip(self.up, ftr, f, self.k)]
            self.ubar += dl
            check_coupled(ftr, f, dl, self.k, self.gradient(f), self.potential(f),
                          self.hard.fy(self.ubar))
        return f, dl


def check_coupled(ftr, f, dl, k, n, p, fy, tol=1e-12):
    """Discrete equations of behaviors.md §6.4 at a plastic state: K^-1 (F - F_tr) + dl n = 0 and
    P(F) = F_y(u_bar_n + dl), relative to |K^-1 F_tr| and F_y."""
    scale = math.sqrt(sum((fi / ki) ** 2 for fi, ki in zip(ftr, k)))
    r_f = math.sqrt(sum(((fi - ti) / ki + dl * ni) ** 2 for fi, ti, ki, ni in zip(f, ftr, k, n)))
    assert dl > 0.0
    assert r_f <= tol * scale, f"flow-rule residual {r_f} vs scale {scale}"
    assert abs(p - fy) <= tol * fy, f"yield residual {p - fy} (F_y = {fy})"
    return r_f / scale, abs(p - fy) / fy
