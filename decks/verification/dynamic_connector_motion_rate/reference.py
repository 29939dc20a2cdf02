"""Golden values of dynamic_connector_motion_rate: two masses m = 1 on springs k = 100 whose bases
are driven through AXIAL connectors from held ground nodes (small displacements: the
connector's motion CU1 is the base's displacement) by *CONNECTOR MOTION of TYPE=VELOCITY and
TYPE=ACCELERATION (docs/dynamics.md "Prescribed velocities and accelerations"), under HHT-alpha
of APPLICATION=TRANSIENT FIDELITY:

  system A: the base's velocity v_b(t) = 2 s(t), s the SMOOTH STEP from 0 at t = 0 to 1 at
    t = 0.2, held at 2 in step 2: the recurrence of dynamic_base_velocity/reference.py, reused
    (the Newmark relations solved for the displacement whose velocity is prescribed; the mass by
    the HHT equation);
  system B: the base's acceleration a_b(t) = 10 s(t), held at 10 in step 2: the Newmark
    relations with the prescribed acceleration,
      u_b1 = u_b0 + dt v_b0 + dt^2 ((1/2 - beta) a_b0 + beta a_b1),
      v_b1 = v_b0 + dt ((1 - gamma) a_b0 + gamma a_b1),
    and the mass by the same HHT equation.

INITIAL=YES at each step's start: the masses' a0 = -k (u0 - u_b0)/m, and the bases, which carry no
inertia, start from a0 = 0. The connectors' CU1, CV1, CA1 are the bases' U1, V1, A1.
"""
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import golden_lib as g  # noqa: E402

base = g.case_reference("dynamic_base_velocity")
M, K, BETA, GAMMA = base.M, base.K, base.BETA, base.GAMMA
STEPS = base.STEPS  # (0.01, 0.5), (0.01, 0.2)


def base_acceleration(t):
    return 10.0 * g.smooth_step(t, 0.0, 0.0, 0.2, 1.0)


def value_of_acceleration(u0, v0, a0, a1, dt):
    u1 = u0 + dt * v0 + dt * dt * ((0.5 - BETA) * a0 + BETA * a1)
    return u1, v0 + dt * ((1 - GAMMA) * a0 + GAMMA * a1)


# Per system: base (u, v, a) and mass (u, v, a).
a_base, a_mass = [0.0, 0.0, 0.0], [0.0, 0.0, 0.0]
b_base, b_mass = [0.0, 0.0, 0.0], [0.0, 0.0, 0.0]
names = ["CU1@1", "CU1@2", "CV1@1", "CV1@2", "CA1@1", "CA1@2"] + [
    f"{q}1@{n}" for q in "UVA" for n in (1, 2, 3, 4)]
rows = [(1, 0, 0.0, 0.0, [0.0] * len(names))]
total = 0.0
for step, (dt, period) in enumerate(STEPS, start=1):
    for bas, mass in ((a_base, a_mass), (b_base, b_mass)):  # INITIAL=YES
        mass[2], bas[2] = -K * (mass[0] - bas[0]) / M, 0.0
    for inc in range(1, round(period / dt) + 1):
        t = total + dt * inc
        vb1 = base.base_velocity(t) if step == 1 else 2.0
        ub1, ab1 = base.value_of_velocity(a_base[0], a_base[1], a_base[2], vb1, dt)
        a_mass[:] = base.mass_increment(*a_mass, a_base[0], ub1, dt)
        a_base[:] = [ub1, vb1, ab1]
        ab1 = base_acceleration(t) if step == 1 else 10.0
        ub1, vb1 = value_of_acceleration(b_base[0], b_base[1], b_base[2], ab1, dt)
        b_mass[:] = base.mass_increment(*b_mass, b_base[0], ub1, dt)
        b_base[:] = [ub1, vb1, ab1]
        connectors = [a_base[0], b_base[0], a_base[1], b_base[1], a_base[2], b_base[2]]
        nodes = [s[q] for q in range(3) for s in (a_base, a_mass, b_base, b_mass)]
        rows.append((step, inc, dt * inc, t, connectors + nodes))
    total += period

g.write_golden(__file__, [
    "dynamic_connector_motion_rate: masses m = 1 on k = 100 whose bases are driven by *CONNECTOR",
    "MOTION of TYPE=VELOCITY (2 times a SMOOTH STEP over 0.2) and TYPE=ACCELERATION (10 times",
    "it), held in step 2; HHT-alpha (TRANSIENT FIDELITY) written out for the prescribed rates",
    "and the masses (docs/dynamics.md)",
], names, rows)
