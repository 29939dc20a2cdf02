"""Predefined SLOT friction without a normal load (friction.md §4.1 step 5): the run of
tests/run/friction_slot_zero_contact.inp completes and gives zero friction.

The deck: a CONN2D2 SLOT at 20° (e1 = (cos 20°, sin 20°)), mu = 0.25, k = 1e4, node a encastré,
node b driven in X by U1 = X_END·t/T with Y free, DIRECT increments of 0.001 up to T = 0.01451956
(the last one shortened). Equilibrium of b in Y is f1 sin20° + f2 cos20° = 0 with |f1| ≤ mu |f2|;
since mu tan20° < 1 its only solution is f1 = f2 = 0: the contact force f2 is a constraint
reaction that is zero up to round-off, and so is the friction capacity. Every row must then have
  CSF1, CTF1, CTF2, CNF1, RF1, RF2 = 0 to FORCE_TOL,
  CU1 = U1/cos20°, U2 = U1·tan20° (the slot constraint) and U1 = X_END·t/T, to 1e-12 relative,
  CSLIPST1 = 1 and CASU1 = CU1 after the start (all of the motion is slip, §4.1 step 5; §6).
FORCE_TOL = 1e-11: the stick test resolves the trial force k·Δu = 10 of one increment to 1e-12
of itself (§4.1 step 3), so a capacity or force below that is zero.

Usage: friction_zero_contact_check.py CLINCH DECK WORK_DIR
"""
import csv
import math
import os
import subprocess
import sys

X_END, PERIOD = 0.01364392339, 0.01451956
FORCE_TOL = 1e-11
MOTION_RTOL = 1e-12

clinch, deck, work = sys.argv[1:4]
os.makedirs(work, exist_ok=True)
job = os.path.splitext(os.path.basename(deck))[0]
status = subprocess.run([clinch, "run", "--quiet", "--out", work, deck],
                        stderr=subprocess.DEVNULL).returncode
failures = []
if status != 0:
    failures.append(f"exit status {status}, expected 0")
last = open(os.path.join(work, job + ".sta"), encoding="utf-8").read().splitlines()[-1]
if last != "COMPLETED":
    failures.append(f"status line: {last!r}")
rows = list(csv.DictReader(open(os.path.join(work, job + ".history.csv"), encoding="utf-8")))
if len(rows) != 16:  # the start and 15 increments
    failures.append(f"{len(rows)} history rows, expected 16")
c, s = math.cos(math.radians(20.0)), math.sin(math.radians(20.0))
for row in rows:
    t = float(row["step_time"])
    where = f"increment {row['increment']} (t = {t})"
    for name in ("CSF1@1", "CTF1@1", "CTF2@1", "CNF1@1", "RF1@Point-2.1", "RF2@Point-2.1"):
        if abs(float(row[name])) > FORCE_TOL:
            failures.append(f"{where}: {name} = {row[name]}, expected 0")
    u1 = X_END * t / PERIOD
    expected = {"U1@Point-2.1": u1, "U2@Point-2.1": u1 * s / c, "CU1@1": u1 / c}
    if t > 0:
        expected["CASU1@1"] = u1 / c
    for name, value in expected.items():
        if abs(float(row[name]) - value) > MOTION_RTOL * X_END:
            failures.append(f"{where}: {name} = {row[name]}, expected {value!r}")
    if float(row["CSLIPST1@1"]) != (1.0 if t > 0 else 0.0):
        failures.append(f"{where}: CSLIPST1 = {row['CSLIPST1@1']}")
for f in failures:
    print(f)
sys.exit(1 if failures else 0)
