"""Recovery test of `clinch fit` (docs/fit.md "Recovery tests"): measured curves are made by
clinch itself at known parameter values, with Gaussian noise of a stated size added (a seeded
generator, so the test is repeatable), and the fit started elsewhere must find the known values.

The truth deck is written here, independently of clinch's own deck copies: the line `name = ...`
of each known parameter replaced. The noise on each measured column has the standard deviation
--noise times the column's largest |value|. Criteria, for each parameter:
  - |fitted - known| <= --sigmas standard errors (3 by default: a 0.3 % chance per parameter for
    a fit that is linear near the optimum and errors as reported), and
  - the standard error is below --max-relative-error of the known value, so that a fit that
    reports huge errors cannot pass;
and the RMS of the scaled residual after the fit (the residual's unit is the column's largest
|measured value|) lies within 40 % of --noise: the noise the fit sees is the noise that was added
(with 20 points or more the RMS of pure noise is within 40 % of its sigma with probability above
0.99).
With --expect undetermined, the fit must instead exit 2 and name the parameters as not determined.
With --outliers N, N measured values of the first column (rows drawn by the same generator) are
moved by 20 % of the column's peak: the RMS check is then left out, and with --expect biased
some parameter must lie more than --sigmas standard errors off (a fit the outliers pull away).
With --failed-runs, some runs of the fit must have failed (and the fit converged all the same).
With --data, the measured curves are the files given (one per deck, made at the --truth values
with --noise), not made here.

Usage: recovery.py --clinch CLINCH --work DIR --deck D.inp [--deck D2.inp] --truth a=1,b=2
       --vary a=lo:hi,b=lo:hi --measure COL[,COL] [--x COL] [--noise 0.01] [--seed 1]
       [--sigmas 3] [--max-relative-error 0.05] [--expect recovered|undetermined]
       [--data MEASURED.csv ...] [--failed-runs] [--fit-option=--method=dogleg ...]
"""
import argparse
import csv
import os
import random
import re
import shutil
import subprocess
import sys


def truth_deck(deck, truth, path):
    with open(deck) as f:
        text = f.read()
    for name, value in truth.items():
        text, count = re.subn(rf"^(\s*){re.escape(name)}\s*=.*$", rf"\g<1>{name} = {value!r}",
                              text, count=1, flags=re.M)
        if count != 1:
            sys.exit(f"recovery.py: {deck} defines no parameter '{name}'")
    with open(path, "w") as f:
        f.write(text)


def measured_table(history, x, columns, noise, outliers, rng, path):
    with open(history, newline="") as f:
        rows = list(csv.DictReader(f))
    peaks = {c: max(abs(float(r[c])) for r in rows) for c in columns}
    values = [[float(r[c]) + rng.gauss(0.0, noise * peaks[c]) for c in columns] for r in rows]
    for row in rng.sample(range(1, len(rows)), outliers):
        values[row][0] += 0.2 * peaks[columns[0]]
    with open(path, "w", newline="") as f:
        out = csv.writer(f)
        out.writerow([x] + columns)
        for r, v in zip(rows, values):
            out.writerow([r[x]] + [repr(value) for value in v])


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--clinch", required=True)
    p.add_argument("--work", required=True)
    p.add_argument("--deck", action="append", required=True)
    p.add_argument("--truth", required=True)
    p.add_argument("--vary", required=True)
    p.add_argument("--measure", required=True)
    p.add_argument("--x", default="total_time")
    p.add_argument("--noise", type=float, default=0.01)
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--sigmas", type=float, default=3.0)
    p.add_argument("--max-relative-error", type=float, default=0.05)
    p.add_argument("--expect", choices=("recovered", "undetermined", "biased"),
                   default="recovered")
    p.add_argument("--outliers", type=int, default=0)
    p.add_argument("--data", action="append")
    p.add_argument("--failed-runs", action="store_true")
    p.add_argument("--fit-option", action="append", default=[],
                   help="an option passed on to clinch fit")
    a = p.parse_args()
    truth = {k: float(v) for k, v in (item.split("=") for item in a.truth.split(","))}
    columns = a.measure.split(",")
    rng = random.Random(a.seed)
    shutil.rmtree(a.work, ignore_errors=True)
    os.makedirs(a.work)
    # The fit runs copies of the decks (their values are the start), so that the fitted decks it
    # writes beside them land in the work directory.
    decks = []
    for deck in a.deck:
        decks.append(os.path.join(a.work, os.path.basename(deck)))
        shutil.copy(deck, decks[-1])
    data = a.data or []
    for deck in [] if a.data else a.deck:
        stem = os.path.splitext(os.path.basename(deck))[0]
        known = os.path.join(a.work, f"{stem}.truth.inp")
        truth_deck(deck, truth, known)
        out = os.path.join(a.work, f"truth-{stem}")
        subprocess.run([a.clinch, "run", "--quiet", "--out", out, "--job", stem, known],
                       check=True)
        data.append(os.path.join(a.work, f"{stem}.measured.csv"))
        measured_table(os.path.join(out, f"{stem}.history.csv"), a.x, columns, a.noise,
                       a.outliers, rng, data[-1])
    command = [a.clinch, "fit", *decks, "--vary", a.vary, "--x", a.x, "--jobs", "2",
               "--work", os.path.join(a.work, "fit"), "--quiet", *a.fit_option]
    for d in data:
        command += ["--data", d]
    fit = subprocess.run(command, capture_output=True, text=True)
    print(fit.stdout + fit.stderr)
    if a.expect == "undetermined":
        names = ", ".join(truth)
        ok = fit.returncode == 2 and f"NOT DETERMINED by the data: {names}" in fit.stdout
        print("undetermined as expected" if ok else f"FAIL: expected exit 2 naming {names}")
        return 0 if ok else 1
    if fit.returncode != 0:
        print(f"FAIL: clinch fit exited {fit.returncode}")
        return 1
    job = os.path.splitext(os.path.basename(a.deck[0]))[0]
    failed = False
    worst = 0.0
    with open(os.path.join(a.work, "fit", f"{job}.fit.csv"), newline="") as f:
        for row in csv.DictReader(f):
            name, value, error = row["parameter"], float(row["fitted"]), float(
                row["standard_error"])
            known = truth[name]
            off = abs(value - known)
            good = off <= a.sigmas * error and 0 < error <= a.max_relative_error * abs(known)
            worst = max(worst, off / error)
            failed |= not good and a.expect == "recovered"
            print(f"{name}: known {known:g}, fitted {value:.6g} +- {error:.3g}: off by "
                  f"{off / error:.2f} standard errors {'ok' if good else 'FAIL'}")
    checked = 0
    for line in fit.stdout.splitlines():
        match = re.match(r"\s+(\S+\.csv)\s+\(.*\): \S+ -> (\S+)$", line)
        if match and a.outliers == 0:
            checked += 1
            rms = float(match.group(2))
            good = abs(rms / a.noise - 1.0) <= 0.4
            failed |= not good
            print(f"{match.group(1)}: RMS scaled residual {rms:.4g} against noise {a.noise:g} "
                  f"{'ok' if good else 'FAIL'}")
    failures = re.search(r"^runs: \d+ \((\d+) failed\)", fit.stdout, re.M)
    if a.failed_runs and not (failures and int(failures.group(1)) > 0):
        print("FAIL: no run of the fit failed")
        failed = True
    if a.expect == "biased":
        good = worst > a.sigmas
        print(f"the outliers pull a parameter {worst:.1f} standard errors off: "
              f"{'ok' if good else 'FAIL'} (more than {a.sigmas:g} expected)")
        failed |= not good
    if checked != (0 if a.outliers else len(data)):
        print(f"FAIL: {checked} residual lines for {len(data)} data files")
        failed = True
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
