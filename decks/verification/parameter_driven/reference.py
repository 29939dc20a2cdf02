"""Golden values of parameter_driven (input-syntax.md §6; behaviors.md §4; connection-types.md §3.4).

The *PARAMETER block is evaluated here with the same Python expressions, in the same order,
so the parameter values are the same doubles as in the deck (input-syntax.md §6.3, §6.4).
"""
import math
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import golden_lib as g  # noqa: E402

L = 2.5
k = 4.0e3
P = 0.5 * k * 0.01
theta = 40.0
ct = math.cos(math.radians(theta))
st = math.sin(math.radians(theta))
mst = -st
Q = 30.0
Qx = Q * ct
Qy = Q * st
u1 = 0.02
f1 = k * u1
f2 = 1.5 * f1
u2 = 2 * u1
U3 = 0.03

frame = g.orientation([ct, st, 0.0], [mst, ct, 0.0])
d0 = [L, 0.0, 0.0]
table = [(0.0, 0.0), (u1, f1), (u2, f2)]


def nonlinear(u):
    """Piecewise linear, LINEAR extrapolation past the last point (behaviors.md §1.2)."""
    if u > u2:
        return f1 + (f2 - f1) * (u - u1) / (u2 - u1)
    return g.tabular(u, table)


names = ["CTF1@1", "CU1@1", "CP1@1"]
names += [f"CTF{i}@2" for i in (1, 2, 3)] + [f"CU{i}@2" for i in (1, 2, 3)]
names += [f"CP{i}@2" for i in (1, 2, 3)]
names += ["CTF1@3", "CU1@3", "CP1@3"]
names += [f"U{i}@{n}" for n in (2, 4, 6) for i in (1, 2, 3)]
rows = []
for inc, t in enumerate([0.0, 0.5, 1.0]):
    c1 = t * P / k
    load2 = [t * Qx, t * Qy, 0.0]
    f = [g.dot(e, load2) for e in frame]          # node a fixed: f_i = e_i . F
    c2 = [fi / k for fi in f]
    p2 = [g.dot(e, d0) + ci for e, ci in zip(frame, c2)]  # CP = e_i . d0 + CU (NLGEOM=NO)
    u4 = [0.0] * 3
    for ci, e in zip(c2, frame):
        u4 = g.add(u4, g.scale(ci, e))
    c3 = t * U3
    values = [t * P, c1, L + c1] + f + c2 + p2 + [nonlinear(c3), c3, L + c3]
    values += [c1, 0.0, 0.0] + u4 + [c3, 0.0, 0.0]
    rows.append((1, inc, t, t, values))
g.write_golden(__file__, [
    "parameter_driven: L = 2.5, k = 4000, P = 0.5 k 0.01 = 20, theta = 40 deg, Q = 30;",
    "AXIAL CU1 = P/k, CP1 = L + CU1; CARTESIAN in ORIT (e1 = (cos40, sin40, 0)) under Q e1:",
    "CTF = e . F, CU = CTF/k, CP = e . d0 + CU; nonlinear AXIAL table (0,0) (0.02,80) (0.04,120),",
    "LINEAR extrapolation, driven to 0.03: CTF1 = 60 at t = 0.5, 100 at t = 1",
], names, rows)
