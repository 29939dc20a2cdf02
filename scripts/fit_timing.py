#!/usr/bin/env python3
"""The worked example's three-parameter spot-weld fit (decks/examples/spot_weld_calibration.inp
against spot_weld_calibration.test.csv) by `clinch fit` (Ceres Solver, Levenberg-Marquardt with
forward differences over whole runs) and by the derivative-free Nelder-Mead method of SciPy on
the same objective, from the same start and within the same bounds: number of runs, wall time
(median of --repeat), final cost and values. Each Nelder-Mead evaluation is one `clinch run` of
a deck copy; its objective is written here independently of clinch's: 1/2 the sum over the
measured points of ((model - measured) / largest |measured| of the column)^2, the run's column
interpolated linearly at the measured time, the parameters divided by their start values as
`clinch fit` does. Nelder-Mead stops when the simplex is within --xatol (relative) and the cost
within --fatol.

Usage: fit_timing.py [--clinch build/clinch] [--repeat 5] [--jobs 1] [--xatol 1e-3]
                     [--fatol 1e-7]
Needs SciPy and NumPy (Debian python3-scipy), for the comparison only.
"""
import argparse
import csv
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np
from scipy.optimize import minimize

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DECK = os.path.join(ROOT, "decks", "examples", "spot_weld_calibration.inp")
DATA = os.path.join(ROOT, "decks", "examples", "spot_weld_calibration.test.csv")
BOUNDS = {"elastic_stiffness": (1e4, 1e6), "yield_force": (1e4, 1e5),
          "hardening_rise": (0.0, 1e5)}


def read_table(path):
    with open(path, newline="") as f:
        lines = [line for line in f if not line.startswith("#")]
    rows = list(csv.DictReader(lines))
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0]}


def deck_values(text):
    return {name: float(re.search(rf"^{name}\s*=\s*(\S+)", text, re.M).group(1))
            for name in BOUNDS}


class Objective:
    def __init__(self, clinch, work, text, data, start):
        self.clinch, self.work, self.text, self.data, self.start = clinch, work, text, data, start
        self.columns = [c for c in data if c != "total_time"]
        self.runs = 0

    def __call__(self, z):
        text = self.text
        for (name, x0), zi in zip(self.start.items(), z):
            text = re.sub(rf"^{name}\s*=.*$", f"{name} = {zi * x0!r}", text, count=1, flags=re.M)
        deck = os.path.join(self.work, "nm.inp")
        with open(deck, "w") as f:
            f.write(text)
        self.runs += 1
        done = subprocess.run([self.clinch, "run", "--quiet", "--out", self.work, deck],
                              capture_output=True)
        if done.returncode != 0:
            return 1e30
        run = read_table(os.path.join(self.work, "nm.history.csv"))
        cost = 0.0
        for c in self.columns:
            model = np.interp(self.data["total_time"], run["total_time"], run[c])
            cost += 0.5 * np.sum(((model - self.data[c]) / np.max(np.abs(self.data[c]))) ** 2)
        return cost


def clinch_fit(clinch, work, jobs):
    vary = ",".join(f"{k}={lo:g}:{hi:g}" for k, (lo, hi) in BOUNDS.items())
    # A copy of the deck, so that the fitted deck is written in the work directory.
    deck = os.path.join(work, os.path.basename(DECK))
    with open(DECK) as f, open(deck, "w") as out:
        out.write(f.read())
    start = time.perf_counter()
    done = subprocess.run([clinch, "fit", deck, "--data", DATA, "--vary", vary, "--jobs",
                           str(jobs), "--work", os.path.join(work, "fit"), "--quiet"],
                          capture_output=True, text=True, check=True)
    wall = time.perf_counter() - start
    runs = int(re.search(r"^runs: (\d+)", done.stdout, re.M).group(1))
    values = {m.group(1): float(m.group(3)) for m in
              re.finditer(r"^(\w+)\s+(\S+)\s+(\S+)\s+\S+\s+\[", done.stdout, re.M)}
    return runs, wall, values


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--clinch", default=os.path.join(ROOT, "build", "clinch"))
    p.add_argument("--repeat", type=int, default=5)
    p.add_argument("--jobs", type=int, default=1)
    p.add_argument("--xatol", type=float, default=1e-3)
    p.add_argument("--fatol", type=float, default=1e-7)
    a = p.parse_args()
    with open(DECK) as f:
        text = f.read()
    start = deck_values(text)
    data = read_table(DATA)
    results = {}
    with tempfile.TemporaryDirectory() as work:
        objective = Objective(a.clinch, work, text, data, start)
        for _ in range(a.repeat):
            runs, wall, values = clinch_fit(a.clinch, work, a.jobs)
            results.setdefault("clinch fit (Ceres LM)", []).append(
                (runs, wall, objective([values[k] / start[k] for k in start]), values))
        for _ in range(a.repeat):
            objective.runs = 0
            t0 = time.perf_counter()
            bounds = [(lo / start[k], hi / start[k]) for k, (lo, hi) in BOUNDS.items()]
            best = minimize(objective, np.ones(len(start)), method="Nelder-Mead", bounds=bounds,
                            options={"xatol": a.xatol, "fatol": a.fatol, "maxfev": 5000})
            wall = time.perf_counter() - t0
            runs = objective.runs
            values = {k: z * start[k] for k, z in zip(start, best.x)}
            results.setdefault("Nelder-Mead (SciPy)", []).append(
                (runs, wall, best.fun, values))
    print(f"spot-weld fit of 3 parameters, {a.repeat} repeats, clinch fit --jobs {a.jobs}")
    print(f"{'method':24} {'runs':>6} {'wall s (median)':>16} {'final cost':>12}  values")
    for method, rows in results.items():
        runs = statistics.median(r[0] for r in rows)
        wall = statistics.median(r[1] for r in rows)
        cost = statistics.median(r[2] for r in rows)
        values = ", ".join(f"{k} {v:.6g}" for k, v in rows[0][3].items())
        print(f"{method:24} {runs:6.0f} {wall:16.3f} {cost:12.6e}  {values}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
