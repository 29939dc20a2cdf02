"""Closed forms of connector damage (behaviors.md §7) for the damage_* verification cases.

Standard library only, written from the spec text, not from the implementation. One AXIAL
component, linear elasticity k, node a fixed, node b driven, so the constitutive motion u is the
prescribed displacement. Elastic connectors with FORCE (or MOTION) initiation: u_0 = F_U/k
exactly (r is linear in u, §7.1), δ = s_0 (u − u_0), κ = max δ. The motion laws prescribe the
envelope force k u_0 g(κ) (§7.2), so d = 1 − u_0 g(κ)/(u_0 + κ); ENERGY: W is the effective work
after initiation along the envelope, W = k((u_0 + κ)² − u_0²)/2, d = 1 − exp(−W/G_f), and d = 1
once d ≥ 0.99. Perfectly plastic connectors with PLASTIC MOTION initiation: the backward-Euler
return of §6.3 with F_y constant, ū accumulating |Δu^pl|, δ = ū − ū_0, d = 1 − g(δ), and for
ENERGY W = F_y δ.
"""
import math


def g_linear(kappa, duf):
    return max(0.0, 1.0 - kappa / duf)


def g_exponential(kappa, duf, a):
    if kappa >= duf:
        return 0.0
    return 1.0 - (1.0 - math.exp(-a * kappa / duf)) / (1.0 - math.exp(-a))


def tabular(x, points):
    """d(δ) through (d, δ) rows, held constant outside (EXTRAPOLATION=CONSTANT), clamped."""
    if x <= points[0][1]:
        y = points[0][0]
    elif x >= points[-1][1]:
        y = points[-1][0]
    else:
        for (ya, xa), (yb, xb) in zip(points, points[1:]):
            if xa <= x <= xb:
                y = ya + (yb - ya) * (x - xa) / (xb - xa)
                break
    return min(1.0, max(0.0, y))


class ElasticDamage:
    """Uncoupled elastic connector, FORCE initiation at F_U > 0 (tension), one law."""

    def __init__(self, k, force_limit, law):
        self.k = k
        self.u0 = force_limit / k
        self.law = law  # ("LINEAR", duf) | ("EXPONENTIAL", duf, a) | ("TABULAR", rows) | ("ENERGY", G_f)
        self.kappa = None  # None: not initiated
        self.d = 0.0
        self.r_max = 0.0

    def damage_of(self, kappa):
        kind = self.law[0]
        if kind == "TABULAR":
            return tabular(kappa, self.law[1])
        if kind == "ENERGY":
            w = 0.5 * self.k * ((self.u0 + kappa) ** 2 - self.u0 ** 2)
            d = 1.0 - math.exp(-w / self.law[1])
            return 1.0 if d >= 0.99 else d
        g = g_linear(kappa, self.law[1]) if kind == "LINEAR" else g_exponential(kappa, *self.law[1:])
        return 1.0 if g <= 0.0 else 1.0 - self.u0 * g / (self.u0 + kappa)

    def update(self, u):
        """Commit the converged state at u; returns (CTF, CDMG, CDIF)."""
        f_eff = self.k * u
        self.r_max = max(self.r_max, f_eff / (self.k * self.u0))
        if self.kappa is None and u >= self.u0:
            self.kappa = 0.0
        if self.kappa is not None:
            self.kappa = max(self.kappa, u - self.u0)
            self.d = max(self.d, self.damage_of(self.kappa))
        return (1.0 - self.d) * f_eff, self.d, self.r_max


class PlasticDamage:
    """Uncoupled perfectly plastic connector (k, F_y), PLASTIC MOTION initiation at ū_0."""

    def __init__(self, k, fy, ubar0, law):
        self.k, self.fy, self.ubar0, self.law = k, fy, ubar0, law
        self.up = 0.0
        self.ubar = 0.0
        self.d = 0.0

    def update(self, u):
        """Commit at u; returns (CTF, CUP, CUPEQ, CDIP, CDMG, f_eff)."""
        ftr = self.k * (u - self.up)
        f = ftr
        if abs(ftr) > self.fy:
            s = 1.0 if ftr > 0 else -1.0
            dl = (abs(ftr) - self.fy) / self.k
            self.up += s * dl
            self.ubar += dl
            f = s * self.fy
        delta = self.ubar - self.ubar0
        if delta >= 0.0 and self.law is not None:
            kind = self.law[0]
            if kind == "ENERGY":
                d = 1.0 - math.exp(-self.fy * delta / self.law[1])
                d = 1.0 if d >= 0.99 else d
            else:
                g = g_linear(delta, self.law[1]) if kind == "LINEAR" else g_exponential(delta, *self.law[1:])
                d = 1.0 - g
            self.d = max(self.d, d)
        return (1.0 - self.d) * f, self.up, self.ubar, self.ubar / self.ubar0, self.d, f


def check(actual, expected, tol, what):
    """Stop the script when a computed value misses a value the spec prints."""
    if abs(actual - expected) > tol:
        raise SystemExit(f"reference check failed for {what}: {actual} vs {expected}")


class CoupledElasticDamage:
    """Uncoupled linear elasticity k_i; coupled FORCE initiation r = P(f)/F_U with
    P(f) = (Σ |f_i/R_i|^α_i)^(1/β) (α_i = β = 2 unless given); evolution δ = P_e(u) − P_e(u_0),
    P_e(u) = (Σ |u_i/S_i|^2)^(1/2),
    with the force-shape law d = 1 − m_0 g(κ)/(m_0 + κ), m_0 = P_e(u_0) (behaviors.md §7.2). The
    initiation point is interpolated linearly in r between the ends of the increment that crosses
    r = 1 (§7.1): θ = (1 − r_n)/(r − r_n), u_0 = u_n + θ (u − u_n)."""

    def __init__(self, k, force_scales, force_limit, motion_scales, law, alphas=None, beta=2.0):
        self.k, self.R, self.F, self.S, self.law = k, force_scales, force_limit, motion_scales, law
        self.alphas = alphas or [2.0] * len(k)
        self.beta = beta
        self.u_n = [0.0] * len(k)
        self.r_n = 0.0
        self.r_max = 0.0
        self.m0 = None
        self.kappa = 0.0
        self.d = 0.0

    def criterion(self, u):
        s = sum(abs(ki * ui / ri) ** a for ki, ui, ri, a in zip(self.k, u, self.R, self.alphas))
        return s ** (1.0 / self.beta) / self.F

    def measure(self, u):
        return math.sqrt(sum((ui / si) ** 2 for ui, si in zip(u, self.S)))

    def update(self, u):
        """Commit at the motion vector u; returns (forces, CDMG, CDIF)."""
        r = self.criterion(u)
        self.r_max = max(self.r_max, r)
        if self.m0 is None and r >= 1.0:
            theta = (1.0 - self.r_n) / (r - self.r_n)
            self.m0 = self.measure([a + theta * (b - a) for a, b in zip(self.u_n, u)])
        if self.m0 is not None:
            self.kappa = max(self.kappa, self.measure(u) - self.m0)
            kind = self.law[0]
            g = g_linear(self.kappa, self.law[1]) if kind == "LINEAR" else g_exponential(self.kappa, *self.law[1:])
            d = 1.0 if g <= 0.0 else 1.0 - self.m0 * g / (self.m0 + self.kappa)
            self.d = max(self.d, d)
        self.u_n, self.r_n = list(u), r
        return [(1.0 - self.d) * ki * ui for ki, ui in zip(self.k, u)], self.d, self.r_max
