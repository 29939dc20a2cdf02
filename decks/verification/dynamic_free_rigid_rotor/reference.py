"""Golden values of dynamic_free_rigid_rotor (docs/dynamics.md "Finite rotations").

A torque-free rigid body: J W' + W x J W = 0 in the body's axes, R' = R hat(W), with J the
ROTARYI tensor of the deck (global axes of the reference configuration, R(0) = I) and
W(0) = omega(0), the initial angular velocity. Integrated with classical Runge-Kutta at a step of
1e-4 (a local error ~1e-20, far below the tolerance); the golden values are the spatial angular
velocity omega = R W at the output times, and the script asserts that the reference itself keeps
the spatial angular momentum R J W and the kinetic energy W.JW/2 to 1e-12."""
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import golden_lib as g  # noqa: E402

J = [[2.0, 0.1, -0.2], [0.1, 3.0, 0.15], [-0.2, 0.15, 4.0]]
OMEGA0 = [1.0, 0.3, 0.8]
T_END, OUTPUT_EVERY, H = 4.0, 0.5, 1e-4


def rates(state):
    r = [state[0:3], state[3:6], state[6:9]]
    w = state[9:12]
    jw = g.matvec(J, w)
    dw = g.solve(J, g.scale(-1.0, g.cross(w, jw)))
    dr = g.matmul(r, g.skew(w))
    return dr[0] + dr[1] + dr[2] + dw


def rk4(state, h):
    k1 = rates(state)
    k2 = rates([s + 0.5 * h * k for s, k in zip(state, k1)])
    k3 = rates([s + 0.5 * h * k for s, k in zip(state, k2)])
    k4 = rates([s + h * k for s, k in zip(state, k3)])
    return [s + h / 6.0 * (a + 2 * b + 2 * c + d) for s, a, b, c, d in zip(state, k1, k2, k3, k4)]


def invariants(state):
    r = [state[0:3], state[3:6], state[6:9]]
    w = state[9:12]
    return g.matvec(r, g.matvec(J, w)), 0.5 * g.dot(w, g.matvec(J, w))


state = [1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0] + OMEGA0
pi0, energy0 = invariants(state)
names = ["VR1@1", "VR2@1", "VR3@1"]
rows = [(1, 0, 0.0, 0.0, OMEGA0)]
steps_per_output = round(OUTPUT_EVERY / H)
for k in range(1, round(T_END / OUTPUT_EVERY) + 1):
    for _ in range(steps_per_output):
        state = rk4(state, H)
    pi, energy = invariants(state)
    g.assert_close(pi, pi0, 1e-12, "angular momentum of the reference")
    g.assert_close([energy], [energy0], 1e-12, "kinetic energy of the reference")
    r = [state[0:3], state[3:6], state[6:9]]
    t = k * OUTPUT_EVERY
    rows.append((1, round(t / 0.01), t, t, g.matvec(r, state[9:12])))

g.write_golden(__file__, [
    "dynamic_free_rigid_rotor: J = [[2, .1, -.2], [.1, 3, .15], [-.2, .15, 4]], omega(0) =",
    "(1, .3, .8), no moment: Euler's equations J W' + W x J W = 0 with R' = R hat(W), RK4 at",
    "h = 1e-4; VR = R W (docs/dynamics.md \"Finite rotations\")",
], names, rows)
