"""Golden values of connector_failure (behaviors.md §5.3, example E6).

Closed form: linear elasticity k = 1000 on every component, nodes driven linearly in time, so
CTF_i = k U_i until the failure criterion (CTF1 >= 140) is met on a converged increment (t = 0.75,
CTF1 = 150); that increment is solved again with the released components free: their force is 0
from that row on (CSLST = 4) and the reactions they carried vanish. Element 1 releases ALL (its
only component); element 2 releases component 2 only, component 1 goes on elastically.
"""
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import damage_lib as dl  # noqa: E402
import golden_lib as g  # noqa: E402

K, LIMIT = 1000.0, 140.0
names = ["CU1@1", "CTF1@1", "CSLST1@1", "CU1@2", "CU2@2", "CTF1@2", "CTF2@2", "CSLST1@2",
         "CSLST2@2", "RF1@2", "RF1@4", "RF2@2", "RF2@4"]
rows, failed = [(1, 0, 0.0, 0.0, [0.0] * len(names))], False
for inc in range(1, 5):
    t = 0.25 * inc
    u1, v1, v2 = 0.2 * t, 0.2 * t, 0.1 * t
    failed = failed or K * u1 >= LIMIT  # met on this converged state: re-solved released
    f1 = 0.0 if failed else K * u1
    g1, g2 = K * v1, 0.0 if failed else K * v2
    s = 4.0 if failed else 0.0
    rows.append((1, inc, t, t, [u1, f1, s, v1, v2, g1, g2, 0.0, s, f1, g1, 0.0, g2]))

# §5.3 E6: CTF1 = 50, 100, then 0 (failure detected at 150 and re-solved), 0; RF1@2 = 0.
for inc, want in ((1, 50.0), (2, 100.0), (3, 0.0), (4, 0.0)):
    dl.check(rows[inc][4][1], want, 1e-12, f"E6 CTF1 at increment {inc}")

g.write_golden(__file__, [
    "connector_failure: element 1 = E6 (AXIAL k = 1000, failure at CTF1 >= 140, RELEASE=ALL, U -> 0.2",
    "in 4 incr.); element 2 CARTESIAN k = 1000, failure at CTF1 >= 140 releasing component 2, U = t",
    "(0.2, 0.1, 0). Met at t = 0.75 (CTF1 = 150), that increment re-solved with the released",
    "components free (behaviors.md §5.3)",
], names, rows)
