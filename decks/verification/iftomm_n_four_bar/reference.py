"""Golden values of iftomm_n_four_bar: the IFToMM multibody benchmark A02 (N-four-bar mechanism)
with N = 2 windows: N + 1 cranks pivoted at A_i = (i, 0) and N couplers between their tips B_i,
uniform bars of length L = 1 and mass m = 1, gravity g = 9.81 along -y. At t = 0 the windows are
square (cranks vertical) and B0 moves along +x at 1 m/s.

The windows stay parallelograms: every crank turns by the same angle phi (from +x; B_i = A_i +
L (cos phi, sin phi)) and the couplers translate with the crank tips. The kinetic energy is
((N + 1) m L^2 / 3 + N m L^2) phi'^2 / 2 and the potential energy ((N + 1) / 2 + N) m g L sin phi,
so that the exact equation of motion (Lagrange) is

  ((N + 1) / 3 + N) L phi'' = -((N + 1) / 2 + N) g cos phi,   phi(0) = pi / 2,  phi'(0) = -1,

integrated here by the classical fourth-order Runge-Kutta method with h = 1e-4 (checked against
h = 2e-4 and against the energy integral below). At the horizontal positions (phi = 0, pi) the
mechanism is singular (N + 1 degrees of freedom for an instant); the parallelogram branch is the
one the motion keeps, as in the benchmark's reference. U1, U2, V1, V2 are those of B0 from its
initial position (0, 1). Rows every 0.1 s over 3 s.
"""
import math
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import golden_lib as g  # noqa: E402

N, L, MASS, GRAV = 2, 1.0, 1.0, 9.81
PHI0, RATE0 = math.pi / 2, -1.0
TIMES = [0.1 * i for i in range(1, 31)]


def inertia(n):
    return ((n + 1) / 3 + n) * MASS * L * L


def weight(n):
    return ((n + 1) / 2 + n) * MASS * GRAV * L


def integrate(times, h, n=N):
    """(phi, phi') at each of `times` for the mechanism of n windows."""
    return g.integrate_second_order(lambda phi: -weight(n) * math.cos(phi) / inertia(n),
                                    PHI0, RATE0, times, h)


def energy(phi, rate, n=N):
    return 0.5 * inertia(n) * rate * rate + weight(n) * math.sin(phi)


def b0_motion(phi, rate):
    """U1, U2, V1, V2 of B0 from its initial position (0, L)."""
    return [L * math.cos(phi), L * math.sin(phi) - L,
            -L * math.sin(phi) * rate, L * math.cos(phi) * rate]


if __name__ == "__main__":  # scripts/iftomm_full_horizon.py reuses integrate() and b0_motion()
    states = integrate(TIMES, 1e-4)
    # Self-checks of the integration (not of clinch): step halving and the energy integral.
    coarse = integrate(TIMES, 2e-4)
    g.assert_close([s[0] for s in coarse], [s[0] for s in states], 1e-9,
                   "RK4 h = 2e-4 against 1e-4")
    g.assert_close([energy(*s) for s in states], [energy(PHI0, RATE0)] * len(states), 1e-10,
                   "energy integral")

    rows = [(1, 0, 0.0, 0.0, [0.0, 0.0, -L * RATE0, 0.0])]
    for i, (t, (phi, rate)) in enumerate(zip(TIMES, states), start=1):
        rows.append((1, i, t, t, b0_motion(phi, rate)))

    g.write_golden(__file__, [
        "iftomm_n_four_bar: IFToMM benchmark A02, N-four-bar mechanism with N = 2 (bars of 1 m,",
        "1 kg), square windows at t = 0, B0 at 1 m/s along +x, g = 9.81; exact equation of motion of",
        "the parallelogram branch integrated by RK4, h = 1e-4; rows every 0.1 s over 3 s",
    ], ["U1@3", "U2@3", "V1@3", "V2@3"], rows)
