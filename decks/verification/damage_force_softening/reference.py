"""Golden values of damage_force_softening (behaviors.md §7.2, §7.5: E12 and its variants).

Closed forms of damage_lib.py: u_0 = 90/1000, the force-shape laws d = 1 − u_0 g(κ)/(u_0 + κ)
(LINEAR, EXPONENTIAL) and d = table(κ) (TABULAR), κ = max(U) − u_0, CTF1 = (1 − d) k U. The
spec's printed E12 table and variant table are asserted to their digits. Every element reaches
d = 1 at U = 0.3 and is deleted at the end of that increment; in step 4 (U = 0.35) its forces
are 0, CDMG = 1, CDIF stays frozen, CSLST1 = 4, and CU1 = 0.35, the motion of its node
(behaviors.md §7.4, output-variables.md §2).
"""
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import damage_lib as dl  # noqa: E402
import golden_lib as g  # noqa: E402

K = 1000.0
laws = [("LINEAR", 0.2), ("EXPONENTIAL", 0.2, 5.0), ("TABULAR", [(0.0, 0.0), (0.5, 0.05), (1.0, 0.2)])]
elements = [dl.ElasticDamage(K, 90.0, law) for law in laws]

# (step, increment, step time, total time, U)
path = [(1, 0, 0.0, 0.0, 0.0)]
path += [(1, i, 0.25 * i, 0.25 * i, 0.05 * i) for i in range(1, 5)]
path += [(2, 1, 1.0, 2.0, 0.1)]
path += [(3, i, 0.25 * i, 2.0 + 0.25 * i, 0.1 + 0.05 * i) for i in range(1, 5)]
path += [(4, 1, 1.0, 4.0, 0.35)]

names = [f"CU1@{e}" for e in (1, 2, 3)] + [f"CTF1@{e}" for e in (1, 2, 3)]
names += [f"CEF1@{e}" for e in (1, 2, 3)] + [f"CDMG@{e}" for e in (1, 2, 3)]
names += [f"CDIF@{e}" for e in (1, 2, 3)] + [f"CSLST1@{e}" for e in (1, 2, 3)]
names += ["RF1@2", "RF1@4", "RF1@6"]
rows, table = [], {}
deleted = [False] * 3
for step, inc, st, tt, u in path:
    cu, ctf, dmg, cdif, status = [], [], [], [], []
    for i, el in enumerate(elements):
        if deleted[i]:
            # behaviors.md §7.4, output-variables.md §2: a deleted element carries no force,
            # CDMG = 1, CDIF (history) stays frozen, CSLST = 4, and CU1 goes on reporting the
            # prescribed motion of its node b.
            cu.append(u)
            ctf.append(0.0)
            dmg.append(1.0)
            cdif.append(el.r_max)
            status.append(4.0)
            continue
        f, d, r = el.update(u) if inc > 0 else (0.0, 0.0, 0.0)
        cu.append(u)
        ctf.append(f)
        dmg.append(d)
        cdif.append(r)
        status.append(0.0)
    table[tt] = (ctf, dmg)
    rows.append((step, inc, st, tt, cu + ctf + ctf + dmg + cdif + status + ctf))
    # Deletion at the end of the increment in which d reaches 1 (§7.4).
    for i, el in enumerate(elements):
        if not deleted[i] and el.d >= 1.0:
            deleted[i] = True

# behaviors.md §7.5, E12 table (CDMG, CTF1) and the step-1 variants (d, F).
e12 = {0.25: (0, 50), 0.5: (0.145, 85.5), 0.75: (0.58, 63), 1.0: (0.7975, 40.5),
       2.0: (0.7975, 20.25), 2.25: (0.7975, 30.375), 2.5: (0.7975, 40.5), 2.75: (0.928, 18),
       3.0: (1.0, 0.0)}
for tt, (d, f) in e12.items():
    dl.check(table[tt][1][0], d, 1e-12, f"E12 CDMG at {tt}")
    dl.check(table[tt][0][0], f, 1e-9, f"E12 CTF1 at {tt}")
variants = {0.5: (0.300429780, 69.957022, 0.1, 90), 0.75: (0.869283914, 19.607413, 0.533333, 70),
            1.0: (0.974089958, 5.182008, 0.7, 60)}
for tt, (de, fe, dt, ft) in variants.items():
    dl.check(table[tt][1][1], de, 5e-10, f"EXPONENTIAL d at {tt}")
    dl.check(table[tt][0][1], fe, 5e-7, f"EXPONENTIAL F at {tt}")
    dl.check(table[tt][1][2], dt, 5e-7, f"TABULAR d at {tt}")
    dl.check(table[tt][0][2], ft, 1e-9, f"TABULAR F at {tt}")
for i in range(3):
    dl.check(rows[-1][4][i], 0.35, 0.0, f"CU1 of the deleted element {i + 1} at U = 0.35")

g.write_golden(__file__, [
    "damage_force_softening: three AXIAL connectors, k = 1000, FORCE initiation at 90 (u_0 = 0.09),",
    "LINEAR (0.2), EXPONENTIAL (0.2, a = 5), TABULAR (0,0)/(0.5,0.05)/(1,0.2) softening, all driven",
    "U 0 -> 0.2 (4 incr.), -> 0.1 (1), -> 0.3 (4: every element deleted at U = 0.3), -> 0.35 (1).",
    "Closed forms of behaviors.md §7.2 (damage_lib.py); matches the §7.5 E12 table and its variants.",
    "Deleted: forces 0, CDMG = 1, CDIF frozen, CSLST1 = 4, CU1 = the motion of node b (§7.4)",
], names, rows)
