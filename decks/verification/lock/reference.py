"""Golden values of lock (behaviors.md §5.2, E5, plus a force-bound lock)."""
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import golden_lib as g  # noqa: E402

K, L0 = 1000.0, 10.0
times = [(1, 0, 0.0, 0.0)] + [(1, i, 0.25 * i, 0.25 * i) for i in (1, 2, 3, 4)] + [(2, 1, 1.0, 2.0)]


def history(criterion):
    """Walk the converged increments: free until the criterion holds on a converged state,
    then frozen at that position for good (behaviors.md §5.2). The row of the increment that
    meets the criterion is still the unlocked state."""
    out, locked_at = [], None
    for step, inc, st, tt in times:
        load = 200.0 * st if step == 1 else 0.0
        if locked_at is None:
            c = load / K
            cef, crf, status = K * c, 0.0, 0
        else:
            c = locked_at
            cef = K * c
            crf, status = load - cef, 3
        out.append((c, cef, crf, cef + crf, status))
        if locked_at is None and criterion(L0 + c, cef + crf):
            locked_at = c
    return out


el1 = history(lambda p, f: p >= 10.04)
el2 = history(lambda p, f: f >= 120.0)
names = [f"{v}1@{e}" for e in (1, 2) for v in ("CU", "CEF", "CRF", "CTF", "CSLST")]
names += ["U1@2", "U1@4", "RF1@1", "RF1@3"]
rows = []
for (step, inc, st, tt), a, b in zip(times, el1, el2):
    rows.append((step, inc, st, tt, list(a) + list(b) + [a[0], b[0], -a[3], -b[3]]))
g.write_golden(__file__, [
    "lock: AXIAL k = 1000, l0 = 10, load 0 -> 200 in 4 increments, then 0 in one increment.",
    "Element 1 locks when p >= 10.04 (at t = 0.25, CU1 = 0.05); element 2 when CTF1 >= 120",
    "(at t = 0.75, CU1 = 0.15). Once locked CU1 is frozen, CRF1 = load - k CU1, CSLST1 = 3",
    "(behaviors.md §5.2, E5)",
], names, rows)
