"""Golden values of friction_slot_reversal (friction.md §7.1).

Closed form per increment (friction.md §4.1, rate-independent, P = |f1|, K_s = k): with
F_N = |f2| = 1000 (the SLOT constraint force balances the normal load), F_lim = mu F_N = 300,
    f_tr = k (u1 - u_s,n);  stick if |f_tr| <= F_lim: f1 = f_tr;
    slip: f1 = F_lim sgn(f_tr), dgamma = (|f_tr| - F_lim)/k, u_s += dgamma sgn(f_tr).
The predefined form (element 10) and COMPONENT=1, CONTACT FORCE=2 (element 11) give the same
numbers. The hand table of friction.md §7.1 is asserted to its printed digits.
"""
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import golden_lib as g  # noqa: E402
import friction_lib as fl  # noqa: E402

K, MU, LOAD = 1.0e4, 0.3, -1000.0
ELEMENTS = (10, 11)
NODE_B = {10: 2, 11: 4}

# Independent closed form of the SLOT friction update.
class Slot:
    def __init__(self):
        self.us, self.gamma = 0.0, 0.0

    def update(self, u1, fn):
        flim = MU * fn
        ftr = K * (u1 - self.us)
        if abs(ftr) <= flim:
            return ftr, 0
        s = 1.0 if ftr > 0.0 else -1.0
        dg = (abs(ftr) - flim) / K
        self.us += s * dg
        self.gamma += dg
        return s * flim, 1


closed = Slot()
lib = fl.Friction(K, fl.Constant(MU))  # the shared scalar return, cross-checked below

steps = [  # (step, dt, period, u1 target, load target)
    (1, 1.0, 1.0, 0.0, LOAD),
    (2, 0.125, 1.0, 0.1, LOAD),
    (3, 0.0625, 1.0, -0.1, LOAD),
]
idents = ["CU1", "CSF1", "CNF1", "CSLIPST1", "CASU1", "CTF1", "CTF2"]
names = fl.columns(idents, ELEMENTS) + fl.columns(["RF1"], NODE_B.values())
rows = [(1, 0, 0.0, 0.0, [0.0] * len(names))]
table = {}
u1, load, t0 = 0.0, 0.0, 0.0
for step, dt, period, u_end, load_end in steps:
    u0, p0 = u1, load
    for inc, t in enumerate(fl.increments(dt, period), start=1):
        u1 = fl.ramp(u0, u_end, t, period)
        load = fl.ramp(p0, load_end, t, period)
        f2 = load  # constraint force of component 2 = the load on the free dof 2 of node b
        fn = abs(f2)
        f1, status = closed.update(u1, fn)
        f1_lib = lib.update([u1], fn, dt)[0]
        assert abs(f1 - f1_lib) <= 1e-12 * 300.0 and status == lib.status
        assert abs(closed.gamma - lib.gamma) <= 1e-15 and abs(closed.us - lib.us[0]) <= 1e-15
        per = {"CU1": u1, "CSF1": f1, "CNF1": fn, "CSLIPST1": float(status),
               "CASU1": closed.gamma, "CTF1": f1, "CTF2": f2}
        values = [per[v] for v in idents for _ in ELEMENTS]
        values += [f1 for _ in ELEMENTS]  # RF1 at node b = CTF1 (friction.md §7)
        rows.append((step, inc, t, t0 + t, values))
        table[(step, inc)] = (u1, f1, status, closed.us, closed.gamma)
    t0 += period
fl.check_margins([("slot", lib)])

# friction.md §7.1 hand table: (u1, CSF1, CSLIPST1, u_s, CASU1).
spec = {
    (1, 1): (0.0, 0.0, 0, 0.0, 0.0),
    (2, 1): (0.0125, 125.0, 0, 0.0, 0.0),
    (2, 2): (0.025, 250.0, 0, 0.0, 0.0),
    (2, 3): (0.0375, 300.0, 1, 0.0075, 0.0075),
    (2, 4): (0.05, 300.0, 1, 0.02, 0.02),
    (2, 8): (0.1, 300.0, 1, 0.07, 0.07),
    (3, 1): (0.0875, 175.0, 0, 0.07, 0.07),
    (3, 2): (0.075, 50.0, 0, 0.07, 0.07),
    (3, 3): (0.0625, -75.0, 0, 0.07, 0.07),
    (3, 4): (0.05, -200.0, 0, 0.07, 0.07),
    (3, 5): (0.0375, -300.0, 1, 0.0675, 0.0725),
    (3, 6): (0.025, -300.0, 1, 0.055, 0.085),
    (3, 16): (-0.1, -300.0, 1, -0.07, 0.21),
}
for key, want in spec.items():
    got = table[key]
    for x, y in zip(got, want):
        assert abs(x - y) <= 1e-9 * max(1.0, abs(y)), (key, got, want)
for inc in range(4, 9):  # 2.4-2.8: u_s = CASU1 = u1 - 0.03
    u, f, st, us, gam = table[(2, inc)]
    assert st == 1 and abs(us - (u - 0.03)) <= 1e-15 and abs(gam - (u - 0.03)) <= 1e-15
for inc in range(5, 17):  # 3.k: u_s = u1 + 0.03, CASU1 = 0.07 + (0.07 - u_s)
    u, f, st, us, gam = table[(3, inc)]
    assert st == 1 and abs(us - (u + 0.03)) <= 1e-15 and abs(gam - (0.14 - us)) <= 1e-15

g.write_golden(__file__, [
    "friction_slot_reversal: friction.md §7.1, CONN2D2 SLOT, mu = 0.3, k = 1e4, normal load",
    "-1000 (F_N = |CTF2| = 1000, F_lim = 300); u1 = 0 (step 1), 0 -> 0.1 in 8 increments,",
    "0.1 -> -0.1 in 16. Element 10 PREDEFINED, element 11 COMPONENT=1, CONTACT FORCE=2 (same",
    "values). Closed-form return per increment; the §7.1 hand table is asserted.",
], names, rows)
