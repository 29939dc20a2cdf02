"""Golden values of friction_exponential_decay (friction.md §3.3, §4.1, §7.3).

F_N = F_int = 1000 (no CONTACT FORCE), mu(rate) = 0.2 + 0.2 exp(-2 rate), rate = dgamma/dt with
dt the increment of step time (§3.3). Per increment from the committed state:
    f_tr = k (u1 - u_s,n);  stick if |f_tr| <= mu_s F_N = 400 (the stick test uses rate 0);
    slip: the scalar equation |f_tr| - k dg - F_N mu(dg/dt) = 0 on [0, |f_tr|/k], solved by
    bisection to the last bit (the left side is strictly decreasing because every increment
    satisfies k > F_N d_c (mu_s - mu_k)/dt, asserted); f1 = sgn(f_tr) F_N mu(dg/dt).
Asserted: the §7.3 table (dg, rate, mu, CSF1, CASU1 and the tangent at increments 1, 2, 3, 5, 10;
the tangent by central differences of the return map from the committed state and by the closed
form k h/(k + h)), the steady state 334.064, and mu = 0.399202 (CSF1 = 399.202) over a step time
of 100.
"""
import math
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import golden_lib as g  # noqa: E402
import friction_lib as fl  # noqa: E402
import plastic_lib as pl  # noqa: E402

K, FN = 1.0e5, 1000.0
LAW = fl.ExponentialDecay(0.4, 0.2, 2.0)
f_int = pl.Hardening([(FN, 0.0)])


class Decay:
    """The 1-D update written out on its own (checked against friction_lib)."""

    def __init__(self):
        self.us, self.gamma = 0.0, 0.0

    def solve(self, u1, dt):
        ftr = K * (u1 - self.us)
        if abs(ftr) <= LAW.mu_s * FN:
            return ftr, 0.0

        def phi(dg):
            return abs(ftr) - K * dg - FN * LAW.mu(dg / dt)

        dg = pl.bisect_decreasing(phi, 0.0, abs(ftr) / K)
        return math.copysign(FN * LAW.mu(dg / dt), ftr), dg

    def update(self, u1, dt):
        ftr = K * (u1 - self.us)
        f, dg = self.solve(u1, dt)
        self.us += math.copysign(dg, ftr)
        self.gamma += dg
        return f, dg


models = {30: (Decay(), fl.Friction(K, LAW, f_int=f_int)),
          31: (Decay(), fl.Friction(K, LAW, f_int=f_int))}
steps = [  # (step, dt, period, {element: target u1})
    (1, 0.1, 1.0, {30: 0.2, 31: 0.0}),
    (2, 10.0, 100.0, {30: 0.2, 31: 0.2}),
    (3, 0.01, 1.0, {30: 0.4, 31: 0.2}),
]
idents = ["CU1", "CSF1", "CNF1", "CSLIPST1", "CASU1", "CTF1"]
names = fl.columns(idents, [30, 31]) + fl.columns(["RF1"], [2, 4])
rows, table = [], {}
u = {30: 0.0, 31: 0.0}
t0 = 0.0
for step, dt, period, target in steps:
    start = dict(u)
    for inc, t in enumerate(fl.increments(dt, period), start=1):
        per = {}
        for el in (30, 31):
            assert K > LAW.rate_bound(FN, dt)  # friction.md §7.3 uniqueness condition
            u[el] = fl.ramp(start[el], target[el], t, period)
            ref, lib = models[el]
            h = 1e-9
            tangent = (ref.solve(u[el] + h, dt)[0] - ref.solve(u[el] - h, dt)[0]) / (2 * h)
            f, dg = ref.update(u[el], dt)
            f_lib = lib.update([u[el]], 0.0, dt)[0]
            assert abs(f - f_lib) <= 1e-11 * 400.0 and abs(ref.gamma - lib.gamma) <= 1e-14
            assert (dg > 0.0) == (lib.status == 1)
            per[el] = {"CU1": u[el], "CSF1": f, "CNF1": FN, "CSLIPST1": float(lib.status),
                       "CASU1": ref.gamma, "CTF1": f}
            table[(el, step, inc)] = (u[el], dg, dg / dt, abs(f) / FN, f, ref.gamma, tangent)
        values = [per[el][v] for v in idents for el in (30, 31)]
        values += [per[30]["CSF1"], per[31]["CSF1"]]  # RF1 at node b = CTF1
        rows.append((step, inc, t, t0 + t, values))
    t0 += period
fl.check_margins([("element 30", models[30][1]), ("element 31", models[31][1])])

# friction.md §7.3 table: (u1, dgamma, rate, mu, CSF1, CASU1, df1/du1).
spec = {1: (0.02, 0.0165640, 0.165640, 0.343601, 343.601, 0.0165640, -2956.94),
        2: (0.04, 0.0200980, 0.200980, 0.333802, 333.802, 0.0366620, -2749.61),
        3: (0.06, 0.0199973, 0.199973, 0.334071, 334.071, 0.0566593, -2755.31),
        5: (0.10, 0.0200000, 0.200000, 0.334064, 334.064, 0.0966594, -2755.15),
        10: (0.20, 0.0200000, 0.200000, 0.334064, 334.064, 0.196659, -2755.15)}
for inc, want in spec.items():
    got = table[(30, 1, inc)]
    for x, y in zip(got, want):
        assert abs(x - y) <= 6e-6 * abs(y), (inc, got, want)  # six printed digits
h_rate = FN * LAW.dmu(0.2) / 0.1  # h = F_N mu'(rate)/dt = -2681.28
assert abs(h_rate + 2681.28) <= 5e-3 and abs(K * h_rate / (K + h_rate) + 2755.15) <= 5e-3
assert abs(table[(30, 1, 10)][6] - K * h_rate / (K + h_rate)) <= 1e-3
# Steady state 0.2 + 0.2 e^-0.4 = 0.334064; the same with dt = 0.01 (step 3).
steady = 0.2 + 0.2 * math.exp(-0.4)
assert abs(steady - 0.334064) <= 5e-7
assert abs(table[(30, 3, 100)][4] - FN * steady) <= 1e-6
# Step time 100: rate 0.002, mu = 0.399202, CSF1 = 399.202 (steady from the second increment).
assert abs(table[(31, 2, 10)][2] - 0.002) <= 5e-7 and abs(table[(31, 2, 10)][3] - 0.399202) <= 5e-7
assert abs(table[(31, 2, 10)][4] - 399.202) <= 5e-4
# Element 30 sticks in step 2 (held, 334 < 400); element 31 sticks in step 3.
assert all(table[(30, 2, i)][1] == 0.0 for i in range(1, 11))
assert all(table[(31, 3, i)][1] == 0.0 for i in range(1, 101))

g.write_golden(__file__, [
    "friction_exponential_decay: friction.md §7.3, CONN2D2 SLOT, COMPONENT=1, F_int = 1000,",
    "mu = 0.2 + 0.2 exp(-2 rate), k = 1e5. Element 30: u1 0 -> 0.2 over step time 1 (10",
    "increments), held over step 2, 0.2 -> 0.4 over step time 1 in 100 increments. Element 31:",
    "u1 0 -> 0.2 over step time 100 (10 increments). Scalar slip equation solved by bisection;",
    "the §7.3 table, 334.064 and 0.399202 are asserted. Row 0 is not listed (CNF at time 0).",
], names, rows)
