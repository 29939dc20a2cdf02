"""Independent friction updates shared by the friction verification cases (standard library only).

Written from friction.md §2.2, §3.3, §4.1 and §4.4, not from clinch. Per friction definition the
state is the slip u_s, the accumulated slip gamma and the stick/slip flag; the friction force is
f = k (u_J - u_s). One converged increment n -> n+1 from the committed state:

    F_N(gamma) = |g + F_int(gamma)|                       (§2.2; g = |N(f)| >= 0 given)
    f_tr = k (u_J - u_s,n)
    stick  if P(f_tr) - F_lim(0, gamma_n) <= 1e-12 max(F_lim, P(f_tr))   (§4.1 step 3)
    slip   otherwise: the scalar equation
           phi(dg) = P(f_tr) - k dg - F_lim(dg/dt, gamma_n + dg) = 0      (§4.1 step 4)
           on [0, P(f_tr)/k]; f = F_lim f_tr/P(f_tr) (radial: P = |f| or the circle),
           u_s += dg f_tr/P(f_tr), gamma += dg.
    F_lim(rate, gamma) = min(mu(rate) F_N(gamma), F_max)

The root is found by bisection to the last representable bit (a different algorithm from the
Newton safeguarded by bisection of §4.1); phi is strictly decreasing in dg for every law used by
the cases (rate-independent, F_int increasing in gamma, or exponential decay with
k > F_N d_c (mu_s - mu_k)/dt, which each case asserts). Each update records the relative distance
of the trial from the static surface so that a case can assert that no regime decision is a
near-tie that round-off in clinch could flip.
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plastic_lib as pl  # noqa: E402  (bisection and piecewise-linear tables)

STICK_TOL = 1e-12  # friction.md §4.1 step 3


class Constant:
    """Constant coefficient (the default *FRICTION form with one line)."""

    def __init__(self, mu):
        self.mu_s = mu
        self.mu_k = mu

    def mu(self, rate):
        return self.mu_s


class ExponentialDecay:
    """*FRICTION, EXPONENTIAL DECAY: mu = mu_k + (mu_s - mu_k) exp(-d_c rate) (friction.md §3.1)."""

    def __init__(self, mu_s, mu_k, d_c):
        self.mu_s, self.mu_k, self.d_c = mu_s, mu_k, d_c

    def mu(self, rate):
        return self.mu_k + (self.mu_s - self.mu_k) * math.exp(-self.d_c * rate)

    def dmu(self, rate):
        return -self.d_c * (self.mu_s - self.mu_k) * math.exp(-self.d_c * rate)

    def rate_bound(self, fn, dt):
        """k must exceed this for a unique local update (friction.md §7.3)."""
        return fn * self.d_c * (self.mu_s - self.mu_k) / dt


class Friction:
    """One friction definition with P = |f| (ncomp = 1) or P = sqrt(f2^2 + f3^2) (ncomp = 2, the
    SLIDE-PLANE predefined form and the circular potential), K_s = k I.

    f_int: None (F_int = 0) or a plastic_lib.Hardening table of (F_int, gamma) points with
    CONSTANT (linear=False) or LINEAR extrapolation. f_max: TAUMAX (None = no cap).
    """

    def __init__(self, k, law, ncomp=1, f_int=None, f_max=None):
        self.k, self.law, self.ncomp = k, law, ncomp
        self.f_int = f_int
        self.f_max = f_max
        self.us = [0.0] * ncomp
        self.gamma = 0.0
        self.f = [0.0] * ncomp
        self.status = 0
        self.fn = 0.0
        self.margins = []  # relative distance of every trial from the static surface
        self.dgamma = 0.0

    def contact(self, g, gamma):
        fi = self.f_int.fy(gamma) if self.f_int is not None else 0.0
        return abs(g + fi)

    def limit(self, g, gamma, rate):
        flim = self.law.mu(rate) * self.contact(g, gamma)
        return flim if self.f_max is None else min(flim, self.f_max)

    def update(self, u, g, dt):
        """u: the constitutive motion in the friction components (list of ncomp); g = |N| >= 0.
        Commits and returns the friction force (list)."""
        k = self.k
        ftr = [k * (ui - si) for ui, si in zip(u, self.us)]
        p = math.sqrt(sum(x * x for x in ftr))
        flim0 = self.limit(g, self.gamma, 0.0)
        scale = max(flim0, p)
        if scale > 0.0:
            self.margins.append(abs(p - flim0) / scale)
        if p - flim0 <= STICK_TOL * scale:
            self.f, self.status, self.dgamma = ftr, 0, 0.0
            self.fn = self.contact(g, self.gamma)
            return list(self.f)
        gamma_n = self.gamma

        def phi(dg):
            return p - k * dg - self.limit(g, gamma_n + dg, dg / dt)

        hi = p / k
        if phi(hi) == 0.0:
            dg = hi
        else:
            dg = pl.bisect_decreasing(phi, 0.0, hi)
        flim = self.limit(g, gamma_n + dg, dg / dt)
        n = [x / p for x in ftr]
        self.f = [flim * ni for ni in n]
        self.us = [si + dg * ni for si, ni in zip(self.us, n)]
        self.gamma = gamma_n + dg
        self.dgamma = dg
        self.status = 1
        self.fn = self.contact(g, self.gamma)
        # The discrete equations of §4.1 written out: f = f_tr - k dg n and P(f) = F_lim.
        for fi, ti, ni in zip(self.f, ftr, n):
            assert abs(fi - (ti - k * dg * ni)) <= 1e-12 * max(p, 1.0), (fi, ti, dg)
        return list(self.f)

    def min_margin(self):
        return min(self.margins) if self.margins else 1.0


def ramp(v0, m, step_time, period):
    """Value of a BC or load without amplitude in a RAMP step (keywords.md §13)."""
    return v0 + (m - v0) * (step_time / period)


def increments(dt, period):
    """Step times of a *STATIC, DIRECT step with increment dt and period T (keywords.md §15)."""
    n = int(round(period / dt))
    assert abs(n * dt - period) <= 1e-9 * period
    return [dt * i if i < n else period for i in range(1, n + 1)]


def columns(identifiers, labels):
    """History columns of one request block (output-variables.md §1.2): identifiers in data-line
    order, then labels in ascending order."""
    return [f"{v}@{label}" for v in identifiers for label in sorted(labels)]


def check_margins(models, floor=1e-6, ties_allowed=0):
    """No stick/slip decision of the case lies within `floor` (relative) of the static surface,
    except exact ties (a trial on the surface up to round-off, below 1e-13 relative, which the
    tolerance of §4.1 step 3 puts on the stick side whatever the round-off): at most
    `ties_allowed` of them in the whole case. Returns the number of ties."""
    ties = 0
    for name, model in models:
        for m in model.margins:
            if m < 1e-13:
                ties += 1
            elif m < floor:
                raise SystemExit(f"{name}: a trial lies {m:.3g} from the surface")
    if ties > ties_allowed:
        raise SystemExit(f"{ties} exact ties, {ties_allowed} allowed")
    return ties
