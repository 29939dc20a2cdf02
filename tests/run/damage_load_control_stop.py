"""Load control past a softening peak stops cleanly (behaviors.md §7.4 (2), cli-contract.md exit
status 2). The deck (decks/verification/damage_series/damage_series_load_control*.inp) must exit
2, its .sta must end with a FAILED line that names the step, increment, time, the connector and
the cause, and the history must hold every converged row, each in equilibrium with the ramped
load (CTF1 = RATE t to 1e-9, RATE the load per unit time) and undamaged before the inviscid peak
time T = 90/RATE.
Without --past: the last row lies just below T (no equilibrium past the peak), and the cause is
the softening connector. With --past: viscous regularisation carries the run beyond T before
element 1 fails completely and leaves its nodes without support.
Usage: damage_load_control_stop.py CLINCH DECK WORK_DIR [--rate RATE] [--past]
"""
import csv
import os
import re
import subprocess
import sys

clinch, deck, work = sys.argv[1:4]
rate = float(sys.argv[sys.argv.index("--rate") + 1]) if "--rate" in sys.argv else 100.0
past = "--past" in sys.argv
peak_time = 90.0 / rate
os.makedirs(work, exist_ok=True)
job = os.path.splitext(os.path.basename(deck))[0]
status = subprocess.run([clinch, "run", "--quiet", "--out", work, deck]).returncode
failures = []
if status != 2:
    failures.append(f"exit status {status}, expected 2")
last = open(os.path.join(work, job + ".sta"), encoding="utf-8").read().splitlines()[-1]
if past:
    pattern = (r"^FAILED: singular system: .*; connector element 1 fully damaged \(d=1\) "
               r"\(step 1, increment \d+, time [0-9.]+\)$")
else:
    pattern = (r"^FAILED: .*connector element 1 softening \(d=[0-9.e+-]+\) under load control: "
               r"a limit point, past which no larger load has an equilibrium, at about "
               r"[0-9.e+-]+ of the step's loads; to go past it, use \*STATIC, RIKS, .* "
               r"\(step 1, increment \d+, time [0-9.]+\)$")
if not re.match(pattern, last):
    failures.append(f"status line: {last!r}")
rows = list(csv.DictReader(open(os.path.join(work, job + ".history.csv"), encoding="utf-8")))
for row in rows:
    t = float(row["total_time"])
    if abs(float(row["CTF1@1"]) - rate * t) > 1e-9 * rate:
        failures.append(f"row at t = {t} is not in equilibrium with the load: {row}")
    if t < peak_time * (1.0 - 1e-9) and float(row["CDMG@1"]) != 0.0:
        failures.append(f"row at t = {t} is damaged before the peak: {row}")
last_time = float(rows[-1]["total_time"])
if past and last_time <= peak_time * 1.01:
    failures.append(f"the viscous run did not pass the inviscid peak time {peak_time} (last t = {last_time})")
if not past and not peak_time * 0.999 <= last_time <= peak_time:
    failures.append(f"the converged rows up to the peak are missing (last t = {last_time})")
for f in failures:
    print("FAIL:", f)
print(f"{len(rows)} rows, last at t = {rows[-1]['total_time']}; status: {last}")
sys.exit(1 if failures else 0)
