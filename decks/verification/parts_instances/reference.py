"""Golden values of parts_instances (input-syntax.md §7.2, §7.3; connection-types.md §3.4)."""
import math
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import golden_lib as g  # noqa: E402

C30 = 0.8660254037844387
PART_FRAME = g.orientation([C30, 0.5, 0.0], [-0.5, C30, 0.0])
PART_NODES = {1: [0.0, 0.0, 0.0], 2: [1.0, 0.0, 0.0]}
K = [1000.0, 2000.0, 4000.0]
F = [10.0, 20.0, 30.0]
# instance: (translation t, axis point a, axis point b, angle in degrees)
INSTANCES = {
    "Bracket-1": ([0.0, 0.0, 2.0], None, None, 0.0),
    "Bracket-2": ([5.0, 0.0, 0.0], [5.0, 0.0, 0.0], [5.0, 0.0, 1.0], 90.0),
}


def place(t, a, b, angle):
    """x' = a + R (x + t - a); orientations inside the part are rotated by R (§7.2)."""
    if a is None:
        rot = g.expm([0.0, 0.0, 0.0])
        a = [0.0, 0.0, 0.0]
    else:
        rot = g.expm(g.scale(math.radians(angle), g.unit(g.sub(b, a))))
    nodes = {n: g.add(a, g.matvec(rot, g.sub(g.add(x, t), a))) for n, x in PART_NODES.items()}
    frame = [g.matvec(rot, e) for e in PART_FRAME]
    return nodes, frame


names, v = [], []
for inst, spec in INSTANCES.items():
    nodes, frame = place(*spec)
    d0 = g.sub(nodes[2], nodes[1])
    if inst == "Bracket-2":  # second route: the 90 degree turn maps x to y
        g.assert_close(nodes[2], [5.0, 1.0, 0.0], 1e-15, "Bracket-2 node 2")
        g.assert_close(frame[0], [-0.5, C30, 0.0], 1e-15, "Bracket-2 e1")
    f = [g.dot(e, F) for e in frame]
    c = [fi / k for fi, k in zip(f, K)]
    ub, rm = [0.0] * 3, [0.0] * 3
    for ci, fi, e in zip(c, f, frame):
        ub = g.add(ub, g.scale(ci, e))
        rm = g.add(rm, g.scale(fi, g.cross(e, d0)))
    g.assert_close(rm, g.cross(F, d0), 1e-12, "moment balance")
    names += [f"CTF{i}@{inst}.1" for i in (1, 2, 3)] + [f"CU{i}@{inst}.1" for i in (1, 2, 3)]
    v += f + c
    names += [f"U{i}@{inst}.2" for i in (1, 2, 3)]
    v += ub
    names += [f"RF{i}@{inst}.1" for i in (1, 2, 3)] + [f"RM{i}@{inst}.1" for i in (1, 2, 3)]
    v += g.scale(-1.0, F) + rm
rows = [(1, 0, 0.0, 0.0, [0.0] * len(names)), (1, 1, 1.0, 1.0, v)]
g.write_golden(__file__, [
    "parts_instances: instance placement x' = a + R (x + t - a), part orientation rotated by R;",
    "Bracket-2 turns ORI30 by 90 deg about z: e1 = (-0.5, cos30, 0). CTF_i = e_i . F, CU = CTF/k,",
    "U_b = sum CU_i e_i, node a RF = -F, RM = F x d0 (input-syntax.md §7.2, §7.3;",
    "connection-types.md §3.4); columns instance-qualified (cli-contract.md)",
], names, rows)
