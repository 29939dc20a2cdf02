"""Golden values of dynamic_energy_balance: a two-mass chain M a + C v + K u = P integrated by the
trapezoidal rule (HHT with alpha = 0: beta = 1/4, gamma = 1/2), written out from its definition,
and its energies: ALLKE = v.M v / 2, ALLIE = u.K u / 2 (the spring work), ALLVD the trapezoidal
work of the dashpot force c v over its stretch, ALLWK the trapezoidal work of the load (the held
node does not move), ETOTAL = ALLKE + ALLIE + ALLVD - ALLWK (docs/dynamics.md "Energies").

For this operator the balance is exact: the kinetic energy changes by (v0 + v1)/2 . M (v1 - v0),
which the equation of motion at both ends and dt (v0 + v1)/2 = u1 - u0 turn into the trapezoidal
work of the loads less that of the spring and dashpot forces. ETOTAL therefore stays at its
initial value, the kinetic energy of the initial velocity (asserted below to round-off).
"""
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import golden_lib as g  # noqa: E402

DT, PERIOD = 0.01, 1.0
MASS = [1.0, 2.0]
K1, K2, C = 100.0, 50.0, 0.5
STIFFNESS = [[K1 + K2, -K2], [-K2, K2]]
DAMPING = [[C, 0.0], [0.0, 0.0]]
LOAD = [0.0, 10.0]  # at once from the step's start (a *DYNAMIC step's default)
BETA, GAMMA = 0.25, 0.5


def matvec(a, v):
    return [sum(a[i][j] * v[j] for j in range(2)) for i in range(2)]


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


u, v = [0.0, 0.0], [0.0, 1.0]
# INITIAL=YES: a0 from the equation of motion at the start, under the load of the step.
a = [(LOAD[i] - matvec(DAMPING, v)[i] - matvec(STIFFNESS, u)[i]) / MASS[i] for i in range(2)]
kinetic0 = 0.5 * dot(v, [MASS[i] * v[i] for i in range(2)])
viscous, work = 0.0, 0.0
names = ["U1@2", "U1@3", "V1@2", "V1@3", "ALLKE", "ALLIE", "ALLVD", "ALLWK", "ETOTAL"]
rows = [(1, 0, 0.0, 0.0, [0.0, 0.0, 0.0, 1.0, kinetic0, 0.0, 0.0, 0.0, kinetic0])]
count = round(PERIOD / DT)
for inc in range(1, count + 1):
    # u1 from (M/(beta dt^2) + C gamma/(beta dt) + K) u1 = P + M (...) + C (...).
    c0, c1 = 1.0 / (BETA * DT * DT), GAMMA / (BETA * DT)
    lhs = [[(MASS[i] * c0 if i == j else 0.0) + DAMPING[i][j] * c1 + STIFFNESS[i][j]
            for j in range(2)] for i in range(2)]
    inertia = [MASS[i] * (c0 * u[i] + v[i] / (BETA * DT) + (0.5 / BETA - 1.0) * a[i])
               for i in range(2)]
    damping_rhs = matvec(DAMPING, [c1 * u[i] + (GAMMA / BETA - 1.0) * v[i]
                                   + DT * (GAMMA / (2 * BETA) - 1.0) * a[i] for i in range(2)])
    u1 = g.solve(lhs, [LOAD[i] + inertia[i] + damping_rhs[i] for i in range(2)])
    a1 = [c0 * (u1[i] - u[i]) - v[i] / (BETA * DT) - (0.5 / BETA - 1.0) * a[i] for i in range(2)]
    v1 = [v[i] + DT * ((1 - GAMMA) * a[i] + GAMMA * a1[i]) for i in range(2)]
    # The dashpot (nodes 1-2) stretches by du of node 2 at the force c v of node 2.
    viscous += 0.5 * C * (v[0] + v1[0]) * (u1[0] - u[0])
    work += 0.5 * dot([2 * x for x in LOAD], [u1[i] - u[i] for i in range(2)])
    u, v, a = u1, v1, a1
    kinetic = 0.5 * dot(v, [MASS[i] * v[i] for i in range(2)])
    internal = 0.5 * dot(u, matvec(STIFFNESS, u))
    total = kinetic + internal + viscous - work
    g.assert_close([total], [kinetic0], 1e-10, f"the trapezoidal balance at increment {inc}")
    rows.append((1, inc, DT * inc, DT * inc,
                 [u[0], u[1], v[0], v[1], kinetic, internal, viscous, work, total]))

g.write_golden(__file__, [
    "dynamic_energy_balance: masses 1 and 2 on springs 100 and 50, dashpot 0.5, v0 = 1 on the",
    "outer mass and a load of 10 at once; the trapezoidal rule written out (docs/dynamics.md),",
    "energies from their definitions; ETOTAL stays at the initial kinetic energy 1",
], names, rows)
