"""Golden values of damage_series: two AXIAL connectors in series, one softening (behaviors.md
§7.2, §7.4), node 3 driven.

Closed form: element 1 (k1 = 1000, u_0 = 0.09, linear softening Δu_f = 0.2) and element 2
(k2 = 2000) carry the same force F. Below the envelope F = (1 − d) k1 u1 = k2 (U − u1), so
u1 = k2 U/((1 − d) k1 + k2); on the envelope F = k1 u_0 (1 − (u1 − u_0)/Δu_f) = 450 (0.29 − u1),
so u1 = (k2 U − 130.5)/(k2 − 450), with d = 1 − u_0 g/(u_0 + κ), κ = u1 − u_0. Past u1 = 0.29
element 1 has failed (d = 1): F = 0 and u1 = U in that increment, after which it is deleted.
Then node 2 is held by element 2 alone: equilibrium k2 (U − U2) = 0 gives U2 = U, so node 2
follows node 3, CU1 of element 2 is 0, and element 1's CU1 = U2 − U1 = U goes on reporting the
kinematics of its nodes (behaviors.md §7.4, output-variables.md §2) while its force is 0.
"""
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import damage_lib as dl  # noqa: E402
import golden_lib as g  # noqa: E402

K1, K2, U0, DUF = 1000.0, 2000.0, 0.09, 0.2

path = [(1, 0, 0.0, 0.0, 0.0)]
path += [(1, i, 0.25 * i, 0.25 * i, 0.05 * i) for i in range(1, 5)]
path += [(2, 1, 1.0, 2.0, 0.1)]
path += [(3, i, i / 6.0, 2.0 + i / 6.0, 0.1 + 0.05 * i) for i in range(1, 7)]

names = ["CU1@1", "CU1@2", "CTF1@1", "CTF1@2", "CDMG@1", "CSLST1@1", "U1@2", "U1@3", "RF1@2", "RF1@3"]
rows = []
d, kappa, deleted = 0.0, None, False
for step, inc, st, tt, u in path:
    if deleted:
        # Element 1 is out of the assembly: node 2 is held by element 2 alone, whose force
        # k2 (U3 − U2) must vanish, so U2 = U3 = U (element 2 moves rigidly with node 3). Element
        # 1's CU1 goes on reporting U2 − U1 = U (behaviors.md §7.4, output-variables.md §2); its
        # force is 0, CDMG = 1, CSLST1 = 4.
        u2 = u
        rows.append((step, inc, st, tt, [u2, u - u2, 0.0, 0.0, 1.0, 4.0, u2, u, 0.0, 0.0]))
        continue
    u1 = K2 * u / ((1.0 - d) * K1 + K2)
    envelope = U0 if kappa is None else U0 + kappa
    if u1 > envelope:
        u1 = (K2 * u - 130.5) / (K2 - 450.0)
        kappa = u1 - U0
        d = max(d, 1.0 - U0 * dl.g_linear(kappa, DUF) / (U0 + kappa))
        if u1 >= U0 + DUF:
            d, u1 = 1.0, u
    f = (1.0 - d) * K1 * u1
    dl.check(f, K2 * (u - u1), 1e-9, f"equilibrium at {tt}")
    rows.append((step, inc, st, tt, [u1, u - u1, f, f, d, 0.0, u1, u, 0.0, f]))
    deleted = d >= 1.0
assert deleted
dl.check(rows[-1][4][0], 0.4, 1e-15, "CU1 of the deleted element 1 at U3 = 0.4")

g.write_golden(__file__, [
    "damage_series: AXIAL k1 = 1000 (FORCE initiation 90, linear softening 0.2) in series with",
    "AXIAL k2 = 2000; U3 0 -> 0.2 (4 incr.), -> 0.1 (1), -> 0.4 (6). Envelope F = 450 (0.29 - u1),",
    "u1 = (k2 U - 130.5)/(k2 - 450); below it u1 = k2 U/((1 - d) k1 + k2); element 1 fails at",
    "U3 = 0.3 and is deleted (behaviors.md §7.2, §7.4); then node 2 follows node 3 (k2 (U3 - U2) = 0)",
    "and element 1's CU1 = U2 - U1 = U3 (output-variables.md §2), its force 0",
], names, rows)
