"""*STATIC, STABILIZE on a load-controlled spot weld past its peak (docs/stabilization.md).

The weld (BUSHING, k = 1e5, FORCE damage initiation at 800, exponential softening over 0.02 with
a = 3) shears beside the sheet around it (CARTESIAN, k_s = 9e4) under a force ramped to 2000.
The equilibrium path F(u) = k_s u + F_weld(u) (F_weld from decks/verification/damage_lib.py,
written from the spec) peaks at u = 0.008, F = 1520, falls by 2.5 % and rises again: a limit
point that load control cannot pass. Checked here:

- without STABILIZE the run stops at the peak (exit 2) and the FAILED line names the limit point
  and STABILIZE among the remedies;
- the same deck as *STATIC, RIKS follows the path through the valley (every point on it to 1e-8
  of the peak load), ending where u1 crosses 0.02;
- with STABILIZE (the defaults: dissipated energy fraction 2e-4, adaptive with ALLSDTOL 0.05) it
  completes; at every converged row ALLSD <= 0.05 ALLIE (the fraction the manual names), the
  applied load CF1 differs from the path at the row's displacement by at most 0.05 of the peak
  load (the viscous force is the difference), the reaction of the held node equals the path to
  Newton's tolerance, and ETOTAL = ALLIE + ALLSD - ALLWK stays within the residual tolerance
  R_n = 5e-3 of the work (each end of an increment is in equilibrium to R_n of the forces).

usage: check_stabilized_weld.py CLINCH DECK WORKDIR
"""
import csv
import os
import re
import subprocess
import sys

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "decks",
                                "verification"))
import damage_lib  # noqa: E402

SHEET, PEAK, FRACTION = 9.0e4, 800.0 + 9.0e4 * 0.008, 0.05

clinch, deck, work = sys.argv[1:4]
os.makedirs(work, exist_ok=True)
failures = []


def run(path):
    return subprocess.run([clinch, "run", "--quiet", "--out", work, path],
                          capture_output=True, text=True).returncode


plain = os.path.join(work, "unstabilized_weld.inp")
with open(deck, encoding="utf-8") as src, open(plain, "w", encoding="utf-8") as dst:
    dst.write(src.read().replace("*STATIC, STABILIZE", "*STATIC"))
status = run(plain)
last = open(os.path.join(work, "unstabilized_weld.sta"), encoding="utf-8").read().splitlines()[-1]
if status != 2 or not re.search(r"^FAILED: .*a limit point.*\*STATIC, STABILIZE", last):
    failures.append(f"without STABILIZE: exit {status}, status line {last!r}")

riks = os.path.join(work, "riks_weld.inp")
with open(deck, encoding="utf-8") as src, open(riks, "w", encoding="utf-8") as dst:
    dst.write(src.read().replace("*STATIC, STABILIZE\n0.05, 1., 1e-05, 0.05",
                                 "*STATIC, RIKS\n0.05, 1., 1e-05, 0.05, , 2, 1, 0.02"))
status = run(riks)
riks_rows = list(csv.DictReader(open(os.path.join(work, "riks_weld.history.csv"),
                                     encoding="utf-8")))
riks_weld = damage_lib.ElasticDamage(1.0e5, 800.0, ("EXPONENTIAL", 0.02, 3.0))
riks_worst = max(abs(2000.0 * float(r["LPF"]) - SHEET * float(r["U1@2"])
                     - riks_weld.update(float(r["U1@2"]))[0]) for r in riks_rows) / PEAK
riks_u = [float(r["U1@2"]) for r in riks_rows]
valley = min(2000.0 * float(r["LPF"]) for r in riks_rows if float(r["U1@2"]) > 0.008)
if status != 0 or riks_worst > 1e-8 or max(riks_u) < 0.02 or valley > PEAK * (1 - 0.02):
    failures.append(f"RIKS: exit {status}, off the path by {riks_worst:.3g} of the peak, "
                    f"largest u1 {max(riks_u):.4g}, valley at {valley:.6g}")

status = run(deck)
job = os.path.splitext(os.path.basename(deck))[0]
if status != 0:
    failures.append(f"with STABILIZE: exit {status}")
rows = list(csv.DictReader(open(os.path.join(work, job + ".history.csv"), encoding="utf-8")))
weld = damage_lib.ElasticDamage(1.0e5, 800.0, ("EXPONENTIAL", 0.02, 3.0))
worst_load = worst_ratio = worst_balance = worst_reaction = 0.0
for row in rows:
    u, load = float(row["U1@2"]), float(row["CF1@2"])
    path = SHEET * u + weld.update(u)[0]
    allie, allsd, allwk = (float(row[k]) for k in ("ALLIE", "ALLSD", "ALLWK"))
    worst_load = max(worst_load, abs(load - path) / PEAK)
    worst_reaction = max(worst_reaction, abs(-float(row["RF1@1"]) - path) / PEAK)
    if allie > 0:
        worst_ratio = max(worst_ratio, allsd / allie)
    if allwk > 0:
        worst_balance = max(worst_balance, abs(float(row["ETOTAL"])) / allwk)
if worst_load > FRACTION:
    failures.append(f"the load differs from the path by {worst_load:.3g} of the peak load")
if worst_reaction > 1e-6:
    failures.append(f"the reaction differs from the path by {worst_reaction:.3g} of the peak")
if worst_ratio > FRACTION:
    failures.append(f"ALLSD reached {worst_ratio:.3g} of ALLIE")
if worst_balance > 5e-3:
    failures.append(f"ETOTAL reached {worst_balance:.3g} of ALLWK")
if float(rows[-1]["step_time"]) != 1.0 or float(rows[-1]["CDMG@1"]) < 0.9:
    failures.append(f"the step did not end past the weld's failure: {rows[-1]}")

print(f"RIKS: {len(riks_rows) - 1} increments on the path to {riks_worst:.3g}, valley "
      f"{valley:.6g} ({1 - valley / PEAK:.3g} below the peak)")
print(f"STABILIZE: {len(rows) - 1} increments; load - path <= {worst_load:.3g} of the peak; "
      f"reaction - path <= {worst_reaction:.3g}; ALLSD/ALLIE <= {worst_ratio:.3g}; "
      f"|ETOTAL|/ALLWK <= {worst_balance:.3g}; final CDMG {float(rows[-1]['CDMG@1']):.4f}")
for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
