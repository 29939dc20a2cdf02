"""Golden values of damage_series: two AXIAL connectors in series, one softening (behaviors.md
§7.2, §7.4), node 3 driven.

Closed form: element 1 (k1 = 1000, u_0 = 0.09, linear softening Δu_f = 0.2) and element 2
(k2 = 2000) carry the same force F. Below the envelope F = (1 − d) k1 u1 = k2 (U − u1), so
u1 = k2 U/((1 − d) k1 + k2); on the envelope F = k1 u_0 (1 − (u1 − u_0)/Δu_f) = 450 (0.29 − u1),
so u1 = (k2 U − 130.5)/(k2 − 450), with d = 1 − u_0 g/(u_0 + κ), κ = u1 − u_0. Past u1 = 0.29
element 1 has failed (d = 1): F = 0 and u1 = U in that increment, after which it is deleted and
its CU1 stays at the failure value while node 2 follows node 3.
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
d, kappa, deleted, frozen = 0.0, None, False, 0.0
for step, inc, st, tt, u in path:
    if deleted:
        rows.append((step, inc, st, tt, [frozen, 0.0, 0.0, 0.0, 1.0, 4.0, u, u, 0.0, 0.0]))
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
    if d >= 1.0:
        deleted, frozen = True, u1
assert deleted

g.write_golden(__file__, [
    "damage_series: AXIAL k1 = 1000 (FORCE initiation 90, linear softening 0.2) in series with",
    "AXIAL k2 = 2000; U3 0 -> 0.2 (4 incr.), -> 0.1 (1), -> 0.4 (6). Envelope F = 450 (0.29 - u1),",
    "u1 = (k2 U - 130.5)/(k2 - 450); below it u1 = k2 U/((1 - d) k1 + k2); element 1 fails at",
    "U3 = 0.3 and is deleted (behaviors.md §7.2, §7.4)",
], names, rows)
