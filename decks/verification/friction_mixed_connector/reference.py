"""Golden values of friction_mixed_connector (friction.md §1, §2.2, §4.1; behaviors.md §6).

One CARTESIAN + CARDAN connector, every dof of node b prescribed, node a fixed, coincident nodes,
NLGEOM=NO: the motions are CU = (U1, U2, U3, UR1, UR2, UR3) of node b (connection-types.md §3.4).
The behaviours act on disjoint components and are evaluated separately, each in closed form per
increment from its committed state:
  1    elastic: f1 = k1 u1, k1 = 2000.
  2,3  coupled friction, circle, CONTACT FORCE=1: F_N = |f1| (f1 has no friction part), F_lim =
       0.5 F_N, k_s = 1e4; radial return f = F_lim f_tr/|f_tr|, dgamma = (|f_tr| - F_lim)/k_s
       (F_lim = 0: f = 0, dgamma = |f_tr|/k_s).
  4,5  elastic k = 100 with coupled plasticity, circle, M_y = 1 (perfectly plastic): radial
       return m = M_y m_tr/|m_tr|, dlambda = (|m_tr| - M_y)/k, u_pl += dlambda n, CUPEQ += dlambda.
  6    friction COMPONENT=6, F_N = F_int = 20, M_lim = 0.05 * 20 = 1, k_s = 100.
Reactions at node b: RF = (CTF1, CTF2, CTF3), RM = (CTF4, CTF5, CTF6).
"""
import math
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import golden_lib as g  # noqa: E402
import friction_lib as fl  # noqa: E402
import plastic_lib as pl  # noqa: E402

K1, KS, MU = 2000.0, 1.0e4, 0.5
KR, MY = 100.0, 1.0
K6, MU6, FINT6 = 100.0, 0.05, 20.0


def radial(trial, limit):
    """Radial return on a circle: (force, dgamma); limit may be 0."""
    m = math.hypot(*trial)
    if m - limit <= fl.STICK_TOL * max(limit, m):  # ties stick (friction.md §4.1 step 3)
        return list(trial), 0.0
    return [limit * x / m for x in trial], m - limit


fr23 = fl.Friction(KS, fl.Constant(MU), ncomp=2)
fr6 = fl.Friction(K6, fl.Constant(MU6), f_int=pl.Hardening([(FINT6, 0.0)]))
us23, gam23 = [0.0, 0.0], 0.0
up45, ubar = [0.0, 0.0], 0.0
us6, gam6 = 0.0, 0.0

targets = [  # end values of (U1, U2, U3, UR1, UR2, UR3) per step
    (-0.1, 0.0, 0.0, 0.02, 0.0, 0.015),
    (-0.15, 0.04, 0.0, 0.02, 0.02, 0.015),
    (-0.05, 0.04, 0.04, -0.02, 0.02, -0.01),
    (0.05, -0.04, 0.04, -0.02, 0.02, 0.0),
]
names = [f"CU{i}@70" for i in range(1, 7)] + [f"CTF{i}@70" for i in range(1, 7)]
names += ["CEF1@70", "CEF4@70", "CEF5@70"]
for ident in ("CSF", "CNF", "CSLIPST", "CASU"):
    names += [f"{ident}{i}@70" for i in (2, 3, 6)]
names += ["CSFC@70", "CNFC@70", "CASUC@70", "CUP4@70", "CUP5@70", "CUPEQ@70"]
names += [f"RF{i}@2" for i in (1, 2, 3)] + [f"RM{i}@2" for i in (1, 2, 3)]
rows, u = [], [0.0] * 6
st_hist = []
for step, target in enumerate(targets, start=1):
    u0 = list(u)
    for inc, t in enumerate(fl.increments(0.25, 1.0), start=1):
        u = [fl.ramp(a, b, t, 1.0) for a, b in zip(u0, target)]
        f1 = K1 * u[0]
        # Friction on 2, 3.
        fn = abs(f1)
        f23, dg = radial([KS * (u[1] - us23[0]), KS * (u[2] - us23[1])], MU * fn)
        if dg > 0.0:
            trial = [KS * (u[1] - us23[0]), KS * (u[2] - us23[1])]
            m = math.hypot(*trial)
            us23 = [s + dg / KS * x / m for s, x in zip(us23, trial)]
            gam23 += dg / KS
        s23 = 1 if dg > 0.0 else 0
        lib23 = fr23.update([u[1], u[2]], fn, 0.25)
        assert max(abs(a - b) for a, b in zip(lib23, f23)) <= 1e-12 * 150 and fr23.status == s23
        assert abs(fr23.gamma - gam23) <= 1e-15
        # Plasticity on 4, 5.
        mtr = [KR * (u[3] - up45[0]), KR * (u[4] - up45[1])]
        m45, dl = radial(mtr, MY)
        if dl > 0.0:
            mm = math.hypot(*mtr)
            up45 = [p + dl / KR * x / mm for p, x in zip(up45, mtr)]
            ubar += dl / KR
            pl.check_coupled(mtr, m45, dl / KR, [KR, KR], [x / MY for x in m45], MY, MY)
        # Friction on 6.
        f6, dg6 = radial([K6 * (u[5] - us6)], MU6 * FINT6)
        if dg6 > 0.0:
            us6 += math.copysign(dg6 / K6, u[5] - us6)
            gam6 += dg6 / K6
        s6 = 1 if dg6 > 0.0 else 0
        assert abs(fr6.update([u[5]], 0.0, 0.25)[0] - f6[0]) <= 1e-12 and fr6.status == s6
        assert abs(fr6.gamma - gam6) <= 1e-15
        st_hist.append((s23, 1 if dl > 0.0 else 0, s6))
        ctf = [f1, f23[0], f23[1], m45[0], m45[1], f6[0]]
        values = list(u) + ctf + [f1, m45[0], m45[1]]
        values += [f23[0], f23[1], f6[0], fn, fn, FINT6, s23, s23, s6, gam23, gam23, gam6]
        values += [math.hypot(*f23), fn, gam23, up45[0], up45[1], ubar]
        values += ctf
        rows.append((step, inc, t, step - 1 + t, [float(v) for v in values]))
# The only exact ties: friction 6 held after slipping (step 2), f_tr = M_lim; they stick.
assert fl.check_margins([("friction 2-3", fr23), ("friction 6", fr6)], ties_allowed=4) == 4

# Every regime occurs: friction 2-3 sticks (2.1), then slips under a growing (step 2), a
# shrinking (step 3) and a zero F_N (4.2: u1 = 0); the plasticity yields, turns (step 2) and
# reverses (step 3); friction 6 slips, sticks when held (exact ties) and on reversal, slips
# backwards (3.4) and sticks on the way back (step 4).
u1_zero = rows[-3][4]
assert abs(u1_zero[0]) <= 1e-15 and u1_zero[names.index("CSF2@70")] == 0.0
assert [s[0] for s in st_hist] == [0, 0, 0, 0, 0, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1], st_hist
assert [s[1] for s in st_hist] == [0, 0, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 0, 0, 0, 0], st_hist
assert [s[2] for s in st_hist] == [0, 0, 1, 1, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0], st_hist

g.write_golden(__file__, [
    "friction_mixed_connector: CONN3D2 CARTESIAN + CARDAN, node b driven in all six dofs. 1:",
    "elastic 2000; 2-3: coupled friction (circle), CONTACT FORCE=1, mu = 0.5, k = 1e4; 4-5:",
    "elastic 100 with coupled plasticity (circle), M_y = 1; 6: COMPONENT=6 friction, F_int = 20,",
    "mu = 0.05, k = 100. Separate closed-form radial returns per increment. Row 0 not listed.",
], names, rows)
