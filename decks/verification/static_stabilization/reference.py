"""Golden values of static_stabilization: a spring (k = 100, node 2 along x) and a torsion spring
(k_r = 30, node 3 about x) loaded by ramps, under *STATIC, STABILIZE (docs/stabilization.md),
written out from the rules of docs/decisions.md "Automatic stabilization":

- viscous forces c M* (u - u0)/dt on the free DOFs, M* = 1 per translation and L^2 per rotation,
  L the largest initial connector length (2 here, so 4 for the rotation);
- step 1 (STABILIZE=0.01, ALLSDTOL=0: a constant factor): the first increment without damping,
  then c = f dE (T/dt)^2 dt / (du.M* du) with dE the elements' work in that increment;
- step 2 (FACTOR=5, ALLSDTOL=0.02: adaptive): c = 5 from the first increment; after each
  increment, halved while ALLSD > ALLSDTOL ALLIE, and otherwise halved back towards 5 when above
  it (no attempt fails here, so it never rises);
- ALLIE = k u^2/2 + k_r theta^2/2, ALLSD and ALLWK the trapezoidal work of the viscous forces and
  of the loads over each increment, ETOTAL = ALLIE + ALLSD - ALLWK, which equilibrium at both ends
  of every increment keeps at zero (asserted to round-off).

Each increment of this linear model is one 1x1 solve per DOF: (k + c m/dt) u = P + c m u0/dt.
"""
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import golden_lib as g  # noqa: E402

STIFF = [100.0, 30.0]      # spring, torsion spring
MASS = [1.0, 2.0 ** 2]     # M*: a translation, a rotation times L^2
DT, PERIOD = 0.1, 1.0
STEPS = [  # (loads at the start, loads at the end, fraction, factor, allsdtol)
    ([0.0, 0.0], [10.0, 3.0], 0.01, None, 0.0),
    ([10.0, 3.0], [20.0, 6.0], None, 5.0, 0.02),
]

x = [0.0, 0.0]
force = [0.0, 0.0]  # the viscous forces at the last converged state
internal = stabilization = work = 0.0
names = ["U1@2", "UR1@3", "ALLIE", "ALLSD", "ALLWK", "ETOTAL"]
rows = [(1, 0, 0.0, 0.0, [0.0] * 6)]
total_time = 0.0
for number, (start, end, fraction, given, allsdtol) in enumerate(STEPS, start=1):
    c = given if given is not None else 0.0
    base = c
    count = round(PERIOD / DT)
    for inc in range(1, count + 1):
        t = inc * DT
        loads = [start[i] + (end[i] - start[i]) * t / PERIOD for i in range(2)]
        loads0 = [start[i] + (end[i] - start[i]) * (t - DT) / PERIOD for i in range(2)]
        x1 = [(loads[i] + c * MASS[i] * x[i] / DT) / (STIFF[i] + c * MASS[i] / DT) for i in range(2)]
        force1 = [c * MASS[i] * (x1[i] - x[i]) / DT for i in range(2)]
        dx = [x1[i] - x[i] for i in range(2)]
        element_work = sum(0.5 * STIFF[i] * (x1[i] ** 2 - x[i] ** 2) for i in range(2))
        internal += element_work
        stabilization += sum(0.5 * (force[i] + force1[i]) * dx[i] for i in range(2))
        work += sum(0.5 * (loads0[i] + loads[i]) * dx[i] for i in range(2))
        x, force = x1, force1
        if c == 0.0:
            motion = sum(MASS[i] * dx[i] ** 2 for i in range(2))
            c = base = fraction * element_work * (PERIOD / DT) ** 2 * DT / motion
        elif allsdtol > 0.0:
            above = stabilization > allsdtol * internal
            if not above and c > base:
                c = max(base, 0.5 * c)
            if above:
                c *= 0.5
        total = internal + stabilization - work
        g.assert_close([total], [0.0], 1e-12 * work, f"the balance at step {number} increment {inc}")
        total_time += DT
        rows.append((number, inc, t, total_time, [x[0], x[1], internal, stabilization, work, total]))

g.write_golden(__file__, [
    "static_stabilization: a spring and a torsion spring under ramped loads with STABILIZE=0.01",
    "(constant factor from the first increment), then FACTOR=5 with ALLSDTOL=0.02 (adaptive);",
    "each increment solved by hand from the rules of docs/decisions.md, energies by definition",
], names, rows)
