"""Golden values of damage_friction: damage and friction in one connector (behaviors.md §1.3,
§7.3: damage degrades the elastic force only; friction.md §4).

Closed form: friction on component 1 with a constant internal contact force, F_lim = 0.3 * 100 =
30 and stick stiffness K_s = 1e4, is a one-dimensional elastic-perfectly-plastic spring (exact
at the ends of monotonic increments): f_s = K_s (u - u_s), |f_s| <= 30. Damage: MOTION initiation
at u_0 = 0.09 (exact: r = u/0.09 is linear), linear softening Δu_f = 0.2,
d = 1 - u_0 (1 - κ/Δu_f)/(u_0 + κ), CEF1 = (1 - d) k u. CTF1 = CEF1 + CSF1. At u = 0.3 the elastic
force has failed (d = 1) while friction still carries 30; the element is deleted at the end of
that increment, after which every force is 0, CDMG = 1, CDIM stays frozen, CSLST1 = 4, and CU1
goes on reporting the prescribed motion of node 2 (behaviors.md §7.4, output-variables.md §2).
"""
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import damage_lib as dl  # noqa: E402
import golden_lib as g  # noqa: E402

K, KS, FLIM = 1000.0, 1.0e4, 30.0
damage = dl.ElasticDamage(K, 90.0, ("LINEAR", 0.2))  # MOTION limit 0.09 = FORCE limit 90 / k

path = [(1, 0, 0.0, 0.0, 0.0)]
path += [(1, i, 0.25 * i, 0.25 * i, 0.05 * i) for i in range(1, 5)]
path += [(2, i, 0.5 * i, 1.0 + 0.5 * i, 0.2 - 0.05 * i) for i in (1, 2)]
path += [(3, i, 0.2 * i, 2.0 + 0.2 * i, 0.1 + 0.05 * i) for i in range(1, 6)]

names = ["CU1@1", "CTF1@1", "CEF1@1", "CSF1@1", "CDMG@1", "CDIM@1", "CSLST1@1", "RF1@2"]
rows, slip, deleted = [], 0.0, False
for step, inc, st, tt, u in path:
    if deleted:
        # behaviors.md §7.4, output-variables.md §2: every force 0 (friction included), CDMG = 1,
        # CDIM frozen, CSLST1 = 4; CU1 goes on reporting the prescribed motion of node 2.
        rows.append((step, inc, st, tt, [u, 0.0, 0.0, 0.0, 1.0, damage.r_max, 4.0, 0.0]))
        continue
    trial = KS * (u - slip)
    if abs(trial) > FLIM:
        f_s = FLIM if trial > 0 else -FLIM
        slip = u - f_s / KS
    else:
        f_s = trial
    f_e, d, r = damage.update(u) if inc > 0 else (0.0, 0.0, 0.0)
    rows.append((step, inc, st, tt, [u, f_e + f_s, f_e, f_s, d, r, 0.0, f_e + f_s]))
    deleted = d >= 1.0

# §7.5 E12 (the same law): CEF1 = 85.5, 63, 40.5 at U = 0.1, 0.15, 0.2; friction undegraded.
dl.check(rows[2][4][2], 85.5, 1e-9, "CEF1 at U = 0.1")
dl.check(rows[4][4][2], 40.5, 1e-9, "CEF1 at U = 0.2")
dl.check(rows[4][4][3], FLIM, 0.0, "CSF1 while damaged")
dl.check(rows[-1][4][0], 0.35, 1e-15, "CU1 of the deleted element at U = 0.35")

g.write_golden(__file__, [
    "damage_friction: AXIAL k = 1000, MOTION damage at 0.09, linear softening 0.2, friction",
    "COMPONENT=1 with F_int = 100, mu = 0.3, K_s = 1e4. U 0 -> 0.2 (4 incr.), -> 0.1 (2), -> 0.35 (5).",
    "CEF1 = (1 - d) k U (behaviors.md §7.2), CSF1 = elastic-perfectly-plastic stick/slip (friction.md",
    "§4), CTF1 = CEF1 + CSF1; elastic part fails at U = 0.3, element deleted after that increment:",
    "then forces 0, CDMG = 1, CDIM frozen, CSLST1 = 4, CU1 = the motion of node 2 (§7.4)",
], names, rows)
