"""Golden values of stop_close_open (behaviors.md §5.1, E4, mirrored for the lower stop)."""
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import golden_lib as g  # noqa: E402

K, L0, GAP = 1000.0, 10.0, 0.1  # stops at 10.1 (upper, element 1) and 9.9 (lower, element 2)


def state(load):
    """Force-controlled spring against a stop: free while |load|/k <= GAP, else at the stop
    with the multiplier carrying the rest (CTF = CEF + CRF = load)."""
    s = 1.0 if load >= 0.0 else -1.0
    if abs(load) / K <= GAP:
        c, status = load / K, 0
    else:
        c, status = s * GAP, (2 if s > 0 else 1)
    cef = K * c
    return c, cef, load - cef, status


# (step, increment, step time, total time, load on element 1); element 2 gets -load.
# Step 1 ramps 0 -> 300 in 4 increments; step 2 ramps 300 -> 50 in 2 (keywords.md §13).
times = [(1, 0, 0.0, 0.0)] + [(1, i, 0.25 * i, 0.25 * i) for i in (1, 2, 3, 4)]
times += [(2, i, 0.5 * i, 1.0 + 0.5 * i) for i in (1, 2)]
names = []
for el in (1, 2):
    names += [f"{v}1@{el}" for v in ("CU", "CP", "CEF", "CRF", "CTF", "CSLST")]
names += ["U1@2", "U1@4", "RF1@1", "RF1@3"]
rows = []
for step, inc, st, tt in times:
    load = 300.0 * st if step == 1 else 300.0 + (50.0 - 300.0) * st
    values, cs, ctfs = [], [], []
    for p in (load, -load):
        c, cef, crf, status = state(p)
        values += [c, L0 + c, cef, crf, cef + crf, status]
        cs.append(c)
        ctfs.append(cef + crf)
    # Node a reaction: -CTF (the connector pulls node a toward b).
    values += cs + [-ctfs[0], -ctfs[1]]
    rows.append((step, inc, st, tt, values))
g.write_golden(__file__, [
    "stop_close_open: AXIAL k = 1000, l0 = 10; element 1 upper stop 10.1 under +load,",
    "element 2 lower stop 9.9 under -load; load 0 -> 300 (step 1, 4 incr.), 300 -> 50 (step 2,",
    "2 incr.). Free: CU1 = load/k; at the stop: CU1 = +-0.1, CRF1 = load - k CU1, CSLST1 = 2 / 1",
    "(behaviors.md §5.1, E4; output-variables.md §2 for CSLST)",
], names, rows)
