"""Golden values of cae_damage_direct_jump (behaviors.md §7.1, §7.2, §7.4).

One AXIAL connector (k = 1000), FORCE initiation at 90 (u_0 = 0.09), EXPONENTIAL motion softening
(Δu_f = 0.2, a = 5), node a held, node b driven along U = 0, 0.08, 0.2, 0.05, 0.3 in four DIRECT
increments. Closed forms of damage_lib.py: κ = max(U) − u_0, d = 1 − u_0 g(κ)/(u_0 + κ), CTF1 =
(1 − d) k U, CDIF = max U/u_0, RF1 at the anchor = −CTF1. The second increment takes d from 0 to
0.974 at once, the last to 1 (κ = 0.21 > Δu_f): d is a function of κ alone, so the increment size
does not change it (the deleted element carries no force in the row of its deletion).
"""
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import damage_lib as dl  # noqa: E402
import golden_lib as g  # noqa: E402

element = dl.ElasticDamage(1000.0, 90.0, ("EXPONENTIAL", 0.2, 5.0))
names = ["CU1@1", "CTF1@1", "CDMG@1", "CDIF@1", "RF1@1"]
rows = [(1, 0, 0.0, 0.0, [0.0] * len(names))]
damage = []
for inc, (t, u) in enumerate([(0.25, 0.08), (0.5, 0.2), (0.75, 0.05), (1.0, 0.3)], start=1):
    f, d, r = element.update(u)
    damage.append(d)
    rows.append((1, inc, t, t, [u, f, d, r, -f]))
# The jump that one DIRECT increment cannot avoid, and the failure at the end.
assert damage[0] == 0.0 and damage[1] - damage[0] > 0.75 and damage[3] == 1.0, damage

g.write_golden(__file__, [
    "cae_damage_direct_jump: AXIAL k = 1000, FORCE initiation at 90, EXPONENTIAL softening",
    "(0.2, 5), U = 0, 0.08, 0.2, 0.05, 0.3 in four DIRECT increments; d = 1 - u_0 g(kappa)/(u_0 +",
    "kappa) from damage_lib.py, CTF1 = (1 - d) k U.",
], names, rows)
