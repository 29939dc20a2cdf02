"""Golden values of assembled_types: HINGE, CYLINDRICAL, PLANAR, TRANSLATOR, UJOINT, WELD, BEAM,
BUSHING, ALIGN under a general load at node b (connection-types.md §2.1, §3.4, §3.5, §3.8)."""
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import golden_lib as g  # noqa: E402

C30 = 0.8660254037844387
FRAMES = {
    "GLOBAL": g.orientation([1.0, 0.0, 0.0], [0.0, 1.0, 0.0]),
    "ORI30": g.orientation([C30, 0.5, 0.0], [-0.5, C30, 0.0]),
    "ORIYX": g.orientation([0.0, 1.0, 0.0], [-1.0, 0.0, 0.0]),
    "HZ": g.orientation([0.0, 0.0, 1.0], [1.0, 0.0, 0.0]),
}
g.assert_close(sum(FRAMES["HZ"], []), [0, 0, 1, 1, 0, 0, 0, 1, 0], 0.0, "HZ (§5.3)")
K = {1: 1000.0, 2: 2000.0, 3: 4000.0, 4: 100.0, 5: 200.0, 6: 400.0}
F = [10.0, 20.0, 30.0]
M = [1.0, 2.0, 3.0]
# element: (type, frame, d0, available components, force at b, moment at b)
ELEMENTS = {
    1: ("HINGE", "HZ", [0.0, 0.0, 0.0], (4,), F, M),
    2: ("CYLINDRICAL", "ORI30", [0.0, 0.0, 0.0], (1, 4), F, M),
    3: ("PLANAR", "GLOBAL", [0.0, 0.0, 0.0], (2, 3, 4), F, M),
    4: ("TRANSLATOR", "ORIYX", [0.0, 0.0, 0.0], (1,), F, M),
    5: ("UJOINT", "GLOBAL", [0.0, 0.0, 0.0], (4, 6), F, M),
    6: ("WELD", "GLOBAL", [0.0, 0.0, 1.0], (), F, M),
    7: ("BEAM", "ORI30", [1.0, 0.0, 0.0], (), F, M),
    8: ("BUSHING", "ORI30", [0.0, 0.0, 0.0], (1, 2, 3, 4, 5, 6), F, M),
    9: ("ALIGN", "GLOBAL", [0.0, 0.0, 0.0], (), [0.0, 0.0, 0.0], M),
}


def solve(frame, d0, avail, force, moment):
    """Aligned frames (b defaults to a's directions), node a fixed, NLGEOM=NO. The rows of
    components 1-3 are e_i (node b) and of 4-6 e_k (node b's rotation) (§3.4), so equilibrium at
    node b gives f_i = e_i . F and m_k = e_k . M. Available components move by f/k; constrained
    ones carry f as CRF. Node a: RF = -F, RM = F x d0 - M."""
    e = FRAMES[frame]
    ctf = [g.dot(ei, force) for ei in e] + [g.dot(ei, moment) for ei in e]
    cu = [ctf[i - 1] / K[i] if i in avail else 0.0 for i in range(1, 7)]
    crf = [0.0 if i in avail else ctf[i - 1] for i in range(1, 7)]
    ub, urb = [0.0] * 3, [0.0] * 3
    for i in range(3):
        ub = g.add(ub, g.scale(cu[i], e[i]))
        urb = g.add(urb, g.scale(cu[i + 3], e[i]))
    rma = g.sub(g.cross(force, d0), moment)
    return ctf, cu, crf, ub, urb, g.scale(-1.0, force), rma


names, final = [], []
for el, (typ, frame, d0, avail, force, moment) in ELEMENTS.items():
    ctf, cu, crf, ub, urb, rfa, rma = solve(frame, d0, avail, force, moment)
    if typ == "ALIGN":  # components 4-6 only; node b translations held, nothing loads them
        comps = (4, 5, 6)
    else:
        comps = (1, 2, 3, 4, 5, 6)
    for var, vals in (("CTF", ctf), ("CU", cu), ("CRF", crf)):
        names += [f"{var}{i}@{el}" for i in comps]
        final += [vals[i - 1] for i in comps]
    b, a = 2 * el, 2 * el - 1
    names += [f"U{i}@{b}" for i in (1, 2, 3)] + [f"UR{i}@{b}" for i in (1, 2, 3)]
    final += ub + urb
    names += [f"RF{i}@{a}" for i in (1, 2, 3)] + [f"RM{i}@{a}" for i in (1, 2, 3)]
    final += rfa + rma
rows = [(1, 0, 0.0, 0.0, [0.0] * len(names)), (1, 1, 1.0, 1.0, final)]
g.write_golden(__file__, [
    "assembled_types: node a fixed, F = (10, 20, 30) and M = (1, 2, 3) at node b (ALIGN: M only),",
    "aligned frames: CTF_i = e_i . F (i = 1-3), CTF_k = e_k . M (k = 4-6); available CU = CTF/k",
    "with k = (1000, 2000, 4000, 100, 200, 400); constrained CU = 0, CRF = CTF; node a RF = -F,",
    "RM = F x d0 - M (connection-types.md §2.1, §3.4, §3.5, §3.8, §4)",
], names, rows)
