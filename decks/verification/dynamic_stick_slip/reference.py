"""Golden values of dynamic_stick_slip: a mass m on a spring k and a Coulomb slider in parallel,
the slider's stick spring K_s in series with a slip limit F (friction.md §4: the friction force
is f = K_s (u - s), |f| <= F, the slip s moving only when |f| = F), released at u = 0 with v0.

The golden rows are this discrete model integrated by HHT-alpha with the defaults of
APPLICATION=TRANSIENT FIDELITY on the deck's increments (docs/dynamics.md; Hilber, Hughes and
Taylor 1977), written out here from the operator's definition:

  m a1 + (1 + alpha)(k u1 + f1) - alpha (k u0 + f0) = 0,
  u1 = u0 + dt v0 + dt^2 ((1/2 - beta) a0 + beta a1),  v1 = v0 + dt ((1 - gamma) a0 + gamma a1),

with f1 the backward-Euler return of the slider at u1 from the slip s0 of the increment's start
(friction.md §4.1: stick if |K_s (u1 - s0)| <= F(0), else f1 = +-F(dl/dt), dl the slip of the
increment; the Coulomb slider's F is constant). Each increment has one solution, found here by
trying stick and then slip in the trial's direction, solved for dl by bisection (for a constant
F the slip branch is linear and the bisection ends on its closed-form root to round-off).

The recurrence is checked against the exact motion of the same model, which reference.py also
computes event by event: each phase is a harmonic motion in closed form (stick: stiffness
k + K_s about K_s s/(k + K_s); slip: stiffness k about -sign(f) F/k), a stick phase ends when
|f| reaches F moving outward, a slip phase when the velocity vanishes.
"""
import math
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import golden_lib as g  # noqa: E402

M, K, K_STICK, F_INTERNAL = 1.0, 100.0, 1.0e4, 100.0
F_SLIP = 0.1 * F_INTERNAL  # the Coulomb slider: mu = 0.1
V0 = 10.0
DT, PERIOD = 0.005, 2.0
ALPHA = -0.05  # APPLICATION=TRANSIENT FIDELITY
BETA, GAMMA = (1.0 - ALPHA) ** 2 / 4.0, 0.5 - ALPHA


def coulomb(rate):
    """The slip force of the Coulomb slider: mu F_int, whatever the rate."""
    return F_SLIP


def hht_increment(state, dt, law=coulomb, alpha=ALPHA, beta=BETA, gamma=GAMMA):
    """One increment from state (u, v, a, f, s, slip accumulated)."""
    u0, v0, a0, f0, s0, gamma_slip = state
    big_a = 1.0 / (beta * dt * dt)  # a1 = big_a u1 + big_b
    big_b = -(u0 + dt * v0) * big_a - (0.5 / beta - 1.0) * a0
    known = -M * big_b + alpha * (K * u0 + f0)
    # Stick: f1 = K_s (u1 - s0), kept if within the slip force at rest (friction.md §4.1).
    u1 = (known + (1.0 + alpha) * K_STICK * s0) / (M * big_a + (1.0 + alpha) * (K + K_STICK))
    s1 = s0
    trial = K_STICK * (u1 - s0)
    if abs(trial) > law(0.0) * (1.0 + 1e-12):
        # Slip in the trial's direction by dl at the rate dl/dt: f1 = sign F(dl/dt) and
        # u1 = s0 + sign (dl + F/K_s); the equation of motion is then one equation in dl, whose
        # left side grows with dl (m big_a dominates), solved by bisection to round-off.
        sign = math.copysign(1.0, trial)

        def position(dl):
            return s0 + sign * (dl + law(dl / dt) / K_STICK)

        def residual(dl):
            return sign * ((M * big_a + (1.0 + alpha) * K) * position(dl)
                           + (1.0 + alpha) * sign * law(dl / dt) - known)

        low, high = 0.0, 1e-6
        while residual(high) < 0.0:
            high *= 2.0
        for _ in range(200):
            middle = 0.5 * (low + high)
            if residual(middle) < 0.0:
                low = middle
            else:
                high = middle
        dl = 0.5 * (low + high)
        u1, s1 = position(dl), s0 + sign * dl
    f1 = K_STICK * (u1 - s1)
    a1 = big_a * u1 + big_b
    v1 = v0 + dt * ((1.0 - gamma) * a0 + gamma * a1)
    return (u1, v1, a1, f1, s1, gamma_slip + abs(s1 - s0))


def recurrence(dt, period, law=coulomb):
    state = (0.0, V0, 0.0, 0.0, 0.0, 0.0)  # INITIAL=YES: a0 = -(k u0 + f0)/m = 0
    rows = [state]
    for _ in range(round(period / dt)):
        state = hht_increment(state, dt, law)
        rows.append(state)
    return rows


# The exact motion, event by event.

def harmonic(x, v, centre, omega, t):
    c, s = math.cos(omega * t), math.sin(omega * t)
    return centre + (x - centre) * c + v / omega * s, -(x - centre) * omega * s + v * c


def first_time(angles, omega, after=1e-12):
    """The smallest t > after with omega t = angle + 2 pi n for one of the angles."""
    best = math.inf
    for angle in angles:
        t = (angle % (2.0 * math.pi)) / omega
        while t <= after:
            t += 2.0 * math.pi / omega
        best = min(best, t)
    return best


def phases(period):
    """[(t_start, x, v, s, slip sign or 0 for stick, slip accumulated)] up to the period."""
    t, x, v, s, sign, slipped = 0.0, 0.0, V0, 0.0, 0.0, 0.0
    out = []
    while t < period:
        out.append((t, x, v, s, sign, slipped))
        if sign == 0.0:  # stick until |K_s (x - s)| = F moving outward
            omega = math.sqrt((K + K_STICK) / M)
            centre = K_STICK * s / (K + K_STICK)
            radius = math.hypot(x - centre, v / omega)
            phase = math.atan2(v / omega, x - centre)  # x - centre = radius cos(omega t - phase)
            angles = []
            for edge in (1.0, -1.0):
                ratio = (s + edge * F_SLIP / K_STICK - centre) / radius
                # A crossing, outward: sin(omega t - phase) has the sign of -edge. An orbit that
                # only touches the edge (one that stuck there at rest) stays in stick: the stick
                # test keeps |f| = F with no outward motion.
                if abs(ratio) < 1.0 - 1e-9:
                    angles.append(phase - edge * math.acos(ratio))
            if not angles:
                break  # stuck for good
            duration = first_time(angles, omega)
            x, v = harmonic(x, v, centre, omega, duration)
            sign = math.copysign(1.0, K_STICK * (x - s))
        else:  # slip until the velocity vanishes
            omega = math.sqrt(K / M)
            centre = -sign * F_SLIP / K
            phase = math.atan2(v / omega, x - centre)
            duration = first_time([phase, phase + math.pi], omega)
            x_end, v = harmonic(x, v, centre, omega, duration)
            slipped += abs(x_end - x)
            s += x_end - x
            x, v, sign = x_end, 0.0, 0.0
        t += duration
    return out


def exact(events, t):
    """(u, v, f, slip accumulated) at time t."""
    start = max(e for e in events if e[0] <= t)
    t0, x, v, s, sign, slipped = start
    if sign == 0.0:
        centre, omega = K_STICK * s / (K + K_STICK), math.sqrt((K + K_STICK) / M)
        x1, v1 = harmonic(x, v, centre, omega, t - t0)
        return x1, v1, K_STICK * (x1 - s), slipped
    centre, omega = -sign * F_SLIP / K, math.sqrt(K / M)
    x1, v1 = harmonic(x, v, centre, omega, t - t0)
    return x1, v1, sign * F_SLIP, slipped + abs(x1 - x)


# The recurrence is shared with dynamic_stick_slip_rate, which imports this module.
if __name__ == "__main__":
    events = phases(PERIOD)
    # The recurrence converges to the exact motion: with an increment 50 times smaller every slip
    # and stick phase of the 2 s is followed to 2e-6 in u (amplitude 1), 1e-4 in v (amplitude 10),
    # 3e-3 in f (slip force 10) and 5e-6 in the slip, about 3 times the differences measured
    # (6.6e-7, 2.3e-5, 8.7e-4, 1.5e-6; the fast stick oscillation, 100 rad/s, sets the f and v
    # figures). On the deck's increments they are 3.3e-3, 3.6e-2, 3.7 and 2.8e-2: the operator's
    # discretisation error, of second order (5.3e-4 in u with an increment 5 times smaller).
    fine_dt = DT / 50
    for i, state in enumerate(recurrence(fine_dt, PERIOD)):
        t = i * fine_dt
        u, v, f, slipped = exact(events, t)
        for name, value, reference, tol in (("u", state[0], u, 2e-6),
                                            ("v", state[1], v, 1e-4),
                                            ("f", state[3], f, 3e-3),
                                            ("slip", state[5], slipped, 5e-6)):
            g.assert_close([value], [reference], tol, f"fine recurrence {name} at t = {t}")

    rows = []
    for inc, (u, v, a, f, _, slipped) in enumerate(recurrence(DT, PERIOD)):
        rows.append((1, inc, inc * DT, inc * DT, [f, slipped, u, v, a]))
    g.write_golden(__file__, [
        "dynamic_stick_slip: m = 1, spring k = 100 in parallel with a Coulomb slider (slip",
        "force 10, stick stiffness 1e4), released at u = 0 with v = 10; HHT-alpha (TRANSIENT",
        "FIDELITY) on the deck's increments, each increment solved branch by branch",
    ], ["CSF1@1", "CASU1@1", "U1@2", "V1@2", "A1@2"], rows)
