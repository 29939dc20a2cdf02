"""Golden values of dashpots: DASHPOTA, DASHPOT1 and DASHPOT2 in *STATIC (behaviors.md §8).

Closed form: in an increment a dashpot's velocity is v = (Δ_{n+1} − Δ_n)/dt and its force
S11 = c v, or the NONLINEAR table at v (held constant beyond its ends, keywords.md §7); E11 = Δ.
Driven elements 1–4 follow the boundary, which ramps linearly over each step, so every increment
of a step has the same velocity. The loaded Kelvin–Voigt pair (elements 5–6, node 7) satisfies
k u_{n+1} + c (u_{n+1} − u_n)/dt = P_{n+1} in each increment (backward Euler of k u + c u' = P),
with P ramped from 0 to 5 over step 1 and then held: u_{n+1} = (P_{n+1} + c u_n/dt)/(k + c/dt).
"""
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import golden_lib as g  # noqa: E402

K_PAIR, C_PAIR = 1000.0, 50.0        # elements 1 (SPRINGA) and 2 (DASHPOTA)
TABLE = [(-1.0, -20.0), (0.0, 0.0), (0.2, 3.0), (0.5, 7.0)]  # element 3: (velocity, force)
C_TWO_DOFS = 20.0                    # element 4 (DASHPOT2)
K_CREEP, C_CREEP, LOAD = 100.0, 10.0, 5.0  # elements 5 (SPRINGA), 6 (DASHPOTA), node 7


def table_force(v):
    """Piecewise linear in v, constant beyond both ends."""
    if v <= TABLE[0][0]:
        return TABLE[0][1]
    if v >= TABLE[-1][0]:
        return TABLE[-1][1]
    k = 0
    while v > TABLE[k + 1][0]:
        k += 1
    (v0, f0), (v1, f1) = TABLE[k], TABLE[k + 1]
    return f0 + (f1 - f0) / (v1 - v0) * (v - v0)


# (step, increments, step period, driven displacement at the step's start and end, load ramped?)
STEPS = [(1, 4, 1.0, 0.0, 0.1, True), (2, 4, 0.5, 0.1, 0.3, False),
         (3, 4, 0.25, 0.3, 0.0, False)]

names = [f"S11@{e}" for e in range(1, 7)] + [f"E11@{e}" for e in range(1, 7)]
names += ["RF1@2", "RF2@3", "RF1@4", "RF1@5", "U1@2", "U2@3", "U1@4", "U1@7"]

rows = [(1, 0, 0.0, 0.0, [0.0] * len(names))]
total, creep = 0.0, 0.0
for step, count, period, start, end, ramped in STEPS:
    dt = period / count
    v = (end - start) / period
    for inc in range(1, count + 1):
        u = start + (end - start) * inc / count
        t = period * inc / count
        load = LOAD * t / period if ramped else LOAD
        creep = (load + C_CREEP * creep / dt) / (K_CREEP + C_CREEP / dt)
        s11 = [K_PAIR * u, C_PAIR * v, table_force(v), C_TWO_DOFS * v, K_CREEP * creep,
               load - K_CREEP * creep]
        e11 = [u, u, u, u, creep, creep]
        reactions = [s11[0] + s11[1], s11[2], s11[3], -s11[3]]
        values = s11 + e11 + reactions + [u, u, u, creep]
        rows.append((step, inc, t, total + t, values))
    total += period

assert abs(table_force(0.1) - 1.5) < 1e-15
assert abs(table_force(0.4) - (7.0 - 4.0 / 3.0 * 1.0)) < 1e-12  # inside the last segment
assert table_force(-1.2) == -20.0  # below the first point: the end value
# The dashpot of the creep pair carries what the spring does not: c (u_{n+1} − u_n)/dt.
first_u = (LOAD * 0.25 + 0.0) / (K_CREEP + C_CREEP / 0.25)
assert abs(first_u - 1.25 / 140.0) < 1e-15

g.write_golden(__file__, [
    "dashpots: SPRINGA k = 1000 with DASHPOTA c = 50, DASHPOT1 NONLINEAR table, DASHPOT2 c = 20,",
    "and a SPRINGA k = 100 / DASHPOTA c = 10 pair under a load of 5; closed form: v = dDelta/dt per",
    "increment, S11 = c v or table(v) (constant beyond the ends), E11 = Delta; the loaded pair by",
    "backward Euler of k u + c u' = P (behaviors.md §8, keywords.md §7)",
], names, rows)
