"""Golden values of damage_force_criterion_stop (behaviors.md §5.1, §7.1: the FORCE criterion on
the total force).

Closed form: AXIAL k = 1000 with an upper stop at u = 0.05, node 2 loaded by F(t). Off the stop
u = F/k; on it (F > 50) u = 0.05, CEF1 = 50 and the stop carries CRF1 = F − 50; CTF1 = F. The
FORCE criterion reads the total force f^eff + CRF1 = F: CDIF = max F/90 (not capped). Damage
initiates when F passes 90 with u held at 0.05 (the initiation point u_0 = 0.05), and
δ = u − u_0 never becomes positive on this path, so CDMG stays 0 and CEF1 is never degraded.
"""
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import damage_lib as dl  # noqa: E402
import golden_lib as g  # noqa: E402

K, STOP, FU = 1000.0, 0.05, 90.0
names = ["CU1@1", "CTF1@1", "CEF1@1", "CRF1@1", "CDMG@1", "CDIF@1", "CSLST1@1"]
rows, r_max = [(1, 0, 0.0, 0.0, [0.0] * 7)], 0.0
for step in (1, 2):
    for inc in range(1, 9):
        st = 0.125 * inc
        f = 150.0 * st if step == 1 else 150.0 - 180.0 * st
        u = min(f / K, STOP)
        at_stop = f / K > STOP
        r_max = max(r_max, f / FU)
        rows.append((step, inc, st, step - 1 + st, [u, f, K * u, f - K * u, 0.0, r_max,
                                                    2.0 if at_stop else 0.0]))
dl.check(r_max, 150.0 / 90.0, 1e-15, "CDIF from the total force")

g.write_golden(__file__, [
    "damage_force_criterion_stop: AXIAL k = 1000, stop at u = 0.05, FORCE initiation at 90 on the",
    "total force (behaviors.md §7.1), load 0 -> 150 -> -30 (8 + 8 incr.): CTF1 = F, CEF1 = min(F, 50),",
    "CRF1 = F - CEF1, CDIF = max F/90; damage initiates at the stop and does not grow (CDMG = 0)",
], names, rows)
