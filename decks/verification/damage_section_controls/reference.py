"""Golden values of damage_section_controls (*SECTION CONTROLS: ELEMENT DELETION, MAX
DEGRADATION; docs/decisions.md "Damage").

Closed form: the E12 law of damage_lib (u_0 = 0.09, LINEAR 0.2) gives d(U) on the envelope; the
damage used is min(d, d_max); CTF1 = (1 − d) k U. With deletion on, the element is deleted at
the end of the increment where d reaches d_max (then CTF1 = 0, CDMG stays d_max, CSLST1 = 4,
and CU1 goes on reporting the prescribed motion of its node: behaviors.md §7.4,
output-variables.md §2); with ELEMENT DELETION=NO it stays: at d = 1 it carries nothing, at
d_max = 0.9 it keeps 0.1 k.
"""
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import damage_lib as dl  # noqa: E402
import golden_lib as g  # noqa: E402

K = 1000.0
controls = [(False, 1.0), (True, 0.9), (False, 0.9)]  # (ELEMENT DELETION, MAX DEGRADATION)
laws = [dl.ElasticDamage(K, 90.0, ("LINEAR", 0.2)) for _ in controls]
path = [(1, i, i / 7.0, i / 7.0, 0.05 * i) for i in range(0, 8)] + [(2, 1, 1.0, 2.0, 0.1)]
names = [f"{v}@{e}" for v in ("CU1", "CTF1", "CDMG", "CSLST1") for e in (1, 2, 3)]
rows, deleted = [], [False] * 3
for step, inc, st, tt, u in path:
    cu, ctf, dmg, status = [], [], [], []
    for e, (deletion, d_max) in enumerate(controls):
        if deleted[e]:
            # behaviors.md §7.4, output-variables.md §2: no force, damage frozen at d_max,
            # CSLST1 = 4; CU1 goes on reporting the prescribed motion of node b.
            cu.append(u), ctf.append(0.0), dmg.append(d_max), status.append(4.0)
            continue
        _, d, _ = laws[e].update(u) if inc > 0 else (0.0, 0.0, 0.0)
        d = min(d, d_max)
        cu.append(u), ctf.append((1.0 - d) * K * u), dmg.append(d), status.append(0.0)
        if deletion and d >= d_max:
            deleted[e] = True
    rows.append((step, inc, st, tt, cu + ctf + dmg + status))

dl.check(rows[7][4][4], 0.0, 0.0, "capped element deleted")
dl.check(rows[8][4][5], (1.0 - 0.9) * K * 0.1, 1e-12, "residual stiffness 0.1 k on unloading")
dl.check(rows[8][4][1], 0.1, 0.0, "CU1 of the deleted element 2 after unloading")

g.write_golden(__file__, [
    "damage_section_controls: three AXIAL connectors with the E12 law (k = 1000, FORCE 90, LINEAR",
    "0.2), U 0 -> 0.35 (7 incr.), -> 0.1 (1). ELEMENT DELETION=NO; MAX DEGRADATION=0.9 (deleted at",
    "0.9); MAX DEGRADATION=0.9 with ELEMENT DELETION=NO (residual 0.1 k). d = min(d_E12, d_max).",
    "Deleted element 2: CTF1 = 0, CDMG = 0.9, CSLST1 = 4, CU1 = the motion of node b (§7.4)",
], names, rows)
