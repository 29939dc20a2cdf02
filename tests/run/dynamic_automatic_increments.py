"""Automatic incrementation of *DYNAMIC by the half-increment residual (docs/dynamics.md
"Automatic incrementation").

1. The increments of decks/verification/dynamic_automatic_increments are those its reference.py
   chooses by the same rules from the independently computed half-increment residual: the same
   rows (step, increment) at the same step times, to 1e-12 relative (the golden's values are
   checked by the verify_ CTest; `clinch compare` interpolates between rows, so it alone would
   not see a different increment).
2. A free undamped oscillator (m = 1, k = 100, v0 = 1: u = 0.1 sin 10t) under the trapezoidal
   rule (ALPHA=0) with a tight HAFTOL:
   - every accepted increment holds to HAFTOL, by the half-increment residual computed here from
     the history's U1, V1, A1 at its start and end (the definition in the verification case's
     reference.py);
   - the answer against the exact motion: the trapezoidal rule turns the state (u, v/omega) by
     2 atan(omega dt/2) per increment, whatever dt, so its only error is the phase lag
     sum(omega dt - 2 atan(omega dt/2)) over the increments so far, and |u - u_exact| <= U times
     that lag (+1e-12 round-off);
   - against a fine DIRECT run (dt = 1e-4) at the end of the step: within U times the sum of the
     two runs' lags. The tight HAFTOL keeps that below 1 % of U.
3. The same oscillator without HAFTOL: the TRANSIENT FIDELITY default tolerance is reported in
   the log for every accepted increment and the residual holds to it.
Usage: dynamic_automatic_increments.py CLINCH CASE_DIR WORK_DIR
"""
import csv
import math
import os
import re
import subprocess
import sys

clinch, case_dir, work = sys.argv[1:4]
os.makedirs(work, exist_ok=True)
failures = []
OMEGA, U = 10.0, 0.1


def run(deck_path, out):
    status = subprocess.run([clinch, "run", "--quiet", "--out", out, deck_path]).returncode
    if status != 0:
        failures.append(f"{deck_path}: exit status {status}")
        return [], ""
    job = os.path.splitext(os.path.basename(deck_path))[0]
    rows = list(csv.DictReader(open(os.path.join(out, job + ".history.csv"), encoding="utf-8")))
    log = open(os.path.join(out, job + ".log"), encoding="utf-8").read()
    return rows, log


# 1. The increments of the verification case.
case = os.path.basename(os.path.normpath(case_dir))
rows, _ = run(os.path.join(case_dir, case + ".inp"), os.path.join(work, "case"))
golden = list(csv.DictReader(line for line in open(os.path.join(case_dir, "golden.csv"),
                                                   encoding="utf-8")
                             if not line.startswith("#")))
if len(rows) != len(golden):
    failures.append(f"{len(rows)} rows, the reference chose {len(golden)}")
for r, g in zip(rows, golden):
    same = (r["step"], r["increment"]) == (g["step"], g["increment"]) and math.isclose(
        float(r["step_time"]), float(g["step_time"]), rel_tol=1e-12, abs_tol=1e-15)
    if not same:
        failures.append(f"row {r['step']},{r['increment']} at {r['step_time']}: the reference "
                        f"has {g['step']},{g['increment']} at {g['step_time']}")
        break


def oscillator_deck(name, dynamic, data):
    path = os.path.join(work, name + ".inp")
    with open(path, "w", encoding="utf-8") as f:
        f.write("\n".join([
            "*NODE, NSET=N", "2, 0., 0., 0.", "*ELEMENT, TYPE=SPRING1, ELSET=S", "1, 2",
            "*SPRING, ELSET=S", "1", "100.", "*ELEMENT, TYPE=MASS, ELSET=M", "5, 2",
            "*MASS, ELSET=M", "1.", "*INITIAL CONDITIONS, TYPE=VELOCITY", "2, 1, 1.",
            "*STEP, INC=100000", dynamic, data, "*OUTPUT, HISTORY", "*NODE OUTPUT, NSET=N",
            "U1, V1, A1", "*END STEP"]) + "\n")
    return path


def lag(dt):
    return OMEGA * dt - 2.0 * math.atan(OMEGA * dt / 2.0)


# 2. Tight HAFTOL under the trapezoidal rule.
HAFTOL = 1e-3
auto, _ = run(oscillator_deck("tight", f"*DYNAMIC, ALPHA=0., HAFTOL={HAFTOL}",
                              "0.001, 2., 1e-6, 0.1"), os.path.join(work, "tight"))
total_lag, largest = 0.0, 0.0
for before, after in zip(auto, auto[1:]):
    t0, t1 = float(before["total_time"]), float(after["total_time"])
    dt = t1 - t0
    u0, v0, a0 = (float(before[c]) for c in ("U1@2", "V1@2", "A1@2"))
    u1, a1 = float(after["U1@2"]), float(after["A1@2"])
    h, a_h = dt / 2.0, (a0 + a1) / 2.0
    u_h = u0 + h * v0 + h * h * (0.25 * a0 + 0.25 * a_h)
    eps = abs(a_h + OMEGA ** 2 * u_h)
    largest = max(largest, eps)
    if eps > HAFTOL * (1.0 + 1e-6):
        failures.append(f"increment ending at {t1}: half-increment residual {eps} > {HAFTOL}")
    total_lag += lag(dt)
    error = abs(u1 - U * math.sin(OMEGA * t1))
    if error > U * total_lag + 1e-12:
        failures.append(f"t = {t1}: |u - u_exact| = {error} above U x lag = {U * total_lag}")
fine, _ = run(oscillator_deck("fine", "*DYNAMIC, DIRECT, ALPHA=0.", "0.0001, 2."),
              os.path.join(work, "fine"))
if auto and fine:
    bound = U * (total_lag + 20000 * lag(1e-4)) + 1e-12
    difference = abs(float(auto[-1]["U1@2"]) - float(fine[-1]["U1@2"]))
    if difference > bound or bound > 1e-2 * U:
        failures.append(f"at t = 2: automatic and fine DIRECT differ by {difference}, bound "
                        f"{bound}")
    print(f"tight HAFTOL {HAFTOL}: {len(auto) - 1} increments, largest half-increment residual "
          f"{largest:.3g}; |u_auto - u_fine| at t = 2: {difference:.3g} (bound {bound:.3g})")

# 3. The default tolerance of TRANSIENT FIDELITY.
_, log = run(oscillator_deck("default", "*DYNAMIC", "0.01, 2., 1e-6, 0.5"),
             os.path.join(work, "default"))
reported = re.findall(r"increment \d+: half-increment residual ([0-9.e+-]+) at U1@2 "
                      r"\(tolerance ([0-9.e+-]+)\)$", log, re.M)
if not reported:
    failures.append("no half-increment residual in the log of the default run")
for value, tolerance in reported:
    if not 0.0 < float(value) <= float(tolerance):
        failures.append(f"default run: half-increment residual {value}, tolerance {tolerance}")

for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
