"""Golden values of amplitude_formulas (keywords.md §8, §13; Abaqus "Amplitude curves")."""
import math
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import golden_lib as g  # noqa: E402


def periodic(t, n_terms, omega, t0, a0, coefficients):
    """A0 + sum_n [A_n cos n w (t - t0) + B_n sin n w (t - t0)] for t >= t0, A0 before."""
    if t < t0:
        return a0
    a = a0
    for n in range(1, n_terms + 1):
        an, bn = coefficients[2 * n - 2], coefficients[2 * n - 1]
        a += an * math.cos(n * omega * (t - t0)) + bn * math.sin(n * omega * (t - t0))
    return a


def modulated(t, a0, a, t0, w1, w2):
    """A0 + A sin w1 (t - t0) sin w2 (t - t0) for t > t0, A0 until t0."""
    return a0 if t <= t0 else a0 + a * math.sin(w1 * (t - t0)) * math.sin(w2 * (t - t0))


def decay(t, a0, a, t0, td):
    """A0 + A exp(-(t - t0)/td) for t >= t0, A0 before."""
    return a0 if t < t0 else a0 + a * math.exp(-(t - t0) / td)


def wave(st):
    """WAVE with SCALEX = 2, SHIFTX = 0.1, SCALEY = 1.5, SHIFTY = -0.2: a time t of the deck's
    curve is the time (t - SHIFTX)/SCALEX of the formula, and its value is scaled then shifted."""
    f = periodic((st - 0.1) / 2.0, 2, math.pi, 0.17, 0.5, [1.0, 0.5, -0.25, 0.75])
    return 1.5 * f - 0.2


def beat(st):
    return modulated(st, 0.3, 1.2, 0.1, 2.0, 15.0)


def fade(tt):
    return decay(tt, 1.0, -1.0, 0.25, 0.4)  # TIME=TOTAL TIME


def drop(st):
    return decay(st, 0.0, 5.0, 0.45, 0.2)


times = [(1, i, 0.1 * i, 0.1 * i) for i in range(0, 11)]
times += [(2, i, 0.25 * i, 1.0 + 0.25 * i) for i in range(1, 5)]

names = [f"{v}1@{e}" for v in ("CU", "CTF", "CEF") for e in (1, 2, 3, 4)]
rows = []
for step, inc, st, tt in times:
    if inc == 0:
        rows.append((step, inc, st, tt, [0.0] * len(names)))
        continue
    load1 = 10.0 * wave(st)                          # redefined in step 2: step time restarts
    motion2 = 0.05 * beat(st if step == 1 else 1.0)  # held at its end-of-step-1 value
    pair3 = 20.0 * fade(tt)                          # total time: keeps following FADE
    load4 = drop(st if step == 1 else 1.0)           # VALUE=ABSOLUTE; held in step 2
    cu = [load1 / 100.0, motion2, pair3 / 400.0, load4 / 50.0]
    cef = [load1, 200.0 * motion2, pair3, load4]
    # The motion's multiplier cancels the elastic force of element 2 (node b is otherwise free);
    # the connector load is an applied pair, so CTF = CEF - CCF = 0 (output-variables.md §2).
    ctf = [load1, 0.0, 0.0, load4]
    rows.append((step, inc, st, tt, cu + ctf + cef))
g.write_golden(__file__, [
    "amplitude_formulas: four AXIAL springs, node b free along x. Step 1 (10 x 0.1), step 2",
    "(4 x 0.25). El. 1: CLOAD 10 x PERIODIC (N = 2, SCALEX/SHIFTX/SCALEY/SHIFTY), redefined in",
    "step 2; el. 2: motion 0.05 x MODULATED, held in step 2; el. 3: connector load 20 x DECAY",
    "in total time, followed in step 2; el. 4: CLOAD with an ABSOLUTE DECAY amplitude, held",
    "(keywords.md §8, §13)",
], names, rows)
