"""Golden values of damage_coupled_plastic_motion (behaviors.md §6.4, §7.1, §7.2).

Closed form: K = k I and the circular potential P = |(f1, f2)| make the coupled return radial,
so along the fixed direction e = (0.8, 0.6) the connector is a one-dimensional perfectly plastic
spring in s = |u| (damage_lib.PlasticDamage with F_y = 80): ū = Δλ accumulates the plastic part
of s, CDIP = CDIPC = ū/0.02, d = 1 − g(ū − 0.02) with linear g over 0.2 on components 1 and 2
(the components of the plasticity potential), CTF_i = (1 − d) f^eff e_i. Complete failure at
ū = 0.22 (s = 0.30), reached in the row at s = 0.30; the element is deleted after it.
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
rows, frozen = [], None
for step, inc, st, tt, s in path:
    if frozen is not None:
        rows.append((step, inc, st, tt, frozen))
        continue
    f, up, ubar, cdip, d, feff = law.update(s) if inc > 0 else (0.0, 0.0, 0.0, 0.0, 0.0, 0.0)
    values = [s * E[0], s * E[1], f * E[0], f * E[1], ubar, cdip, cdip, d, d, d]
    rows.append((step, inc, st, tt, values))
    if d >= 1.0:
        frozen = values[:2] + [0.0, 0.0] + values[4:]

dl.check(rows[8][4][7], 0.5, 1e-12, "CDMG at |u| = 0.2")
dl.check(rows[-2][4][7], 1.0, 0.0, "failed at |u| = 0.30")

g.write_golden(__file__, [
    "damage_coupled_plastic_motion: CARTESIAN k = 1000, coupled plasticity P = |(f1, f2)|, F_y = 80,",
    "coupled PLASTIC MOTION damage at 0.02, linear 0.2; U along (0.8, 0.6): |u| -> 0.2 (8 incr.),",
    "-> 0.16 (2), -> 0.32 (8). Radial return: 1D perfect plasticity in |u|; d = 1 - g(ubar - 0.02)",
], names, rows)
