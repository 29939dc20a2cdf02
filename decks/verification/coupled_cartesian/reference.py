"""Golden values of coupled_cartesian (behaviors.md §4.3, §4.5 E3)."""
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import golden_lib as g  # noqa: E402

# Upper triangle column by column: D11, D12, D22, D13, D23, D33 (behaviors.md §4.3).
D = [[1000.0, 200.0, 0.0], [200.0, 500.0, 0.0], [0.0, 0.0, 800.0]]
UB = [0.01, 0.02, 0.0]
E = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]  # no orientation: global axes
D0 = {1: [0.0, 0.0, 0.0], 2: [1.0, 0.0, 0.0]}

c = [g.dot(e, UB) for e in E]  # node a fixed: c_i = e_i . u_b (connection-types.md §3.4)
f = g.matvec(D, c)
names, final = [], []
for el in (1, 2):
    names += [f"CTF{i}@{el}" for i in (1, 2, 3)]
    final += f
for el in (1, 2):
    names += [f"CU{i}@{el}" for i in (1, 2, 3)]
    final += c
# Node a: translations -sum f_i e_i; rotations sum f_i (e_i x d0) (B0 row of §3.4).
for el, node in ((1, 1), (2, 3)):
    fa = g.scale(-1.0, f)
    ma = [0.0, 0.0, 0.0]
    for fi, e in zip(f, E):
        ma = g.add(ma, g.scale(fi, g.cross(e, D0[el])))
    names += [f"RF{i}@{node}" for i in (1, 2, 3)] + [f"RM{i}@{node}" for i in (1, 2, 3)]
    final += fa + ma
for node in (2, 4):  # node b has no active rotations (CARTESIAN ignores ori b)
    names += [f"RF{i}@{node}" for i in (1, 2, 3)]
    final += f
rows = [(1, 0, 0.0, 0.0, [0.0] * len(names)), (1, 1, 1.0, 1.0, final)]
g.write_golden(__file__, [
    "coupled_cartesian: f = D c with D from the 21-term upper triangle (column-wise),",
    "c = (0.01, 0.02, 0) -> CTF = (14, 12, 0); RM at node a = sum f_i (e_i x d0) = (0, 0, -12)",
    "for d0 = (1, 0, 0) (behaviors.md §4.3, §4.5 E3; connection-types.md §3.4)",
], names, rows)
