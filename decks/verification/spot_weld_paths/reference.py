"""Golden values of spot_weld_paths: the spot weld of derived-components-and-potentials.md §3 as
a coupled plasticity (behaviors.md §6.2, §6.4) on BUSHING connectors loaded along five paths.

Potential: F_n = <f3> + or_n sqrt(m1^2 + m2^2), F_s = or_s |m3| + sqrt(f1^2 + f2^2),
P = ((<F_n>/R_n)^1.5 + (|F_s|/R_s)^1.5)^(1/1.5), F_y = 40000 + 1e7 u_bar, u_bar = lambda.
Elasticity uncoupled, k_t on 1-3 and k_r on 4-6.

Independent backward-Euler closest-point projection (not the Newton of §6.4). Write
n = a grad F_n + b grad F_s with a = dP/dF_n, b = dP/dF_s. For given (dl, a, b) the flow rule
K^-1 (F - F_tr) + dl n = 0 separates into four groups with explicit solutions: f3 is reduced by
k_t dl a (only while positive), the moment pair (m1, m2) and the force pair (f1, f2) shrink
radially by k_r dl a or_n and k_t dl b, and |m3| by k_r dl b or_s. On the yield surface P = t with
t = F_y(u_bar_n + dl), so a = sqrt(F_n/(R_n t))/R_n and b = sqrt(F_s/(R_s t))/R_s; for a given dl
each of F_n and F_s then solves its own increasing scalar equation (bisection), and the outer
equation P(F_n, F_s) - t = 0 is solved for dl by bisection. Each converged state is then
checked against the discrete equations of §6.4 evaluated with a separate, generic evaluator of
derived components and potentials (§1.4, §2.4; which also reproduces states A-C of §3).
"""
import math
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import golden_lib as g  # noqa: E402
import plastic_lib as pl  # noqa: E402

# *PARAMETER block of the deck (same expressions, same double arithmetic).
I_XX, AREA = 30.68, 19.63
R_N_GEOM = math.sqrt(I_XX / AREA)
R_S_GEOM = 2.0 * R_N_GEOM
OR_N, OR_S = 1.0 / R_N_GEOM, 1.0 / R_S_GEOM
RN, RS, BETA = 0.02, 0.05, 1.5
KT, KR = 1.0e5, 1.0e5
K = [KT, KT, KT, KR, KR, KR]
HARD = pl.Hardening([(40000.0, 0.0), (1040000.0, 0.1)])

# ---------------------------------------------------------------------------------------------
# Generic evaluator (derived-components-and-potentials.md §1.3-§1.4, §2.3-§2.5), used only to
# check the converged states. Components are 0-based here (component k -> index k-1).
DERIVED = {
    "normal": [("MACAULEY SUM", 1.0, [2], [1.0]), ("NORM", 1.0, [3, 4], [OR_N, OR_N])],
    "shear": [("NORM", 1.0, [5], [OR_S]), ("NORM", 1.0, [0, 1], [1.0, 1.0])],
}
CONTRIB = [("normal", RN, BETA, "MACAULEY", 0.0, 1.0), ("shear", RS, BETA, "ABS", 0.0, 1.0)]


def derived_value_grad(name, c):
    terms = DERIVED[name]
    m = max(abs(coef * c[k]) for _, _, ks, cs in terms for k, coef in zip(ks, cs))
    value, grad = 0.0, [0.0] * 6
    for op, sign, ks, cs in terms:
        ys = [coef * c[k] for k, coef in zip(ks, cs)]
        if op == "MACAULEY SUM":
            value += sign * sum(max(y, 0.0) for y in ys)
            for k, coef, y in zip(ks, cs, ys):
                grad[k] += sign * coef * (1.0 if y > 0.0 else 0.0)
        elif op == "NORM":
            r = math.sqrt(sum(y * y for y in ys))
            value += sign * r
            if r > 1e-12 * m and r > 0.0:
                for k, coef, y in zip(ks, cs, ys):
                    grad[k] += sign * coef * y / r
        else:
            raise AssertionError(op)
    return value, grad


def potential_value_grad(c):
    es, ges, xs, ps = [], [], [], []
    for name, r, alpha, h, a, s in CONTRIB:
        e, ge = derived_value_grad(name, c)
        x = (e - a) / r
        p = abs(x) if h == "ABS" else max(x, 0.0)
        es.append(e)
        ges.append(ge)
        xs.append(x)
        ps.append(p)
    big = max(abs(x) for x in xs)
    sum_s = sum(s * p ** alpha for (_, _, alpha, _, _, s), p in zip(CONTRIB, ps))
    if sum_s <= 0.0:
        return 0.0, [0.0] * 6, es
    pot = sum_s ** (1.0 / BETA)
    grad = [0.0] * 6
    for (name, r, alpha, h, a, s), x, p, ge in zip(CONTRIB, xs, ps, ges):
        if abs(x) <= 1e-12 * big:
            continue  # H'(0) = 0 (ABS: sgn 0; MACAULEY: inactive side)
        hp = (1.0 if x > 0.0 else -1.0) if h == "ABS" else (1.0 if x > 0.0 else 0.0)
        gi = s * alpha * p ** (alpha - 1.0) * hp / r
        ni = (1.0 / BETA) * sum_s ** (1.0 / BETA - 1.0) * gi
        for k in range(6):
            grad[k] += ni * ge[k]
    return pot, grad, es


# States A, B, C of derived-components-and-potentials.md §3 to the printed digits.
for f, want_p, want_grad in (
    ((100, 0, 500, 200, 0, 0), 33326.4, (4.89949, 0, 49.7538, 39.7977, 0, 0)),
    ((300, -400, -200, 0, 150, 800), 18736.7, (11.2265, -14.9687, 0, 0, 22.6309, 7.48335)),
    ((0, 0, -100, 0, 0, 50), 399.947, (0, 0, 0, 0, 0, 7.99894)),
):
    p, grad, _ = potential_value_grad([float(x) for x in f])
    assert abs(p - want_p) <= 5e-6 * want_p, (p, want_p)
    for x, y in zip(grad, want_grad):
        assert abs(x - y) <= 5e-6 * max(1.0, abs(y)), (grad, want_grad)
    assert abs(sum(fi * gi for fi, gi in zip(f, grad)) - p) <= 1e-9 * p  # Euler (homogeneity)
assert abs(R_N_GEOM - 1.25017) < 5e-6 and abs(OR_N - 0.799894) < 5e-7 and abs(OR_S - 0.399947) < 5e-7


# ---------------------------------------------------------------------------------------------
# Independent return mapping.
def shrink(x, d):
    """max(0, x - d) for x >= 0."""
    return x - d if x > d else 0.0


class SpotWeld:
    def __init__(self, allow_kinks=False):
        self.up = [0.0] * 6
        self.ubar = 0.0
        # With allow_kinks, a group may be returned onto its kink (shrunk exactly to zero); the
        # check then uses the subgradient the flow rule needs there and asserts that it lies in
        # the subdifferential (derived-components-and-potentials.md §1.4).
        self.allow_kinks = allow_kinks
        self.kink_rows = 0

    def update(self, u):
        ftr = [k * (ui - pi) for k, ui, pi in zip(K, u, self.up)]
        fy_n = HARD.fy(self.ubar)
        p_tr = potential_value_grad(ftr)[0]
        # Trial states stay clear of the yield surface (round-off cannot switch the regime).
        assert abs(p_tr - fy_n) > 1e-6 * fy_n, ("trial state on the yield surface", u)
        if p_tr - fy_n <= 0.0:
            return ftr, 0.0, None
        f3_tr = ftr[2]
        rho_m = math.hypot(ftr[3], ftr[4])
        rho_f = math.hypot(ftr[0], ftr[1])
        m3_tr = abs(ftr[5])

        def fn_of(ca):  # F_n after the flow with dl*a = ca
            f3 = shrink(f3_tr, KT * ca) if f3_tr > 0.0 else 0.0
            return f3 + OR_N * shrink(rho_m, KR * ca * OR_N)

        def fs_of(cb):  # F_s after the flow with dl*b = cb
            return OR_S * shrink(m3_tr, KR * cb * OR_S) + shrink(rho_f, KT * cb)

        def inner(dl, t, phi_of, r):
            top = phi_of(0.0)
            if top <= 0.0:
                return 0.0, 0.0

            def gfun(x):
                coef = math.sqrt(x / (r * t)) / r if x > 0.0 else 0.0
                return x - phi_of(dl * coef)

            if gfun(top) <= 0.0:
                x = top
            else:
                x = pl.bisect_increasing(gfun, 0.0, top)
            return x, (math.sqrt(x / (r * t)) / r if x > 0.0 else 0.0)

        def solve_groups(dl):
            t = HARD.fy(self.ubar + dl)
            fn, a = inner(dl, t, fn_of, RN)
            fs, b = inner(dl, t, fs_of, RS)
            return t, fn, a, fs, b

        def psi(dl):
            t, fn, _, fs, _ = solve_groups(dl)
            return ((fn / RN) ** BETA + (fs / RS) ** BETA) ** (1.0 / BETA) - t

        hi = 1e-9
        while psi(hi) > 0.0:
            hi *= 2.0
        dl = pl.bisect_decreasing(psi, 0.0, hi)
        t, fn, a, fs, b = solve_groups(dl)
        ca, cb = dl * a, dl * b
        f = list(ftr)
        # (indices, reduction capacity, Macaulay?) of each group that was shrunk exactly to zero.
        clipped = []
        if f3_tr > 0.0:
            f[2] = shrink(f3_tr, KT * ca)
            if f[2] == 0.0:
                clipped.append(((2,), KT * ca, True))
        for idx, rho, d in (((3, 4), rho_m, KR * ca * OR_N), ((0, 1), rho_f, KT * cb)):
            if rho > 0.0:
                scale = shrink(rho, d) / rho
                for i in idx:
                    f[i] = ftr[i] * scale
                if scale == 0.0:
                    clipped.append((idx, d, False))
        if m3_tr > 0.0:
            f[5] = math.copysign(shrink(m3_tr, KR * cb * OR_S), ftr[5])
            if f[5] == 0.0:
                clipped.append(((5,), KR * cb * OR_S, False))
        # A group driven exactly to zero needs a subgradient other than the minimum-norm choice
        # (§1.4); the paths of spot_weld_paths are chosen so that this never happens.
        assert self.allow_kinks or not clipped, "a group was returned onto its kink"
        self.up = [pi + (ti - fi) / k for pi, ti, fi, k in zip(self.up, ftr, f, K)]
        self.ubar += dl
        # Discrete equations of behaviors.md §6.4 with the generic evaluator.
        p, n, _ = potential_value_grad(f)
        for idx, capacity, macauley in clipped:
            # The flow rule on a group at zero asks for dl*zeta-weighted subgradient
            # (F_tr - 0)/k: zeta = F_tr/capacity must lie in the unit ball (NORM) or in [0, 1]
            # (Macaulay), the group's subdifferential.
            zeta = [ftr[i] / capacity for i in idx]
            if macauley:
                assert 0.0 <= zeta[0] <= 1.0, zeta
            else:
                assert math.sqrt(sum(z * z for z in zeta)) <= 1.0, zeta
            for i in idx:
                n[i] = (ftr[i] - f[i]) / (K[i] * dl)
            self.kink_rows += 1
        res = pl.check_coupled(ftr, f, dl, K, n, p, HARD.fy(self.ubar))
        assert (abs(f[2]) > 1e-6 * max(abs(x) for x in f) or f3_tr <= 0.0 or f[2] == ftr[2]
                or any(idx == (2,) for idx, _, _ in clipped))
        return f, dl, res


# Paths: per element, the targets of node b (u1, u2, u3, ur1, ur2, ur3) at the end of each step.
NODES = {1: 2, 2: 4, 3: 6, 4: 8, 5: 10}
TARGETS = {
    1: [{3: 0.012}, {3: -0.004}, {3: 0.02}],                      # tension, compression, reload
    2: [{1: 0.021, 2: 0.015}, {1: -0.02}, {6: 0.06}],              # shear, rotate shear, + torsion
    3: [{4: 0.012}, {5: 0.012}, {4: -0.01}],                      # bending, non-proportional
    4: [{3: 0.006, 4: 0.006}, {3: -0.006, 4: 0.03}, {3: 0.012, 1: 0.012}],  # f3 = 0 with bending
    5: [{3: 0.006, 1: 0.012}, {3: -0.004, 1: 0.04}, {2: 0.012, 3: 0.012}],  # f3 = 0 with shear
}
NINC = 5
COLUMNS = 15  # per element: CTF1-6, CUP1-6, CUPEQ, CDERF-normal, CDERF-shear


def path_rows(targets, increments, welds, observe=None):
    """Drives each weld along its targets (node-b motions at the end of each step, reached
    linearly over `increments` equal increments; unlisted dofs keep their value). Returns the
    column names and the rows of the golden table (row 0 the initial state); `observe(el, f, dl,
    res, weld)` sees every update."""
    names = []
    for el in targets:
        names += [f"CTF{i}@{el}" for i in range(1, 7)] + [f"CUP{i}@{el}" for i in range(1, 7)]
        names += [f"CUPEQ@{el}", f"CDERF-normal@{el}", f"CDERF-shear@{el}"]
    rows = [(1, 0, 0.0, 0.0, [0.0] * len(names))]
    motion = {el: [0.0] * 6 for el in targets}
    for step in range(len(next(iter(targets.values())))):
        start = {el: list(motion[el]) for el in targets}
        for inc in range(1, increments + 1):
            tau = inc / increments
            values = []
            for el, w in welds.items():
                for comp, target in targets[el][step].items():
                    v0 = start[el][comp - 1]
                    motion[el][comp - 1] = v0 + (target - v0) * tau
                f, dl, res = w.update(motion[el])
                if observe:
                    observe(el, f, dl, res, w)
                _, _, (fn, fs) = potential_value_grad(f)
                values += f + w.up + [w.ubar, fn, fs]
            rows.append((step + 1, inc, tau, step + tau, values))
    return names, rows


if __name__ == "__main__":
    worst = [0.0, 0.0]
    sign_changes = {el: [] for el in TARGETS}
    plastic = {el: 0 for el in TARGETS}

    def observe(el, f, dl, res, w):
        global worst
        if res:
            worst = [max(worst[0], res[0]), max(worst[1], res[1])]
            plastic[el] += 1
        sign_changes[el].append((f[2] > 0.0, dl > 0.0))

    names, rows = path_rows(TARGETS, NINC, {el: SpotWeld() for el in TARGETS}, observe)
    # f3 changes sign on a plastic increment of elements 4 and 5 (both directions).
    for el in (4, 5):
        flips = [i for i in range(1, len(sign_changes[el]))
                 if sign_changes[el][i][0] != sign_changes[el][i - 1][0] and sign_changes[el][i][1]]
        assert len(flips) >= 2, (el, sign_changes[el])
    assert all(v >= 4 for v in plastic.values()), plastic
    print("plastic increments per element:", plastic, " worst relative residuals:", worst)
    g.write_golden(__file__, [
        "spot_weld_paths: BUSHING, k = 1e5 on 1-6, spot-weld potential of",
        "derived-components-and-potentials.md §3 (R_n = 0.02, R_s = 0.05, beta = 1.5), F_y = 40000",
        "+ 1e7 u_bar. Five elements, three steps of five increments (paths in README.md). Backward",
        "Euler closest-point projection by nested bisection (reference.py); every plastic row",
        "satisfies the discrete equations of behaviors.md §6.4 to 1e-12 relative",
    ], names, rows)
