"""Golden values of axial_linear: a linear AXIAL spring, NLGEOM=NO (behaviors.md §4.5 E1)."""
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import golden_lib as g  # noqa: E402

K = 1000.0
# Element 1: l0 = 10 along x; U1@2 = 0.2 t.
# Element 2: n0 = (0.6, 0.8, 0), l0 = 5; u4 = (0.06, 0.02, 0.01) t. Small displacement:
# CU1 = n0 . u4 (connection-types.md §3.4), so CU1 = (0.036 + 0.016) t = 0.052 t.
N0 = [0.6, 0.8, 0.0]
U4 = [0.06, 0.02, 0.01]

names = ["CU1@1", "CU1@2", "CP1@1", "CP1@2", "CTF1@1", "CTF1@2", "CEF1@1", "CEF1@2"]
for node in (1, 2, 3, 4):
    names += [f"RF{i}@{node}" for i in (1, 2, 3)]
names += ["U1@2", "U1@4", "U2@4", "U3@4"]

rows = []
for inc, t in enumerate([0.0, 0.25, 0.5, 0.75, 1.0]):
    c1 = 0.2 * t
    u4 = g.scale(t, U4)
    c2 = g.dot(N0, u4)
    f1, f2 = K * c1, K * c2
    # RF = internal force - applied load; the internal force of the connector on node b is
    # +f n and on node a is -f n (connection-types.md §4). Row 0: nothing solved, RF = 0.
    rf = {1: [-f1, 0.0, 0.0], 2: [f1, 0.0, 0.0], 3: g.scale(-f2, N0), 4: g.scale(f2, N0)}
    if inc == 0:
        rf = {n: [0.0, 0.0, 0.0] for n in rf}
    values = [c1, c2, 10.0 + c1, 5.0 + c2, f1, f2, f1, f2]
    for node in (1, 2, 3, 4):
        values += rf[node]
    values += [c1] + u4
    rows.append((1, inc, t, t, values))

g.write_golden(__file__, [
    "axial_linear: AXIAL, k = 1000, NLGEOM=NO, displacement driven",
    "closed form: CU1 = n0.(u_b - u_a), CTF1 = CEF1 = k CU1, CP1 = l0 + CU1,",
    "RF(b) = +CTF1 n0, RF(a) = -CTF1 n0 (behaviors.md §4.5 E1; connection-types.md §3.4, §4)",
], names, rows)
