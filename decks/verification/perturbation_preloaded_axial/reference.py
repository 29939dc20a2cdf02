"""Golden values of perturbation_preloaded_axial (docs/perturbation.md; connection-types.md §3.7).

A perturbation step's response is the linear one about the base state: K δ = ΔP on the free DOFs
of node 2, δ = Δ on its prescribed ones, with K the tangent of the internal force of node 2 at the
base state. K is computed here by central differences of the AXIAL connector's force
f (x − x1)/|x − x1|, f = k (|x − x1| − ref), and checked against the closed form
k n nᵀ + (f/L)(I − n nᵀ)."""
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import golden_lib as g  # noqa: E402

K, L0, REF = 1000.0, 1.0, 0.9
P_BASE, P_RELOAD = 150.0, 200.0


def internal(x):
    """The connector's force on node 2 at position x (node 1 at the origin)."""
    length = g.norm(x)
    return g.scale(K * (length - REF) / length, x)


def tangent(x, h=1e-6):
    """dF/dx by central differences (error O(h^2) ~ 1e-12 relative here)."""
    cols = []
    for j in range(3):
        xp, xm = list(x), list(x)
        xp[j] += h
        xm[j] -= h
        cols.append(g.scale(0.5 / h, g.sub(internal(xp), internal(xm))))
    return g.transpose(cols)


def perturbation(k, load, prescribed):
    """δ with δ_p = prescribed[p] and K_ff δ_f = load_f − K_fp δ_p; returns δ and K δ."""
    free = [i for i in range(3) if i not in prescribed]
    delta = [prescribed.get(i, 0.0) for i in range(3)]
    rhs = [load[i] - sum(k[i][p] * v for p, v in prescribed.items()) for i in free]
    for i, v in zip(free, g.solve([[k[i][j] for j in free] for i in free], rhs)):
        delta[i] = v
    return delta, g.matvec(k, delta)


names = ["CTF1@1", "CU1@1", "U1@2", "U2@2", "U3@2", "RF1@2", "RF2@2", "RF3@2", "RF1@1", "RF2@1",
         "RF3@1"]


def general_row(step, inc, st, tt, load):
    """Node 2 on the x axis under an axial load: L = ref + P/k, CTF1 = P; only node 1 is held."""
    if inc == 0:
        return (step, inc, st, tt, [K * (L0 - REF)] + [0.0] * 10)
    length = REF + load / K
    return (step, inc, st, tt, [load, length - L0, length - L0, 0.0, 0.0, 0.0, 0.0, 0.0, -load,
                                0.0, 0.0])


rows = [general_row(1, 0, 0.0, 0.0, 0.0)]
for inc, t in enumerate([0.25, 0.5, 0.75, 1.0], start=1):
    rows.append(general_row(1, inc, t, t, P_BASE * t))

base = [REF + P_BASE / K, 0.0, 0.0]
k = tangent(base)
length = base[0]
n = [1.0, 0.0, 0.0]
closed = [[K * n[i] * n[j] + P_BASE / length * ((i == j) - n[i] * n[j]) for j in range(3)]
          for i in range(3)]
for i in range(3):
    g.assert_close(k[i], closed[i], 1e-6, "tangent of the base state")

# Steps 2-4: (perturbation load, prescribed perturbations of node 2). Node 1 is held in each
# (step 4 holds it again after OP=NEW), so RF@1 = −K δ, the change of its connector force.
perturbations = [
    ([10.0, 3.0, 0.0], {}),
    ([0.0, 0.0, 0.0], {1: 0.01}),
    ([0.0, 0.0, 0.0], {0: 0.002}),
]
for step, (load, prescribed) in enumerate(perturbations, start=2):
    delta, force = perturbation(k, load, prescribed)
    reaction2 = [force[i] - load[i] if i in prescribed else 0.0 for i in range(3)]
    axial = g.dot(n, delta)  # the change of the length, to first order
    rows.append((step, 1, 0.0, 1.0, [K * axial, axial] + delta + reaction2 +
                 g.scale(-1.0, force)))

for inc, t in enumerate([0.5, 1.0], start=1):
    rows.append(general_row(5, inc, t, 1.0 + t, P_BASE + (P_RELOAD - P_BASE) * t))

g.write_golden(__file__, [
    "perturbation_preloaded_axial: AXIAL k = 1000, ref = 0.9, node 2 loaded to 150 along x",
    "(NLGEOM) -> base state L = 1.05, f = 150; perturbation steps: dP = (10, 3, 0); dU2 = 0.01;",
    "OP=NEW with dU1 = 0.002. Each is K d = dP on the free DOFs with K the tangent of the base",
    "state (central differences of the connector force, checked against k nn^T + f/L (I - nn^T));",
    "a general step after them reloads to 200 from the base state (docs/perturbation.md)",
], names, rows)
