"""Golden values of dynamic_sdof_recurrence: one-DOF oscillators m u'' + c u' + k u = P under the
integration operators of *DYNAMIC (docs/dynamics.md), written out here from their definitions
(Hilber, Hughes and Taylor 1977; Abaqus Theory Manual "Implicit dynamic analysis"):

  HHT-alpha:  m a1 + (1 + alpha)(c v1 + k u1 - P1) - alpha (c v0 + k u0 - P0) = 0,
              u1 = u0 + dt v0 + dt^2 ((1/2 - beta) a0 + beta a1),
              v1 = v0 + dt ((1 - gamma) a0 + gamma a1);
  backward Euler (APPLICATION=QUASI-STATIC): v1 = (u1 - u0)/dt, a1 = (v1 - v0)/dt,
              m a1 + c v1 + k u1 = P1.

Each increment is linear in u1 and is solved in closed form. INITIAL=YES (the default of the
HHT applications) sets a0 = (P0 - c v0 - k u0)/m at a step's start, with the load at the step's
start (the load of AMPLITUDE=STEP acts there already); QUASI-STATIC keeps the accelerations of
the previous step (INITIAL=NO).
"""
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import golden_lib as g  # noqa: E402

M, K = 1.0, 100.0
# Node: (damping c, initial velocity, load once applied).
OSCILLATORS = {2: (0.0, 1.0, 0.0), 3: (0.0, 0.0, 50.0), 4: (2.0, 1.0, 0.0)}
# Step: (increment, period, application).
STEPS = [(0.01, 0.5, "TRANSIENT FIDELITY"), (0.02, 0.5, "MODERATE DISSIPATION"),
         (0.05, 0.5, "QUASI-STATIC")]


def operator(application):
    """(alpha, beta, gamma, initial) of an APPLICATION (docs/decisions.md "Implicit dynamics")."""
    if application == "QUASI-STATIC":
        return None, None, None, False
    alpha = -0.05 if application == "TRANSIENT FIDELITY" else -0.41421
    return alpha, (1.0 - alpha) ** 2 / 4.0, 0.5 - alpha, True


def hht_increment(c, u0, v0, a0, p0, p1, dt, alpha, beta, gamma):
    # a1 = A u1 + B and v1 = C u1 + D, then the equation of motion, linear in u1.
    big_a = 1.0 / (beta * dt * dt)
    big_b = -(u0 + dt * v0) * big_a - (0.5 / beta - 1.0) * a0
    big_c = gamma * dt * big_a
    big_d = v0 + dt * (1.0 - gamma) * a0 + gamma * dt * big_b
    r0 = c * v0 + K * u0 - p0
    lhs = M * big_a + (1.0 + alpha) * (c * big_c + K)
    rhs = -M * big_b - (1.0 + alpha) * (c * big_d - p1) + alpha * r0
    u1 = rhs / lhs
    return u1, big_c * u1 + big_d, big_a * u1 + big_b


def euler_increment(c, u0, v0, p1, dt):
    # m (u1 - u0 - dt v0)/dt^2 + c (u1 - u0)/dt + k u1 = P1.
    u1 = (p1 + M * (u0 + dt * v0) / dt ** 2 + c * u0 / dt) / (M / dt ** 2 + c / dt + K)
    v1 = (u1 - u0) / dt
    return u1, v1, (v1 - v0) / dt


history = {}
for node, (c, v_start, load) in OSCILLATORS.items():
    u, v, a, p = 0.0, v_start, 0.0, 0.0  # the initial state; no load before step 1
    rows = []
    for dt, period, application in STEPS:
        alpha, beta, gamma, initial = operator(application)
        p = load  # applied at once in step 1 and held after
        if initial:
            a = (p - c * v - K * u) / M
        count = round(period / dt)
        for _ in range(count):
            if alpha is None:
                u, v, a = euler_increment(c, u, v, load, dt)
            else:
                u, v, a = hht_increment(c, u, v, a, p, load, dt, alpha, beta, gamma)
            rows.append((u, v, a))
    history[node] = rows

# The operator is consistent: with alpha = 0 and a tiny increment the free oscillator follows
# sin(10 t)/10 (a check of the recurrence itself, not of clinch).
u, v, a = 0.0, 1.0, 0.0
for _ in range(1000):
    u, v, a = hht_increment(0.0, u, v, a, 0.0, 0.0, 1e-4, 0.0, 0.25, 0.5)
g.assert_close([u], [0.1 * 0.8414709848078965], 1e-8, "trapezoidal recurrence at t = 0.1")

names = [f"{q}1@{n}" for q in "UVA" for n in OSCILLATORS]
rows = [(1, 0, 0.0, 0.0, [0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 0.0, 0.0, 0.0])]
index, total = 0, 0.0
for step, (dt, period, _) in enumerate(STEPS, start=1):
    count = round(period / dt)
    for inc in range(1, count + 1):
        values = [history[n][index][q] for q in range(3) for n in OSCILLATORS]
        rows.append((step, inc, dt * inc, total + dt * inc, values))
        index += 1
    total += period

g.write_golden(__file__, [
    "dynamic_sdof_recurrence: m = 1, k = 100; node 2 from v0 = 1, node 3 under a load of 50 from",
    "rest, node 4 from v0 = 1 with c = 2; HHT-alpha (TRANSIENT FIDELITY, then MODERATE",
    "DISSIPATION with new initial accelerations) and backward Euler (QUASI-STATIC), each",
    "increment solved in closed form from the operator's definition (docs/dynamics.md)",
], names, rows)
