"""Golden values of dynamic_automatic_increments: one-DOF oscillators m u'' + c u' + k u = P
under *DYNAMIC with automatic incrementation (docs/dynamics.md "Automatic incrementation"), the
increments chosen here from their own definitions, independently of clinch:

  the operator (HHT-alpha, backward Euler) of dynamic_sdof_recurrence/reference.py, reused, each
  increment solved in closed form;
  the half-increment residual of a solved increment: the state halfway, with the acceleration
  a_h = (a0 + a1)/2 and Newmark's relations over dt/2,
      u_h = u0 + h v0 + h^2 ((1/2 - beta) a0 + beta a_h),  v_h = v0 + h ((1 - gamma) a0 + gamma a_h),
  h = dt/2, put into the HHT equation of motion,
      R_h = m a_h + (1 + alpha) G_h - (alpha/2)(G_0 + G_-1),  G = c v + k u - P,
  G_-1 at the start of the step's previous increment (G_0 in a step's first increment), as the
  Abaqus Theory Manual ("Implicit dynamic analysis") writes it,
  and eps = max |R_h| over the oscillators;
  the time policy (Abaqus Analysis User's Guide, "Time integration accuracy in transient
  problems", and keywords.md section 16): eps > HAFTOL solves the increment again with
  D_A (HAFTOL/eps) dt, D_A = 0.85; after N_S = 3 increments in a row with eps < D_H HAFTOL
  (D_H = 0.75) the next may grow to D_S (HAFTOL/eps) dt (D_S = 0.8), at most D_M = 1.25 times;
  growth by convergence: D_D = 1.5 after two increments in a row with at most I_G = 4 iterations
  (every increment here is linear: one iteration); never above the maximum increment; the last
  increment ends exactly at the step's period.
"""
import math
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import golden_lib as g  # noqa: E402

# The operators of dynamic_sdof_recurrence, each increment solved in closed form.
recurrence = g.case_reference("dynamic_sdof_recurrence")
M, K = recurrence.M, recurrence.K
# Node: (damping c, initial velocity, load once applied).
OSCILLATORS = {2: (0.0, 1.0, 0.0), 3: (0.0, 0.0, 50.0), 4: (2.0, 1.0, 0.0)}
# Step: (initial increment, period, maximum increment, application, HAFTOL or None).
STEPS = [(0.01, 1.0, 0.1, "TRANSIENT FIDELITY", 0.5),
         (0.02, 1.0, 0.2, "MODERATE DISSIPATION", 5.0),
         (0.05, 1.0, 0.5, "QUASI-STATIC", None)]
D_A, D_H, D_S, D_M, N_S = 0.85, 0.75, 0.8, 1.25, 3
D_D = 1.5


def operator(application):
    """(alpha, beta, gamma) of an HHT application; None for backward Euler."""
    alpha, beta, gamma, _ = recurrence.operator(application)
    return None if alpha is None else (alpha, beta, gamma)


def hht_increment(c, p, state, dt, alpha, beta, gamma):
    u0, v0, a0 = state
    return recurrence.hht_increment(c, u0, v0, a0, p, p, dt, alpha, beta, gamma)


def euler_increment(c, p, state, dt):
    u0, v0, _ = state
    return recurrence.euler_increment(c, u0, v0, p, dt)


def half_increment_residual(c, p, start, end, before, dt, alpha, beta, gamma):
    u0, v0, a0 = start
    h = 0.5 * dt
    a_h = 0.5 * (a0 + end[2])
    u_h = u0 + h * v0 + h * h * ((0.5 - beta) * a0 + beta * a_h)
    v_h = v0 + h * ((1.0 - gamma) * a0 + gamma * a_h)
    g0 = c * v0 + K * u0 - p
    return abs(M * a_h + (1.0 + alpha) * (c * v_h + K * u_h - p) - 0.5 * alpha * (g0 + before))


states = {n: (0.0, v0, 0.0) for n, (_, v0, _) in OSCILLATORS.items()}
names = [f"{q}1@{n}" for q in "UVA" for n in OSCILLATORS]
rows = [(1, 0, 0.0, 0.0, [0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 0.0, 0.0, 0.0])]
total = 0.0
residuals = []  # (step, dt, eps) of the accepted increments of the checked steps
for step, (dt, period, dt_max, application, haftol) in enumerate(STEPS, start=1):
    hht = operator(application)
    if hht:  # INITIAL=YES: the accelerations from equilibrium at the step's start
        states = {n: (u, v, (OSCILLATORS[n][2] - OSCILLATORS[n][0] * v - K * u) / M)
                  for n, (u, v, _) in states.items()}
    time, increment, easy, accurate, cutbacks = 0.0, 0, 0, 0, 0
    before = {n: OSCILLATORS[n][0] * v + K * u - OSCILLATORS[n][2]
              for n, (u, v, _) in states.items()}
    while time < period * (1.0 - 1e-12):
        remaining = period - time
        if dt >= remaining * (1.0 - 1e-9):
            dt = remaining
        trial = {}
        for n, (c, _, p) in OSCILLATORS.items():
            trial[n] = (hht_increment(c, p, states[n], dt, *hht) if hht
                        else euler_increment(c, p, states[n], dt))
        eps = None
        if haftol is not None:
            eps = max(half_increment_residual(OSCILLATORS[n][0], OSCILLATORS[n][2], states[n],
                                              trial[n], before[n], dt, *hht)
                      for n in OSCILLATORS)
            if eps > haftol:
                dt *= D_A * haftol / eps
                easy, accurate = 0, 0
                cutbacks += 1
                assert cutbacks <= 5, (step, time, dt)  # I_A: clinch would stop here
                continue
            cutbacks = 0
            before = {n: OSCILLATORS[n][0] * v + K * u - OSCILLATORS[n][2]
                      for n, (u, v, _) in states.items()}
            residuals.append((step, dt, eps))
        states = trial
        time += dt
        increment += 1
        values = [states[n][q] for q in range(3) for n in OSCILLATORS]
        rows.append((step, increment, time, total + time, values))
        accepted = dt
        easy += 1
        if easy >= 2:
            dt *= D_D
        if eps is not None:
            accurate = accurate + 1 if eps < D_H * haftol else 0
            allowed = min(D_M, D_S * haftol / eps) if accurate >= N_S else 1.0
            dt = min(dt, accepted * allowed)
        dt = min(dt, dt_max)
    total += period

# Checks of the reference itself (not of clinch): every accepted increment of a checked step
# holds to its tolerance, and the increments vary (the control acted).
assert all(eps <= STEPS[s - 1][4] for s, _, eps in residuals)
assert len({round(dt, 12) for _, dt, _ in residuals}) > 10

g.write_golden(__file__, [
    "dynamic_automatic_increments: m = 1, k = 100; node 2 from v0 = 1, node 3 under a load of",
    "50 from rest, node 4 from v0 = 1 with c = 2; automatic increments held to the",
    "half-increment residual (TRANSIENT FIDELITY, HAFTOL 0.5; MODERATE DISSIPATION, HAFTOL 5)",
    "and by convergence (QUASI-STATIC), chosen by the same rules written out here",
], names, rows)
