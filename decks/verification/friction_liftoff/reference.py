"""Golden values of friction_liftoff (friction.md §2.2, §3.1, §3.3, §4.1, §4.4).

Element 50, Coulomb (mu = 0.3, k = 1e4): F_N = |f2| = |P(t)| with P the normal load on the free
dof 2 of node b (the SLOT constraint force balances it exactly, whatever the friction does).
Closed form per increment from the committed state:
    F_lim = mu |P|;  f_tr = k (u1 - u_s,n);  stick if |f_tr| <= F_lim: f1 = f_tr;
    slip: f1 = F_lim sgn(f_tr), dgamma = (|f_tr| - F_lim)/k  (with F_lim = 0: f1 = 0,
    dgamma = |f_tr|/k, u_s = u1, §4.1 step 5).
Element 51, exponential decay (mu_s = 0.4, mu_k = 0.2, d_c = 2, F_N = 1000, dt = 0.125):
    stick if |f_tr| <= mu_s F_N; slip: |f_tr| - k dg - F_N mu(dg/dt) = 0, strictly decreasing
    since k = 1e4 > F_N d_c (mu_s - mu_k)/dt = 3200 (asserted), solved by bisection to the last bit.
Asserted: the regimes described in the README (forced slip without motion while the capacity
drops, f1 = 0 at zero normal force, stick after re-contact with f_tr = 0, friction under a
pulling normal force, slip through zero normal force while sliding; stick, breakaway above
mu_s F_N, kinetic slip, reversal), and no decision within 1e-6 of the surface.
"""
import math
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import golden_lib as g  # noqa: E402
import friction_lib as fl  # noqa: E402
import plastic_lib as pl  # noqa: E402

K, MU = 1.0e4, 0.3
DECAY = fl.ExponentialDecay(0.4, 0.2, 2.0)
LIFTOFF = [(0.0, 1.0), (1.0, -1.0)]
RECONTACT = [(0.0, -1.0), (1.0, 1.0)]


class Coulomb:
    def __init__(self):
        self.us, self.gamma = 0.0, 0.0

    def update(self, u1, fn):
        flim = MU * fn
        ftr = K * (u1 - self.us)
        if abs(ftr) <= flim:
            return ftr, 0
        s = math.copysign(1.0, ftr)
        dg = (abs(ftr) - flim) / K
        self.us += s * dg
        self.gamma += dg
        return s * flim, 1


class Decay:
    def __init__(self):
        self.us, self.gamma = 0.0, 0.0

    def update(self, u1, fn, dt):
        ftr = K * (u1 - self.us)
        if abs(ftr) <= DECAY.mu_s * fn:
            return ftr, 0
        assert K > DECAY.rate_bound(fn, dt)

        def phi(dg):
            return abs(ftr) - K * dg - fn * DECAY.mu(dg / dt)

        dg = pl.bisect_decreasing(phi, 0.0, abs(ftr) / K)
        self.us += math.copysign(dg, ftr)
        self.gamma += dg
        return math.copysign(fn * DECAY.mu(dg / dt), ftr), 1


c50, c51 = Coulomb(), Decay()
l50, l51 = fl.Friction(K, fl.Constant(MU)), fl.Friction(K, DECAY)

# (step, dt, targets u1 of nodes 2 and 4, load of node 2 as a function of step time)
steps = [
    (1, 1.0, (0.0, 0.0), lambda t: fl.ramp(0.0, -1000.0, t, 1.0)),
    (2, 0.125, (0.1, 0.1), lambda t: -1000.0),
    (3, 0.125, (0.1, 0.1), lambda t: -1000.0 * g.tabular(t, LIFTOFF)),
    (4, 0.125, (0.2, 0.2), lambda t: -1000.0 * g.tabular(1.0, LIFTOFF)),
    (5, 0.125, (0.3, 0.1), lambda t: -1000.0 * g.tabular(t, RECONTACT)),
]
ids = ["CU1", "CSF1", "CNF1", "CSLIPST1", "CASU1", "CTF2"]
names = fl.columns(ids, [50, 51]) + fl.columns(["RF1"], [2, 4])
rows = [(1, 0, 0.0, 0.0, [0.0] * len(names))]
u = [0.0, 0.0]
hist = {}
t0 = 0.0
for step, dt, target, load in steps:
    u0 = list(u)
    for inc, t in enumerate(fl.increments(dt, 1.0), start=1):
        u = [fl.ramp(a, b, t, 1.0) for a, b in zip(u0, target)]
        p50 = load(t)
        p51 = fl.ramp(0.0, -1000.0, t, 1.0) if step == 1 else -1000.0
        f50, s50 = c50.update(u[0], abs(p50))
        f51, s51 = c51.update(u[1], abs(p51), dt)
        assert abs(l50.update([u[0]], abs(p50), dt)[0] - f50) <= 1e-12 * 300 and l50.status == s50
        assert abs(l51.update([u[1]], abs(p51), dt)[0] - f51) <= 1e-11 * 400 and l51.status == s51
        assert abs(l50.gamma - c50.gamma) <= 1e-15 and abs(l51.gamma - c51.gamma) <= 1e-14
        v50 = [u[0], f50, abs(p50), float(s50), c50.gamma, p50]
        v51 = [u[1], f51, abs(p51), float(s51), c51.gamma, p51]
        values = [x for pair in zip(v50, v51) for x in pair] + [f50, f51]
        rows.append((step, inc, t, t0 + t, values))
        hist[(step, inc)] = (f50, s50, p50, f51, s51)
    t0 += 1.0
fl.check_margins([("element 50", l50), ("element 51", l51)])

# Element 50.
assert [hist[(2, i)][1] for i in range(1, 9)] == [0, 0, 1, 1, 1, 1, 1, 1]
assert hist[(2, 8)][0] == 300.0
# Step 3: held; the capacity 0.3 |P| drops below the force: slip without motion, f1 = 0.3|P|.
for i in range(1, 5):
    assert hist[(3, i)][1] == 1 and abs(hist[(3, i)][0] - 0.3 * abs(hist[(3, i)][2])) <= 1e-12
assert hist[(3, 4)][2] == 0.0 and hist[(3, 4)][0] == 0.0  # lift-off: F_N = 0, f1 = 0
for i in range(5, 9):  # re-contact under tension: capacity returns, f_tr = 0: stick
    assert hist[(3, i)][1] == 0 and hist[(3, i)][0] == 0.0 and hist[(3, i)][2] > 0.0
# Step 4: P = +1000 (pulling), F_N = 1000: stick for 2 increments, then slip at 300.
assert [hist[(4, i)][1] for i in range(1, 9)] == [0, 0, 1, 1, 1, 1, 1, 1]
assert hist[(4, 8)][0] == 300.0
# Step 5: sliding through zero normal force: slip in every increment, f1 = 0.3 |P|.
for i in range(1, 9):
    f, s, p = hist[(5, i)][:3]
    assert s == 1 and abs(f - 0.3 * abs(p)) <= 1e-12 * 300
assert hist[(5, 4)][2] == 0.0 and hist[(5, 4)][0] == 0.0
# Element 51: stick to mu_s F_N = 400, kinetic slip, hold (stick), breakaway, reversal.
assert [hist[(2, i)][4] for i in range(1, 9)] == [0, 0, 0, 1, 1, 1, 1, 1]
assert all(hist[(3, i)][4] == 0 for i in range(1, 9))
assert hist[(4, 1)][4] == 1 and hist[(4, 1)][3] < 400.0
assert [hist[(5, i)][4] for i in range(1, 9)] == [0, 0, 0, 0, 0, 0, 1, 1], \
    [hist[(5, i)][4] for i in range(1, 9)]
# Kinetic slip stays below the static capacity mu_s F_N = 400 (velocity weakening).
assert all(340.0 < abs(v[3]) < 400.0 for v in hist.values() if v[4] == 1)

g.write_golden(__file__, [
    "friction_liftoff: CONN2D2 SLOT, PREDEFINED. Element 50: mu = 0.3, k = 1e4, F_N = |P|, normal",
    "load P: -1000; -1000 -> +1000 held (step 3); +1000 sliding (step 4); +1000 -> -1000 sliding",
    "(step 5). Element 51: exponential decay 0.4, 0.2, d_c = 2, k = 1e4, P = -1000: slide, hold,",
    "slide, reverse. Closed-form return (50), scalar bisection of the slip equation (51).",
], names, rows)
