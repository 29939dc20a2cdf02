"""Golden values of damage_viscous_regularisation (*SECTION CONTROLS, VISCOSITY; keywords.md §5,
docs/decisions.md "Damage").

Closed form: the inviscid E12 law (damage_lib.ElasticDamage: u_0 = 0.09, LINEAR 0.2) gives d at
each row; the regularised damage follows d_v' = (d − d_v)/η, integrated by backward Euler over
each increment Δt = 0.01: d_v,n+1 = (η d_v,n + Δt d_n+1)/(η + Δt), never decreasing, taken as
reaching 1 once within 1e-3 of it (the element is then deleted, as the inviscid one at d = 1).
CTF1 = (1 − d_v) k U. After deletion CTF1 = 0, CDMG = 1 and CU1 goes on reporting the prescribed
motion U of node b (behaviors.md §7.4, output-variables.md §2). The script asserts that the difference from the inviscid history shrinks
in proportion to the viscosity: max |CDMG(η) − CDMG(0)| over the softening rows for η = 2e-4 is
twice that for η = 1e-4 within 3 % (backward Euler gives the ratio 2 (η1 + Δt)/(η2 + Δt) = 1.98
for η ≪ Δt).
"""
import os
import sys

sys.dont_write_bytecode = True  # keep the case directories free of __pycache__

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import damage_lib as dl  # noqa: E402
import golden_lib as g  # noqa: E402

K, DT = 1000.0, 0.01
ETAS = (0.0, 1e-4, 2e-4)
laws = [dl.ElasticDamage(K, 90.0, ("LINEAR", 0.2)) for _ in ETAS]
dv = [0.0] * 3
deleted = [False] * 3

names = [f"CU1@{e}" for e in (1, 2, 3)] + [f"CTF1@{e}" for e in (1, 2, 3)]
names += [f"CDMG@{e}" for e in (1, 2, 3)]
rows = [(1, 0, 0.0, 0.0, [0.0] * 9)]
histories = [[], [], []]
energy, excess_old = [0.0] * 3, [0.0] * 3
u_old = 0.0
for inc in range(1, 101):
    t = inc * DT
    u = 0.35 * t
    cu, ctf, dmg = [], [], []
    for e, eta in enumerate(ETAS):
        if deleted[e]:
            # behaviors.md §7.4, output-variables.md §2: no force, CDMG = 1, and CU1 goes on
            # reporting the prescribed motion of node b.
            cu.append(u)
            ctf.append(0.0)
            dmg.append(1.0)
            continue
        _, d, _ = laws[e].update(u)
        if eta > 0.0:
            v = max(dv[e], (eta * dv[e] + DT * d) / (eta + DT))
            v = 1.0 if v >= 1.0 - 1e-3 else v
            # The regularisation energy the log reports: the work of (d - d_v) f^eff along U.
            excess = (d - v) * K * u
            energy[e] += 0.5 * (excess + excess_old[e]) * (u - u_old)
            excess_old[e] = excess
            d = v
        dv[e] = d
        cu.append(u)
        ctf.append((1.0 - d) * K * u)
        dmg.append(d)
        histories[e].append(d)
        deleted[e] = d >= 1.0
    rows.append((1, inc, t, t, cu + ctf + dmg))
    u_old = u

# The rows where all three soften (none has failed yet).
softening = [i for i in range(len(histories[2])) if 0.0 < histories[0][i] < 1.0 and histories[2][i] < 1.0]
gap1 = max(abs(histories[1][i] - histories[0][i]) for i in softening)
gap2 = max(abs(histories[2][i] - histories[0][i]) for i in softening)
dl.check(gap2 / gap1, 2.0, 0.06, "difference from the inviscid history against the viscosity")

dl.check(energy[2] / energy[1], 2.0, 0.06, "regularisation energy against the viscosity")
for e in range(3):
    dl.check(rows[-1][4][e], 0.35, 1e-15, f"CU1 of the deleted element {e + 1} at the end")

g.write_golden(__file__, [
    "damage_viscous_regularisation: three AXIAL connectors with the E12 law (k = 1000, FORCE 90,",
    "LINEAR 0.2), U 0 -> 0.35 in 100 DIRECT increments (dt = 0.01). VISCOSITY 0, 1e-4, 2e-4:",
    "d_v = (eta d_v,n + dt d)/(eta + dt), 1 within 1e-3. Max |CDMG(eta) - CDMG(0)| while softening:",
    f"{gap1:.6e} (eta = 1e-4), {gap2:.6e} (eta = 2e-4), ratio {gap2 / gap1:.4f}. Regularisation",
    f"energy (work of (d - d_v) f^eff): {energy[1]:.6e}, {energy[2]:.6e}, total {energy[1] + energy[2]:.6g}.",
    "Deleted elements: CTF1 = 0, CDMG = 1, CU1 = the motion of node b (behaviors.md §7.4)",
], names, rows)
