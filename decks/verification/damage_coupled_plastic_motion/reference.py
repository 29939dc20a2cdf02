"""Golden values of damage_coupled_plastic_motion (behaviors.md §6.4, §7.1, §7.2).

Closed form: K = k I and the circular potential P = |(f1, f2)| make the coupled return radial,
so along the fixed direction e = (0.8, 0.6) the connector is a one-dimensional perfectly plastic
spring in s = |u| (damage_lib.PlasticDamage with F_y = 80): ū = Δλ accumulates the plastic part
of s, CDIP = CDIPC = ū/0.02, d = 1 − g(ū − 0.02) with linear g over 0.2 on components 1 and 2
(the components of the plasticity potential), CTF_i = (1 − d) f^eff e_i. Complete failure at
ū = 0.22 (s = 0.30), reached in the row at s = 0.30; the element is deleted after it. From then
on (behaviors.md §7.4, output-variables.md §2) its forces are 0, CUPEQ, CDIP and CDIPC stay at
their values at deletion, CDMG = 1, and CU goes on reporting the prescribed motion s e of node 2
(s = 0.32 in the last row: CU = (0.256, 0.192)).
"""
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import damage_lib as dl  # noqa: E402
import golden_lib as g  # noqa: E402

E = (0.8, 0.6)
law = dl.PlasticDamage(1000.0, 80.0, 0.02, ("LINEAR", 0.2))
path = [(1, 0, 0.0, 0.0, 0.0)]
path += [(1, i, 0.125 * i, 0.125 * i, 0.025 * i) for i in range(1, 9)]
path += [(2, i, 0.5 * i, 1.0 + 0.5 * i, 0.2 - 0.02 * i) for i in (1, 2)]
path += [(3, i, 0.125 * i, 2.0 + 0.125 * i, 0.16 + 0.02 * i) for i in range(1, 9)]
names = ["CU1@1", "CU2@1", "CTF1@1", "CTF2@1", "CUPEQ@1", "CDIP@1", "CDIPC@1", "CDMG@1",
         "CDMG1@1", "CDMG2@1"]
rows, history = [], None  # history: CUPEQ, CDIP, CDIPC, CDMG... frozen at deletion
for step, inc, st, tt, s in path:
    motion = [s * E[0], s * E[1]]  # CU = the prescribed motion of node 2, deleted or not
    if history is not None:
        # Deleted (behaviors.md §7.4, output-variables.md §2): forces 0, the plastic and damage
        # history frozen, CU still the kinematics of the nodes.
        rows.append((step, inc, st, tt, motion + [0.0, 0.0] + history))
        continue
    f, up, ubar, cdip, d, feff = law.update(s) if inc > 0 else (0.0, 0.0, 0.0, 0.0, 0.0, 0.0)
    values = motion + [f * E[0], f * E[1], ubar, cdip, cdip, d, d, d]
    rows.append((step, inc, st, tt, values))
    if d >= 1.0:
        history = values[4:]

dl.check(rows[8][4][7], 0.5, 1e-12, "CDMG at |u| = 0.2")
dl.check(rows[-2][4][7], 1.0, 0.0, "failed at |u| = 0.30")
dl.check(rows[-1][4][0], 0.256, 1e-15, "CU1 of the deleted element at |u| = 0.32")
dl.check(rows[-1][4][1], 0.192, 1e-15, "CU2 of the deleted element at |u| = 0.32")

g.write_golden(__file__, [
    "damage_coupled_plastic_motion: CARTESIAN k = 1000, coupled plasticity P = |(f1, f2)|, F_y = 80,",
    "coupled PLASTIC MOTION damage at 0.02, linear 0.2; U along (0.8, 0.6): |u| -> 0.2 (8 incr.),",
    "-> 0.16 (2), -> 0.32 (8). Radial return: 1D perfect plasticity in |u|; d = 1 - g(ubar - 0.02).",
    "Deleted after |u| = 0.30: forces 0, history frozen, CU = the motion of node 2 (behaviors.md §7.4)",
], names, rows)
