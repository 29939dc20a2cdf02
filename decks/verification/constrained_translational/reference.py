"""Golden values of constrained_translational (connection-types.md §2.1, §3.4, §3.8, §4)."""
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import golden_lib as g  # noqa: E402

C30 = 0.8660254037844387
ORI30 = g.orientation([C30, 0.5, 0.0], [-0.5, C30, 0.0])
ORIYX = g.orientation([0.0, 1.0, 0.0], [-1.0, 0.0, 0.0])
GLOBAL = g.orientation([1.0, 0.0, 0.0], [0.0, 1.0, 0.0])
g.assert_close(ORIYX[0] + ORIYX[1] + ORIYX[2], [0, 1, 0, -1, 0, 0, 0, 0, 1], 0.0, "ORIYX")
F = [10.0, 20.0, 30.0]


def projection(frame, d0, load, stiff):
    """Frame-a projections, node a fixed: sum f_i e_i = F at node b, so f_i = e_i . F.
    Available components (in stiff) move by f_i/k_i; constrained ones carry f_i as CRF.
    Node a: RF = -F, RM = sum f_i (e_i x d0) (B0 rows, §3.4)."""
    f = [g.dot(e, load) for e in frame]
    cu = [f[i] / stiff[i + 1] if i + 1 in stiff else 0.0 for i in range(3)]
    crf = [0.0 if i + 1 in stiff else f[i] for i in range(3)]
    ub = [0.0, 0.0, 0.0]
    rm = [0.0, 0.0, 0.0]
    for i in range(3):
        ub = g.add(ub, g.scale(cu[i], frame[i]))
        rm = g.add(rm, g.scale(f[i], g.cross(frame[i], d0)))
    g.assert_close(rm, g.cross(load, d0), 1e-12, "moment balance")
    return f, cu, crf, ub, g.scale(-1.0, load), rm


out = {}
# 1 SLOT: available 1 (k 1000); 2 and 3 constrained.
f, cu, crf, ub, rfa, rma = projection(ORI30, [1.0, 0.0, 0.0], F, {1: 1000.0})
out[1] = dict(ctf=f, cu=cu, crf=crf, ub=ub, rfb=[0.0] * 3, rfa=rfa + rma)
# 2 SLIDE-PLANE: available 2, 3 (500, 800); 1 constrained (plane normal e1 = Y).
f, cu, crf, ub, rfa, rma = projection(ORIYX, [1.0, 0.0, 0.0], F, {2: 500.0, 3: 800.0})
out[2] = dict(ctf=f, cu=cu, crf=crf, ub=ub, rfb=[0.0] * 3, rfa=rfa + rma)
# 3 RADIAL-THRUST: radial e_r = d0/|d0| = x, axial e3 = z; the tangential y of node b is held by
# a boundary condition and nothing loads it. Load (10, 0, 30): f1 = 10, f3 = 30 (§2.1).
load3 = [10.0, 0.0, 30.0]
f, cu, crf, ub, rfa, rma = projection(GLOBAL, [1.0, 0.0, 0.0], load3, {1: 1000.0, 3: 3000.0})
out[3] = dict(ctf=[f[0], f[2]], cu=[cu[0], cu[2]], crf=[0.0, 0.0], ub=ub,
              rfb=[0.0] * 3, rfa=rfa + rma, comps=(1, 3))
# 4 LINK: q = (0.6, 0.8, 0); node 8 moves along x only, so the constraint q . u_b = 0 keeps it in
# place; equilibrium in x: lambda 0.6 = 60, lambda = 100 (tension); the y support takes
# lambda 0.8 = 80.
lam = 60.0 / 0.6
q = [0.6, 0.8, 0.0]
out[4] = dict(ctf=[lam], cu=[0.0], crf=[lam], ub=[0.0] * 3, rfb=[0.0, lam * 0.8, 0.0],
              rfa=g.scale(-lam, q), comps=(1,))
# 5 JOIN: node a has no rotations; u_b = u_a = 0; multipliers = F in global axes.
out[5] = dict(ctf=F[:], cu=[0.0] * 3, crf=F[:], ub=[0.0] * 3, rfb=[0.0] * 3,
              rfa=g.scale(-1.0, F))
# 6 PROJECTION CARTESIAN, coincident nodes: at zero relative rotation the mid frame is frame a;
# the theta blocks 1/2 (e_i x d0) vanish, so node b's held rotations carry no moment.
f, cu, crf, ub, rfa, rma = projection(ORI30, [0.0, 0.0, 0.0], F,
                                      {1: 1000.0, 2: 2000.0, 3: 4000.0})
out[6] = dict(ctf=f, cu=cu, crf=crf, ub=ub + [0.0] * 3, rfb=[0.0] * 6, rfa=rfa + rma)

NODE_A = {1: 1, 2: 3, 3: 5, 4: 7, 5: 9, 6: 11}
names, final = [], []
for el, o in out.items():
    comps = o.get("comps", (1, 2, 3))
    names += [f"CTF{i}@{el}" for i in comps] + [f"CU{i}@{el}" for i in comps]
    names += [f"CRF{i}@{el}" for i in comps]
    final += o["ctf"] + o["cu"] + o["crf"]
    b = 2 * el
    names += [f"U{i}@{b}" for i in (1, 2, 3)] + (["UR1@12", "UR2@12", "UR3@12"] if el == 6 else [])
    final += o["ub"]
    names += [f"RF{i}@{b}" for i in (1, 2, 3)] + (["RM1@12", "RM2@12", "RM3@12"] if el == 6 else [])
    final += o["rfb"]
    a = NODE_A[el]
    names += [f"RF{i}@{a}" for i in (1, 2, 3)]
    if len(o["rfa"]) == 6:
        names += [f"RM{i}@{a}" for i in (1, 2, 3)]
    final += o["rfa"]
rows = [(1, 0, 0.0, 0.0, [0.0] * len(names)),
        (1, 1, 0.5, 0.5, [0.5 * v for v in final]),
        (1, 2, 1.0, 1.0, final)]
g.write_golden(__file__, [
    "constrained_translational: SLOT, SLIDE-PLANE, RADIAL-THRUST, LINK, JOIN, PROJECTION",
    "CARTESIAN; node a fixed, load at node b; f_i = e_i . F from equilibrium at node b,",
    "available components CU = f/k, constrained CTF = CRF = f, CU = 0; node a RF = -F,",
    "RM = F x d0; LINK: lambda = 60/0.6 = 100 (connection-types.md §2.1, §3.4, §3.8, §4)",
], names, rows)
