"""Golden values of slot_stop: SLOT with elasticity and an upper stop on component 1 (behaviors.md
§5.1, example E4), lateral load carried by the SLOT constraint."""
import os
import sys

sys.dont_write_bytecode = True  # keep the deck directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from cae_lib import g, ramp_rows  # noqa: E402

K, UPPER = 1000.0, 0.1  # nodes coincide, so the position p1 = CU1
names = ["CU1@1", "CEF1@1", "CRF1@1", "CTF1@1", "CSLST1@1", "CTF2@1", "CRF2@1",
         "U1@Point-2.1", "U2@Point-2.1"]
# (step, inc, step_time, total_time, load along e1, load along e2)
states = [(1, 0, 0.0, 0.0, 0.0, 0.0)]
states += [(s, i, st, tt, 300.0 * tau, 60.0 * tau) for s, i, st, tt, tau in ramp_rows(1, 0.0, 4)]
states += [(s, i, st, tt, 300.0 + (50.0 - 300.0) * tau, 60.0)
           for s, i, st, tt, tau in ramp_rows(2, 1.0, 2)]
rows = []
for step, inc, st, tt, f1, f2 in states:
    u = min(f1 / K, UPPER)
    crf = f1 - K * u
    status = 2.0 if crf > 0.0 else 0.0
    rows.append((step, inc, st, tt, [u, K * u, crf, f1, status, f2, f2, u, 0.0]))
g.write_golden(__file__, [
    "slot_stop: SLOT, k1 = 1000, stop upper 0.1 on component 1, load 300 then 50 along e1, 60 along e2",
    "closed form: CU1 = min(F1/k, 0.1), CEF1 = k CU1, CRF1 = F1 - CEF1, CTF1 = F1, CSLST1 = 2 at the stop,",
    "CTF2 = CRF2 = F2 (SLOT constraint), U2 = 0",
], names, rows)
