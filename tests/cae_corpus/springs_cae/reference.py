"""Golden values of springs_cae: SPRING1, SPRING2, SPRINGA in Abaqus/CAE layout."""
import os
import sys

sys.dont_write_bytecode = True  # keep the deck directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from cae_lib import g, ramp_rows, local_components  # noqa: E402,F401

N0 = [0.6, 0.8, 0.0]  # SPRINGA from (0, 5, 0) to (3, 9, 0)
U5 = [0.03, 0.01, 0.02]
names = ["S11@1", "S11@2", "S11@3", "E11@1", "E11@2", "E11@3",
         "U1@Point-1.1", "U1@Point-2.1", "U1@Point-3.1", "U1@Point-5.1",
         "RF1@Point-1.1", "RF1@Point-2.1", "RF1@Point-3.1", "RF1@Point-5.1"]
rows = []
for step, inc, st, tt, tau in [(1, 0, 0.0, 0.0, 0.0)] + ramp_rows(1, 0.0, 2):
    f1, f2 = 10.0 * tau, 20.0 * tau       # SPRING1 k = 100, SPRING2 k = 200 (node 2 loaded)
    d3 = g.dot(N0, g.scale(tau, U5))      # SPRINGA, NLGEOM=NO: n0.(u2 - u1)
    f3 = 1000.0 * d3
    rows.append((step, inc, st, tt, [f1, f2, f3, f1 / 100.0, f2 / 200.0, d3,
                                     f1 / 100.0, f2 / 200.0, 0.0, 0.03 * tau,
                                     0.0, 0.0, -f2, f3 * N0[0]]))
g.write_golden(__file__, [
    "springs_cae: SPRING1 k = 100 (load 10), SPRING2 dofs 1-1 k = 200 (load 20 on the first node, second held),",
    "SPRINGA k = 1000 from (0,5,0) to (3,9,0) with the far end moved by (0.03, 0.01, 0.02)",
    "closed form: S11 = F, E11 = F/k; SPRINGA E11 = n0.u = 0.026, RF1 = S11 n0_x; SPRING2 RF1(second) = -F",
], names, rows)
