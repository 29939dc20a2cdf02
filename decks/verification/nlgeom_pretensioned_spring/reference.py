"""Golden values of nlgeom_pretensioned_spring (connection-types.md §3.7; behaviors.md §3)."""
import math
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import golden_lib as g  # noqa: E402

K, L0, REF, P = 1000.0, 1.0, 0.9, 30.0


def lateral(load):
    """Node 2 at (1, y): L = sqrt(1 + y^2), f = k (L - ref); equilibrium in y: f y / L = load.
    h(y) = f y / L - load is increasing in y (f > 0), so bisection on [0, 1] converges to the
    unique root; 200 halvings reach the last bit."""
    if load == 0.0:
        return 0.0
    lo, hi = 0.0, 1.0
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        length = math.hypot(1.0, mid)
        if K * (length - REF) * mid / length < load:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


names = ["CTF1@1", "CU1@1", "CCU1@1", "CP1@1", "U2@2", "RF1@2", "RF1@1", "RF2@1", "RF3@1"]
rows = []
for inc, t in enumerate([0.0, 0.25, 0.5, 0.75, 1.0]):
    y = lateral(P * t)
    length = math.hypot(1.0, y)
    f = K * (length - REF)
    # Second route: the residual in y vanishes to round-off.
    if abs(f * y / length - P * t) > 1e-11:
        raise SystemExit("lateral equilibrium not reached")
    q = [1.0 / length, y / length, 0.0]
    # RF = internal force (f q on node 2, -f q on node 1); row 0: nothing solved, RF = 0.
    rf2x = f * q[0] if inc else 0.0
    rf1 = g.scale(-f, q) if inc else [0.0] * 3
    rows.append((1, inc, t, t, [f, length - L0, length - REF, length, y, rf2x] + rf1))
g.write_golden(__file__, [
    "nlgeom_pretensioned_spring: AXIAL k = 1000, l0 = 1, ref = 0.9 (preload 100), node 2 held in",
    "x, lateral load 30 t: y from f y / L = P with L = sqrt(1 + y^2), f = k (L - 0.9), solved by",
    "bisection to the last bit; CTF1 = f, CU1 = L - 1, CCU1 = L - 0.9, RF1@2 = f / L, RF@1 = -f q",
    "(connection-types.md §3.7; behaviors.md §3)",
], names, rows)
