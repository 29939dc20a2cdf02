"""Golden values of coupled_cartesian_print: 21-term coupled elasticity on CARTESIAN."""
import os
import sys

sys.dont_write_bytecode = True  # keep the deck directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from cae_lib import g, ramp_rows, local_components  # noqa: E402,F401

# Column-wise upper triangle (behaviors.md §4.3): D11, D12, D22, D13, D23, D33, ...
D = [[1000.0, 200.0, 0.0], [200.0, 500.0, 0.0], [0.0, 0.0, 800.0]]
C = [0.01, 0.02, 0.0]
names = ["CTF1@1", "CTF2@1", "CTF3@1", "CU1@1", "CU2@1", "CU3@1",
         "RF1@Point-1.1", "RF2@Point-1.1", "RF3@Point-1.1"]
rows = [(1, 0, 0.0, 0.0, [0.0] * 9)]
f = g.matvec(D, C)
rows.append((1, 1, 1.0, 1.0, f + C + g.scale(-1.0, f)))
g.write_golden(__file__, [
    "coupled_cartesian_print: CARTESIAN, coupled elasticity D11 = 1000, D12 = 200, D22 = 500, D33 = 800",
    "closed form: CU = u_b = (0.01, 0.02, 0), CTF = D CU = (14, 12, 0), RF(a) = -CTF",
], names, rows)
