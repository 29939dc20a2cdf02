"""Golden values of dynamic_sdof_closed_form: the exact motion of one-DOF oscillators
m u'' + c u' + k u = P (m = 1, k = 100: omega = 10), which *DYNAMIC with ALPHA=0 (the
trapezoidal rule, beta = 1/4, gamma = 1/2) follows up to its discretisation error.

  node 2, free from v0 = 1:        u = (v0/w) sin(w t)
  node 3, P = 50 at once, at rest: u = (P/k)(1 - cos(w t))
  node 4, c = 2 (zeta = 0.1):      u = (v0/wd) exp(-zeta w t) sin(wd t), wd = w sqrt(1 - zeta^2)

The trapezoidal rule has no amplitude error on an undamped oscillator and its frequency is
w_h = (2/dt) atan(w dt/2) (Hughes, The Finite Element Method, §9.3): after a time t the phase
lags by (w - w_h) t = w^3 dt^2 t/12 + O(dt^4) = 8.3e-5 rad at t = 1 for w dt = 0.01, an error
of 8.3e-5 of each column's amplitude (the step load acts from the step's start, where it sets
the initial acceleration P/m: docs/dynamics.md). compare.args allows 2e-4 of each column's largest value; this script
checks that the recurrence of the operator, written out here, stays within half of it.
"""
import math
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import golden_lib as g  # noqa: E402

M, K, C, V0, P = 1.0, 100.0, 2.0, 1.0, 50.0
W = math.sqrt(K / M)
ZETA = C / (2.0 * math.sqrt(K * M))
WD = W * math.sqrt(1.0 - ZETA * ZETA)
DT, PERIOD, EVERY = 0.001, 1.0, 50
RTOL = 2e-4  # compare.args


def free(t):
    return V0 / W * math.sin(W * t), V0 * math.cos(W * t), -V0 * W * math.sin(W * t)


def loaded(t):
    return P / K * (1.0 - math.cos(W * t)), P / K * W * math.sin(W * t), P / M * math.cos(W * t)


def damped(t):
    e, s, c = math.exp(-ZETA * W * t), math.sin(WD * t), math.cos(WD * t)
    u = V0 / WD * e * s
    v = V0 * e * (c - ZETA * W / WD * s)
    return u, v, (P * 0.0 - C * v - K * u) / M


def trapezoidal(c, v0, load):
    """The operator's recurrence, each increment solved for u1 in closed form."""
    u, v, a = 0.0, v0, (load - c * v0) / M  # INITIAL=YES, with the load of the step's start
    out = []
    for _ in range(round(PERIOD / DT)):
        big_a = 4.0 / DT ** 2
        big_b = -(u + DT * v) * big_a - a
        big_c, big_d = 0.5 * DT * big_a, v + 0.5 * DT * a + 0.5 * DT * big_b
        u1 = (load - M * big_b - c * big_d) / (M * big_a + c * big_c + K)
        u, v, a = u1, big_c * u1 + big_d, big_a * u1 + big_b
        out.append((u, v, a))
    return out


exact = [free, loaded, damped]
discrete = [trapezoidal(0.0, V0, 0.0), trapezoidal(0.0, 0.0, P), trapezoidal(C, V0, 0.0)]
count = round(PERIOD / DT)
# The discretisation error stays within half the tolerance, column by column.
for f, d in zip(exact, discrete):
    for q in range(3):
        scale = max(abs(f(DT * n)[q]) for n in range(1, count + 1))
        worst = max(abs(d[n - 1][q] - f(DT * n)[q]) for n in range(1, count + 1))
        if worst > 0.5 * RTOL * scale:
            raise SystemExit(f"discretisation error {worst} above half the tolerance of {scale}")
# The predicted phase lag of the trapezoidal rule.
lag = (W - 2.0 / DT * math.atan(W * DT / 2.0)) * PERIOD
g.assert_close([lag], [W ** 3 * DT ** 2 * PERIOD / 12.0], 1e-8, "phase lag")  # O(dt^4) rest

names = [f"{q}1@{n}" for q in "UVA" for n in (2, 3, 4)]
rows = [(1, 0, 0.0, 0.0, [0.0, 0.0, 0.0, V0, 0.0, V0, 0.0, 0.0, 0.0])]
for inc in range(EVERY, count + 1, EVERY):
    t = DT * inc
    values = [f(t)[q] for q in range(3) for f in exact]
    rows.append((1, inc, t, t, values))

g.write_golden(__file__, [
    "dynamic_sdof_closed_form: m = 1, k = 100; node 2 free from v0 = 1, node 3 under P = 50 from",
    "rest, node 4 from v0 = 1 with c = 2 (zeta = 0.1); exact motion u(t), v(t), a(t) of each; the",
    "trapezoidal rule (ALPHA=0, dt = 0.001) lags by w^3 dt^2 t/12 = 8.3e-5 rad at t = 1",
], names, rows)
