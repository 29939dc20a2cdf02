"""Golden values of dynamic_connector_damping: one-DOF oscillators m u'' + c u' + k u = P whose
spring and damper are a connector's *CONNECTOR ELASTICITY and *CONNECTOR DAMPING (an AXIAL
component between a held node and the mass, small displacements: the component's motion is the
mass's displacement), under the operators of *DYNAMIC (docs/dynamics.md). The recurrence is the
one written out in dynamic_sdof_recurrence/reference.py (HHT-alpha, backward Euler, each
increment solved in closed form), reused here; the damping force is c times the velocity the
operator gives, v1 = v0 + dt((1 - gamma) a0 + gamma a1) or (u1 - u0)/dt.

Connector output: CV1 = v, CA1 = a (the held node does not move), CVF1 = c v. Row 0 is the
initial state: CV1 the initial velocity, CA1 and CVF1 zero (no step has computed an
acceleration or run the damping yet).
"""
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import golden_lib as g  # noqa: E402

recurrence = g.case_reference("dynamic_sdof_recurrence")
assert (recurrence.M, recurrence.K) == (1.0, 100.0)
C = 2.0
# Connector element: (mass node, initial velocity, load once applied).
OSCILLATORS = {1: (2, 1.0, 0.0), 2: (4, 0.0, 50.0)}
STEPS = [(0.01, 0.5, "TRANSIENT FIDELITY"), (0.05, 0.5, "QUASI-STATIC")]

history = {}
for element, (_, v_start, load) in OSCILLATORS.items():
    u, v, a = 0.0, v_start, 0.0
    rows = []
    for dt, period, application in STEPS:
        alpha, beta, gamma, initial = recurrence.operator(application)
        if initial:
            a = (load - C * v - recurrence.K * u) / recurrence.M
        for _ in range(round(period / dt)):
            if alpha is None:
                u, v, a = recurrence.euler_increment(C, u, v, load, dt)
            else:
                u, v, a = recurrence.hht_increment(C, u, v, a, load, load, dt, alpha, beta, gamma)
            rows.append((u, v, a))
    history[element] = rows

names = ([f"{q}@{e}" for q in ("CV1", "CA1", "CVF1") for e in OSCILLATORS]
         + [f"{q}1@{n}" for q in "UVA" for n, _, _ in OSCILLATORS.values()])
rows = [(1, 0, 0.0, 0.0, [1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0])]
index, total = 0, 0.0
for step, (dt, period, _) in enumerate(STEPS, start=1):
    for inc in range(1, round(period / dt) + 1):
        state = [history[e][index] for e in OSCILLATORS]
        values = ([s[1] for s in state] + [s[2] for s in state] + [C * s[1] for s in state]
                  + [s[q] for q in range(3) for s in state])
        rows.append((step, inc, dt * inc, total + dt * inc, values))
        index += 1
    total += period

g.write_golden(__file__, [
    "dynamic_connector_damping: m = 1, k = 100, c = 2 in *CONNECTOR ELASTICITY and DAMPING;",
    "element 1 (node 2) from v0 = 1, element 2 (node 4) under a load of 50 from rest; HHT-alpha",
    "(TRANSIENT FIDELITY) then backward Euler (QUASI-STATIC), each increment solved in closed",
    "form by the recurrence of dynamic_sdof_recurrence/reference.py",
], names, rows)
