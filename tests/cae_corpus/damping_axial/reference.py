"""Golden values of damping_axial: linear connector damping in *STATIC, v = du/dt."""
import os
import sys

sys.dont_write_bytecode = True  # keep the deck directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from cae_lib import g, ramp_rows, local_components  # noqa: E402,F401

K, C = 1000.0, 50.0
names = ["CU1@1", "CEF1@1", "CVF1@1", "CTF1@1", "RF1@Point-1.1", "RF1@Point-2.1"]
rows = [(1, 0, 0.0, 0.0, [0.0] * 6)]
for step, inc, st, tt, u, v in ([(s, i, st, tt, 0.1 * tau, 0.1) for s, i, st, tt, tau in ramp_rows(1, 0.0, 4)]
                                + [(s, i, st, tt, 0.1 + 0.2 * tau, 0.4)
                                   for s, i, st, tt, tau in ramp_rows(2, 1.0, 4, 0.5)]):
    fe, fv = K * u, C * v
    rows.append((step, inc, st, tt, [u, fe, fv, fe + fv, -(fe + fv), fe + fv]))
g.write_golden(__file__, [
    "damping_axial: AXIAL k = 1000, c = 50; u1 -> 0.1 over 1 (v = 0.1), then -> 0.3 over 0.5 (v = 0.4)",
    "closed form: CEF1 = k u, CVF1 = c du/dt (behaviors.md §8, corrected 2026-12-02), CTF1 = CEF1 + CVF1",
], names, rows)
