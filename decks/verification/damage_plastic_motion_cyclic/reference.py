"""Golden values of damage_plastic_motion_cyclic (behaviors.md §6.3, §7.1–§7.3, §7.5 E14).

Closed form (damage_lib.PlasticDamage): perfectly plastic backward-Euler return (F_y = 80,
k = 1000; Δλ = (|F_tr| − F_y)/k), ū accumulating Δλ in both directions, CDIP = ū/ū_0 with
ū_0 = 0.05, δ = ū − ū_0, d = 1 − g(δ) with linear g (plasticity is integrated in effective
space, so the effective force stays on the yield surface, §7.3), CTF1 = (1 − d) f^eff. Asserts
the §7.5 E14 table and its unloading figures. After deletion (behaviors.md §7.4,
output-variables.md §2) an element's CTF1 is 0, CDMG = 1, CUP1, CUPEQ and CDIP stay at their
values at deletion, and CU1 goes on reporting the prescribed motion of its node b (element 1 is
held at 0.25; element 2 follows its node to 0.16).
"""
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import damage_lib as dl  # noqa: E402
import golden_lib as g  # noqa: E402

K, FY = 1000.0, 80.0
e14 = dl.PlasticDamage(K, FY, 0.05, ("LINEAR", 0.1))
cyclic = dl.PlasticDamage(K, FY, 0.05, ("LINEAR", 0.3))

# (step, increment, step time, total time, U@2, U@4)
path = [(1, 0, 0.0, 0.0, 0.0, 0.0)]
path += [(1, i, 0.2 * i, 0.2 * i, 0.05 * i, 0.024 * i) for i in range(1, 6)]
targets = [0.12, -0.12, 0.14, -0.1, 0.16]
for s in range(2, 6):
    a, b = targets[s - 2], targets[s - 1]
    path += [(s, i, i / 6.0, s - 1 + i / 6.0, 0.25, a + (b - a) * i / 6.0) for i in range(1, 7)]

names = []
for e in (1, 2):
    names += [f"{v}@{e}" for v in ("CU1", "CTF1", "CUP1", "CUPEQ", "CDIP", "CDMG")]
rows, e14_rows = [], {}
history = [None, None]  # CUP1, CUPEQ, CDIP of a deleted element, frozen at deletion
for step, inc, st, tt, u2, u4 in path:
    values = []
    for e, (el, u) in enumerate(((e14, u2), (cyclic, u4))):
        if history[e] is not None:
            # Deleted (behaviors.md §7.4, output-variables.md §2): force 0, plastic and damage
            # history frozen, CDMG = 1; CU1 goes on reporting the prescribed motion of node b.
            values += [u, 0.0] + history[e] + [1.0]
            continue
        if inc == 0:
            out = [0.0] * 6
        else:
            f, up, ubar, cdip, d, feff = el.update(u)
            out = [u, f, up, ubar, cdip, d]
            if e == 0:
                e14_rows[round(u, 6)] = (ubar, cdip, d, f)
            if d >= 1.0:  # deleted at the end of this increment (§7.4)
                history[e] = [up, ubar, cdip]
        values += out
    rows.append((step, inc, st, tt, values))

# §7.5 E14: U → (CUPEQ, CDIP, CDMG, CTF1).
for u, want in {0.05: (0, 0, 0, 50), 0.10: (0.02, 0.4, 0, 80), 0.15: (0.07, 1.4, 0.2, 64),
                0.20: (0.12, 2.4, 0.7, 24), 0.25: (0.17, 3.4, 1.0, 0)}.items():
    for got, exp, what in zip(e14_rows[u], want, ("CUPEQ", "CDIP", "CDMG", "CTF1")):
        dl.check(got, exp, 1e-9, f"E14 {what} at {u}")
# §7.5: unloading from U = 0.20 to 0.15 gives f^eff = 30 and CTF1 = 9.
probe = dl.PlasticDamage(K, FY, 0.05, ("LINEAR", 0.1))
for u in (0.05, 0.10, 0.15, 0.20):
    probe.update(u)
f, up, ubar, cdip, d, feff = probe.update(0.15)
dl.check(feff, 30.0, 1e-9, "E14 unloading f^eff")
dl.check(f, 9.0, 1e-9, "E14 unloading CTF1")
dl.check(rows[-1][4][6], 0.16, 1e-15, "CU1 of the deleted element 2 at the end")

g.write_golden(__file__, [
    "damage_plastic_motion_cyclic: AXIAL k = 1000, F_y = 80 perfectly plastic, PLASTIC MOTION",
    "initiation at 0.05, linear softening. Element 1 = E14 (0.1; U -> 0.25 in 5 incr., deleted).",
    "Element 2 (0.3): U 0 -> 0.12 -> -0.12 -> 0.14 -> -0.1 -> 0.16 (5 and 6 incr. per leg),",
    "fails and is deleted at U = 0.116667. Backward-Euler return (§6.3), d = 1 - g(ubar - 0.05).",
    "Deleted: CTF1 = 0, CDMG = 1, CUP1, CUPEQ, CDIP frozen, CU1 = the motion of node b (§7.4)",
], names, rows)
