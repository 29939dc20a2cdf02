"""Golden values of dynamic_base_velocity: a mass m = 1 on a spring k = 100 whose base (node 1) has
a prescribed velocity v_b(t) = 2 s(t), s the SMOOTH STEP from 0 at t = 0 to 1 at t = 0.2
(10 t'^3 - 15 t'^4 + 6 t'^5, t' = t/0.2), carried over at 2 into step 2 (docs/dynamics.md
"Prescribed velocities and accelerations"). HHT-alpha of APPLICATION=TRANSIENT FIDELITY
(alpha = -0.05, beta = (1 - alpha)^2/4, gamma = 1/2 - alpha), written out from its definition
(Hilber, Hughes and Taylor 1977):

  base:  a_b1 = (v_b1 - v_b0 - dt (1 - gamma) a_b0)/(gamma dt),
         u_b1 = u_b0 + dt v_b0 + dt^2 ((1/2 - beta) a_b0 + beta a_b1)   (the Newmark relations
         solved for the displacement whose velocity is prescribed);
  mass:  m a1 + (1 + alpha) k (u1 - u_b1) - alpha k (u0 - u_b0) = 0, with the same relations.

INITIAL=YES at each step's start: the mass's a0 = -k (u0 - u_b0)/m from equilibrium, and the base,
which carries no inertia, starts from a0 = 0 (docs/dynamics.md: the initial accelerations are
computed on the free DOFs with inertia, 0 elsewhere).
"""
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import golden_lib as g  # noqa: E402

M, K = 1.0, 100.0
ALPHA = -0.05
BETA, GAMMA = (1 - ALPHA) ** 2 / 4, 0.5 - ALPHA
STEPS = [(0.01, 0.5), (0.01, 0.2)]


def base_velocity(t):
    return 2.0 * g.smooth_step(t, 0.0, 0.0, 0.2, 1.0)


def value_of_velocity(u0, v0, a0, v1, dt):
    a1 = (v1 - v0 - dt * (1 - GAMMA) * a0) / (GAMMA * dt)
    return u0 + dt * v0 + dt * dt * ((0.5 - BETA) * a0 + BETA * a1), a1


def mass_increment(u0, v0, a0, ub0, ub1, dt):
    # a1 = A u1 + B from the Newmark relations, then the HHT equation, linear in u1.
    big_a = 1.0 / (BETA * dt * dt)
    big_b = -(u0 + dt * v0) * big_a - (0.5 / BETA - 1.0) * a0
    lhs = M * big_a + (1 + ALPHA) * K
    rhs = -M * big_b + (1 + ALPHA) * K * ub1 + ALPHA * K * (u0 - ub0)
    u1 = rhs / lhs
    a1 = big_a * u1 + big_b
    return u1, v0 + dt * ((1 - GAMMA) * a0 + GAMMA * a1), a1


ub, vb, ab = 0.0, 0.0, 0.0
u, v, a = 0.0, 0.0, 0.0
names = ["U1@1", "U1@2", "V1@1", "V1@2", "A1@1", "A1@2"]
rows = [(1, 0, 0.0, 0.0, [0.0] * 6)]
total = 0.0
for step, (dt, period) in enumerate(STEPS, start=1):
    a, ab = -K * (u - ub) / M, 0.0  # INITIAL=YES
    for inc in range(1, round(period / dt) + 1):
        t = total + dt * inc
        vb1 = base_velocity(t) if step == 1 else 2.0
        ub1, ab1 = value_of_velocity(ub, vb, ab, vb1, dt)
        u, v, a = mass_increment(u, v, a, ub, ub1, dt)
        ub, vb, ab = ub1, vb1, ab1
        rows.append((step, inc, dt * inc, t, [ub, u, vb, v, ab, a]))
    total += period

g.write_golden(__file__, [
    "dynamic_base_velocity: m = 1 on k = 100, the base's velocity prescribed (2 times a SMOOTH",
    "STEP over 0.2, then held at 2 in step 2); HHT-alpha (TRANSIENT FIDELITY) written out for",
    "the base's prescribed velocity and the mass's motion (docs/dynamics.md)",
], names, rows)
