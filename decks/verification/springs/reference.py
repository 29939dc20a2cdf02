"""Golden values of springs (keywords.md §7)."""
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import golden_lib as g  # noqa: E402

C30 = 0.8660254037844387
ORI30 = g.orientation([C30, 0.5, 0.0], [-0.5, C30, 0.0])
K2 = [100.0, 200.0, 300.0]
P2 = [10.0, 20.0, 0.0]
N5 = [0.6, 0.8, 0.0]
U5 = [0.03, 0.01, 0.02]
TABLE = [(0.0, 0.0), (1.0, 10.0), (20.0, 100.0)]  # (delta, F)

names = ["S11@1", "E11@1"] + [f"{v}11@{e}" for e in (2, 3, 4) for v in ("S", "E")]
names += ["S11@5", "E11@5", "S11@6", "E11@6", "U1@1", "RF1@1"]
names += [f"{v}{i}@{n}" for n in (2, 3, 4, 5, 6, 7) for v in ("U", "RF") for i in (1, 2, 3)]
rows = []
for inc, t in enumerate([0.0, 0.25, 0.5, 0.75, 1.0]):
    # SPRING1: F = P (f_int = +F at the node), delta = u1.
    s1 = 10.0 * t
    e1 = s1 / 100.0
    # SPRING2 with ORI30, node 3 fixed: delta_i = e_i . u_2, f_int at node 2 = sum F_i e_i = P,
    # so F_i = e_i . P (orthonormal axes), delta_i = F_i / k_i.
    p2 = g.scale(t, P2)
    f2 = [g.dot(e, p2) for e in ORI30]
    d2 = [f / k for f, k in zip(f2, K2)]
    u2 = [0.0] * 3
    for di, e in zip(d2, ORI30):
        u2 = g.add(u2, g.scale(di, e))
    rf3 = g.scale(-1.0, p2)                    # node 3: -F_i e_i summed
    # SPRINGA linear, NLGEOM=NO: delta = n0 . (u5 - u4), F = k delta; node 5 gets +F n0.
    u5 = g.scale(t, U5)
    d5 = g.dot(N5, u5)
    f5 = 1000.0 * d5
    # SPRINGA nonlinear: delta = 3 t along its axis z, F from the table.
    d6 = 3.0 * t
    f6 = g.tabular(d6, TABLE)
    solved = inc > 0
    values = [s1, e1]
    for f, d in zip(f2, d2):
        values += [f, d]
    values += [f5, d5, f6, d6, e1, 0.0]
    values += u2 + [0.0] * 3                                    # node 2 free
    values += [0.0] * 3 + (rf3 if solved else [0.0] * 3)        # node 3 fixed
    values += [0.0] * 3 + (g.scale(-f5, N5) if solved else [0.0] * 3)
    values += u5 + (g.scale(f5, N5) if solved else [0.0] * 3)
    values += [0.0] * 3 + [0.0, 0.0, -f6 if solved else 0.0]
    values += [0.0, 0.0, d6] + [0.0, 0.0, f6 if solved else 0.0]
    rows.append((1, inc, t, t, values))
g.write_golden(__file__, [
    "springs: SPRING1 F = P = 10 t, delta = F/100; SPRING2 in ORI30 axes, F_i = e_i . P with",
    "P = (10, 20, 0) t, delta_i = F_i/k_i, k = (100, 200, 300); SPRINGA k = 1000, delta =",
    "n0 . u5 = 0.026 t, RF5 = F n0; nonlinear SPRINGA (F, delta) = (0,0) (10,1) (100,20),",
    "delta = 3 t: F = 7.5, 10 + 0.5 x 90/19, 10 + 1.25 x 90/19, 10 + 2 x 90/19 (keywords.md §7)",
], names, rows)
