"""Golden values of dynamic_pendulum: the exact motion of a simple pendulum released from rest at
theta0 = 90 degrees (L = 1, g = 9.81), from Jacobi's elliptic functions (Abramowitz and Stegun,
Handbook of Mathematical Functions, 16.4 and 17.6; the period 4 sqrt(L/g) K(k), k = sin(theta0/2)):

  sin(theta/2) = k sn(K - w0 t | k^2),   theta' = -2 k w0 cn(K - w0 t | k^2),   w0 = sqrt(g/L),

theta measured from the downward vertical. The bob is at (L sin theta, -L cos theta); U1, U2 are
its motion from (L, 0), V1, V2 its velocity. ALLKE = m |v|^2 / 2, ALLWK = m g (the height it has
fallen). Rows at the eighths of the period and at the step's end.
"""
import math
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import golden_lib as g  # noqa: E402

L, GRAV, MASS, THETA0, PERIOD_OF_STEP = 1.0, 9.81, 1.0, math.pi / 2, 2.5
W0 = math.sqrt(GRAV / L)
K_MODULUS = math.sin(THETA0 / 2)


def agm_sequence(m):
    """The arithmetic-geometric mean sequence of 1 and sqrt(1 - m) (A&S 17.6)."""
    a, b, c = [1.0], math.sqrt(1.0 - m), [math.sqrt(m)]
    while abs(c[-1]) > 1e-16:
        a_next, b_next = (a[-1] + b) / 2, math.sqrt(a[-1] * b)
        c.append((a[-1] - b) / 2)
        a.append(a_next)
        b = b_next
    return a, c


def complete_k(m):
    a, _ = agm_sequence(m)
    return math.pi / (2 * a[-1])


def ellipj(u, m):
    """sn, cn, dn by the descending Landen transformation (A&S 16.4)."""
    a, c = agm_sequence(m)
    n = len(a) - 1
    phi = 2 ** n * a[n] * u
    for i in range(n, 0, -1):
        phi = (phi + math.asin(c[i] / a[i] * math.sin(phi))) / 2
    sn, cn = math.sin(phi), math.cos(phi)
    return sn, cn, math.sqrt(1 - m * sn * sn)


M_PARAM = K_MODULUS ** 2
K = complete_k(M_PARAM)
PERIOD = 4 * K / W0


def state(t):
    sn, cn, _ = ellipj(K - W0 * t, M_PARAM)
    theta = 2 * math.asin(K_MODULUS * sn)
    rate = -2 * K_MODULUS * W0 * cn
    x, y = L * math.sin(theta), -L * math.cos(theta)
    vx, vy = L * math.cos(theta) * rate, L * math.sin(theta) * rate
    return x - L, y, vx, vy


# Self-checks of the formulas (not of clinch): K(1/2) = 1.854074677301372 (A&S table 17.1), and
# a fine fourth-order Runge-Kutta integration of theta'' = -(g/L) sin theta reaches the same
# state at t = 1.
g.assert_close([K], [1.854074677301372], 1e-14, "K(m = 1/2)")
theta, rate, h = THETA0, 0.0, 1e-4
for _ in range(10000):
    def f(th, om):
        return om, -W0 * W0 * math.sin(th)
    k1 = f(theta, rate)
    k2 = f(theta + h / 2 * k1[0], rate + h / 2 * k1[1])
    k3 = f(theta + h / 2 * k2[0], rate + h / 2 * k2[1])
    k4 = f(theta + h * k3[0], rate + h * k3[1])
    theta += h / 6 * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0])
    rate += h / 6 * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1])
exact = state(1.0)
g.assert_close([L * math.sin(theta) - L, -L * math.cos(theta)], exact[:2], 1e-10,
               "Runge-Kutta against the elliptic solution at t = 1")

names = ["U1@2", "U2@2", "V1@2", "V2@2", "ALLKE", "ALLWK"]
rows = []
times = [PERIOD * i / 8 for i in range(9)] + [PERIOD_OF_STEP]
for i, t in enumerate(times):
    u1, u2, v1, v2 = state(t)
    kinetic = MASS * (v1 * v1 + v2 * v2) / 2
    work = -MASS * GRAV * u2
    rows.append((1, i, t, t, [u1, u2, v1, v2, kinetic, work]))

if __name__ == "__main__":  # iftomm_simple_pendulum reuses state()
    g.write_golden(__file__, [
        "dynamic_pendulum: simple pendulum L = 1, g = 9.81, m = 1, released at rest from 90",
        f"degrees; exact motion from Jacobi's elliptic functions, period 4 K(k)/w0 = {PERIOD:.15g}",
        "(Abramowitz and Stegun 16.4, 17.6); rows at the eighths of the period and the step's end",
    ], names, rows)
