"""Load control past a softening peak stops cleanly (behaviors.md §7.4 (2), cli-contract.md exit
status 2): decks/verification/damage_series/damage_series_load_control.inp must exit 2, its .sta
must end with a FAILED line that names the step, increment, time, the softening element and the
cause, and the history must hold every converged row (each in equilibrium with the ramped load,
CTF1 = 100 t to 1e-9, CDMG = 0 below the peak) up to just below the peak time t = 0.9.
Usage: damage_load_control_stop.py CLINCH DECK WORK_DIR
"""
import csv
import os
import re
import subprocess
import sys

clinch, deck, work = sys.argv[1:4]
os.makedirs(work, exist_ok=True)
job = os.path.splitext(os.path.basename(deck))[0]
status = subprocess.run([clinch, "run", "--quiet", "--out", work, deck]).returncode
failures = []
if status != 2:
    failures.append(f"exit status {status}, expected 2")
last = open(os.path.join(work, job + ".sta"), encoding="utf-8").read().splitlines()[-1]
pattern = (r"^FAILED: .*connector element 1 softening \(d=[0-9.e+-]+\) under load control, "
           r"limit point passed\? \(step 1, increment \d+, time 0\.(89|9)\d*\)$")
if not re.match(pattern, last):
    failures.append(f"status line: {last!r}")
rows = list(csv.DictReader(open(os.path.join(work, job + ".history.csv"), encoding="utf-8")))
for row in rows:
    t = float(row["total_time"])
    if abs(float(row["CTF1@1"]) - 100.0 * t) > 1e-9 * 100.0 or float(row["CDMG@1"]) != 0.0:
        failures.append(f"row at t = {t} is not the converged elastic state: {row}")
if len(rows) < 5 or float(rows[-1]["total_time"]) < 0.899:
    failures.append(f"the converged rows up to the peak are missing (last t = {rows[-1]['total_time']})")
for f in failures:
    print("FAIL:", f)
print(f"{len(rows)} rows, last at t = {rows[-1]['total_time']}; status: {last}")
sys.exit(1 if failures else 0)
