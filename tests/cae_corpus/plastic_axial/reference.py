"""Golden values of plastic_axial: uncoupled plasticity, linear isotropic hardening table."""
import os
import sys

sys.dont_write_bytecode = True  # keep the deck directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from cae_lib import g, ramp_rows, local_components  # noqa: E402,F401

K, F0, H = 1000.0, 100.0, 500.0  # yield 100 at 0, 150 at 0.1 (slope 500), never passed here
names = ["CU1@1", "CTF1@1", "CEF1@1", "CUP1@1", "CUE1@1", "CUPEQ@1", "RF1@Point-1.1", "RF1@Point-2.1"]
states = [(1, 0, 0.0, 0.0, 0.0)]
states += [(s, i, st, tt, 0.2 * tau) for s, i, st, tt, tau in ramp_rows(1, 0.0, 20)]
states += [(s, i, st, tt, 0.2 - 0.2 * tau) for s, i, st, tt, tau in ramp_rows(2, 1.0, 10)]
rows = []
up, ueq = 0.0, 0.0
for step, inc, st, tt, u in states:
    trial = K * (u - up)
    yld = F0 + H * ueq
    if abs(trial) > yld:  # radial return, 1-D linear hardening
        dl = (abs(trial) - yld) / (K + H)
        sign = 1.0 if trial > 0 else -1.0
        up += sign * dl
        ueq += dl
    f = K * (u - up)
    rows.append((step, inc, st, tt, [u, f, f, up, u - up, ueq, -f, f]))
g.write_golden(__file__, [
    "plastic_axial: AXIAL k = 1000, isotropic hardening table (100, 0), (150, 0.1), u1 -> 0.2 in 20 increments,",
    "then back to 0 in 10: elastic to 0.1, then f = 100 + k H/(k + H) (u - 0.1), elastic unloading",
    "closed form: 1-D return mapping with linear hardening (exact per increment)",
], names, rows)
