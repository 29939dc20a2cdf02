"""Golden values of damage_coupled_potential (behaviors.md §7.1, §7.2, §7.5 E15).

Closed form (damage_lib.CoupledElasticDamage): forces k_i u_i before degradation, the coupled
criterion r = P(f) with quadratic potentials, the initiation point by the linear interpolation
of §7.1 inside the crossing increment, δ = P_e(u) − P_e(u_0), the force-shape laws, d applied to
every component the initiation potential involves (§7.2 without AFFECTED COMPONENTS), deletion
at d = 1. Asserts the E15 figures of §7.5 (t_0 = 1/√2, m_0, κ and the rows at t = 1, 2).
A deleted element (behaviors.md §7.4, output-variables.md §2) has forces 0, CDMG = 1 and CDIF
frozen, and its CU goes on reporting the prescribed motion of its nodes: element 1 (deleted at
t = 1.8) shows CU = (0.2, 0.1, 0) from t = 2 on, element 2 (deleted at t = 3.75) the doubled
step-2 motion at t = 4. NLGEOM=NO, so the six components are the differences of the DOFs.
"""
import math
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import damage_lib as dl  # noqa: E402
import golden_lib as g  # noqa: E402

e15 = dl.CoupledElasticDamage([1000.0] * 2, [100.0, 50.0], 1.0, [1.0, 1.0], ("LINEAR", 0.1))
six = dl.CoupledElasticDamage([1000.0] * 3 + [200.0] * 3, [60.0, 40.0, 30.0, 20.0, 15.0, 25.0], 1.0,
                              [1.0, 1.0, 1.0, 0.5, 0.5, 0.5], ("EXPONENTIAL", 0.08, 2.0),
                              alphas=[2.0, 2.0, 2.0, 3.0, 3.0, 1.5], beta=2.5)

T1 = [0.03, 0.02, 0.01]
R2 = [0.05, 0.04, -0.06]


def lerp(a, b, s):
    return [x + (y - x) * s for x, y in zip(a, b)]


# (step, increment, step time, total time, E15 parameter t, motions of element 2)
path = [(1, 0, 0.0, 0.0, 0.0, [0.0] * 6)]
path += [(1, i, 0.5 * i, 0.5 * i, 0.5 * i, lerp([0.0] * 3, T1, 0.5 * i) + [0.0] * 3) for i in (1, 2)]
path += [(2, i, 0.2 * i, 1.0 + 0.2 * i, 1.0 + 0.2 * i, T1 + lerp([0.0] * 3, R2, 0.2 * i)) for i in range(1, 6)]
path += [(3, i, 0.5 * i, 2.0 + 0.5 * i, 2.0, lerp(T1 + R2, [0.0] * 6, 0.5 * i)) for i in (1, 2)]
path += [(4, i, 0.25 * i, 3.0 + 0.25 * i, 2.0, lerp([0.0] * 6, [2 * x for x in T1 + R2], 0.25 * i))
         for i in range(1, 5)]

names = [f"CU{i}@1" for i in (1, 2, 3)] + [f"CTF{i}@1" for i in (1, 2, 3)] + ["CDIF@1", "CDMG@1"]
names += [f"CU{i}@2" for i in range(1, 7)] + [f"CTF{i}@2" for i in range(1, 7)]
names += ["CDIF@2", "CDIFC@2", "CDMG@2", "CDMG1@2", "CDMG4@2"]
rows, e15_rows = [], {}
# After deletion (behaviors.md §7.4, output-variables.md §2): forces 0, CDIF (history) frozen,
# CDMG = 1, and CU goes on reporting the prescribed motion of the element's nodes.
deleted = [False, False]
for step, inc, st, tt, t, u2 in path:
    u1 = [0.1 * t, 0.05 * t]
    if deleted[0]:
        out1 = u1 + [0.0] + [0.0, 0.0, 0.0, e15.r_max, 1.0]
    else:
        f, d, r = e15.update(u1) if inc > 0 else ([0.0, 0.0], 0.0, 0.0)
        out1 = u1 + [0.0] + f + [0.0, r, d]
        e15_rows[round(t, 9)] = (r, d, f, e15.kappa)
        deleted[0] = d >= 1.0
    if deleted[1]:
        out2 = u2 + [0.0] * 6 + [six.r_max, six.r_max, 1.0, 1.0, 1.0]
    else:
        f, d, r = six.update(u2) if inc > 0 else ([0.0] * 6, 0.0, 0.0)
        out2 = u2 + f + [r, r, d, d, d]
        deleted[1] = d >= 1.0
    rows.append((step, inc, st, tt, out1 + out2))

# §7.5 E15: initiation at t_0 = 1/√2, m_0 = 0.0790569415; at t = 1, κ = 0.0327464574,
# CDIF = 1.414214, CDMG = 0.524445639, CTF = (47.555436, 23.777718).
dl.check(e15.criterion([0.1 / math.sqrt(2), 0.05 / math.sqrt(2)]), 1.0, 1e-12, "E15 t_0")
dl.check(e15.m0, 0.0790569415, 5e-11, "E15 m_0")
r, d, f, kappa = e15_rows[1.0]
dl.check(kappa, 0.0327464574, 5e-11, "E15 κ at t = 1")
dl.check(r, 1.414214, 5e-7, "E15 CDIF at t = 1")
dl.check(d, 0.524445639, 5e-10, "E15 CDMG at t = 1")
dl.check(f[0], 47.555436, 5e-7, "E15 CTF1 at t = 1")
dl.check(f[1], 23.777718, 5e-7, "E15 CTF2 at t = 1")
# With these increments δ reaches Δu_f at t = 1.6017 (between rows): d = 1 first at t = 1.8.
dl.check(e15_rows[1.6][1], 0.99924, 5e-6, "E15 CDMG at t = 1.6")
dl.check(e15_rows[1.8][1], 1.0, 0.0, "E15 failed at t = 1.8")
# Motions after deletion: E15 at t = 2 (held there in steps 3 and 4), element 2 at t = 4.
for column, want in (("CU1@1", 0.2), ("CU2@1", 0.1), ("CU1@2", 0.06), ("CU6@2", -0.12)):
    dl.check(rows[-1][4][names.index(column)], want, 1e-15, f"{column} of the deleted element at t = 4")

g.write_golden(__file__, [
    "damage_coupled_potential: element 1 = E15 (CARTESIAN, P = |(f1/100, f2/50)| = 1, P_e = |(u1, u2)|,",
    "linear 0.1) along U = t (0.1, 0.05), t = 0.5, 1, 1.2, ..., 2 (deleted at 1.8). Element 2: CARTESIAN +",
    "CARDAN, P = (sum |f_i/R_i|^a_i)^(1/b), R = 60, 40, 30, 20, 15, 25, a = 2, 2, 2, 3, 3, 1.5, b = 2.5;",
    "P_e = |(u_i/S_i)|, S = 1, 1, 1, .5, .5, .5;",
    "EXPONENTIAL (0.08, 2); translations, then rotations (initiates inside step 2), unload, reload x2.",
    "Initiation point by linear interpolation of r in the crossing increment (behaviors.md §7.1).",
    "Deleted elements: forces 0, CDIF frozen, CDMG = 1, CU = the motion of their nodes (§7.4)",
], names, rows)
