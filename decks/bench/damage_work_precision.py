"""Work-precision tables of connector damage (behaviors.md §7): exponential softening and
energy-based evolution, each in a connector in series with a stiffer elastic one.

Deck: element 1 (AXIAL, k1 = 1000, FORCE initiation at 90, so u_0 = 0.09) between a held node and a
free node 2; element 2 (AXIAL, k2 = 4000, elastic) between node 2 and node 3, which is driven from
0 to 0.4 in N equal increments (*STATIC, DIRECT). k2 exceeds the steepest softening slope of
element 1 (2265 for EXPONENTIAL, about 650 for ENERGY), so the path has no snap-back and Newton
solves for node 2 on the softening branch in every increment.

1. EXPONENTIAL softening (Δu_f = 0.2, a = 5). Reference: on the envelope k2 (U − u1) =
   k1 u_0 g(u1 − u_0), g = 1 − (1 − e^(−aκ/Δu_f))/(1 − e^(−a)), solved by bisection to round-off;
   d = 1 − u_0 g/(u_0 + κ); below initiation u1 = k2 U/(k1 + k2). Errors: at the rows (the update
   is exact at every converged state, so this measures Newton's tolerance and round-off), and of
   the curve the rows resolve: the history interpolated linearly between rows against the
   reference at 2001 points of U (max over U of |error| / 90 for CTF1, |error| for CDMG).
2. ENERGY (G_f = 10). The dissipated energy after initiation, the trapezoidal area of element 1's
   force–motion history from u_0 to the failed row, against G_f (the law tends to G_f; the switch
   at d ≥ 0.99 leaves 1 %) and against G_f (1 − e^(−W_s/G_f)), the exact area of the continuous
   envelope up to the last state before the switch (u_s = that row's CU1).

Per N: median wall time of `clinch run` over --repeat runs, Newton iterations (.log total).
Usage: damage_work_precision.py CLINCH [--sizes 10,20,40,80,160,320] [--repeat 3] [--work DIR]
"""

import argparse
import csv
import math
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time

K1, K2, FU, DUF, A, GF, UMAX = 1000.0, 4000.0, 90.0, 0.2, 5.0, 10.0, 0.4
U0 = FU / K1


def g_exp(kappa):
    if kappa >= DUF:
        return 0.0
    return 1.0 - (1.0 - math.exp(-A * kappa / DUF)) / (1.0 - math.exp(-A))


def exponential_reference(u):
    """(u1, CTF1, CDMG) at U on monotonic loading."""
    u1 = K2 * u / (K1 + K2)
    if u1 <= U0:
        return u1, K1 * u1, 0.0

    def residual(x):
        return K2 * (u - x) - K1 * U0 * g_exp(x - U0)

    lo, hi = U0, u
    if residual(U0 + DUF) >= 0.0:
        return u, 0.0, 1.0  # past failure: element 1 carries nothing
    hi = U0 + DUF
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if mid in (lo, hi):
            break
        if residual(mid) > 0.0:
            lo = mid
        else:
            hi = mid
    kappa = lo - U0
    d = 1.0 - U0 * g_exp(kappa) / (U0 + kappa)
    return lo, (1.0 - d) * K1 * lo, d


def deck_text(n, evolution):
    return "\n".join([
        "*NODE", "1, 0., 0., 0.", "2, 10., 0., 0.", "3, 20., 0., 0.",
        "*ELEMENT, TYPE=CONN3D2, ELSET=SOFT", "1, 1, 2",
        "*ELEMENT, TYPE=CONN3D2, ELSET=STIFF", "2, 2, 3",
        "*CONNECTOR SECTION, ELSET=SOFT, BEHAVIOR=SOFT", "AXIAL,",
        "*CONNECTOR SECTION, ELSET=STIFF, BEHAVIOR=STIFF", "AXIAL,",
        "*CONNECTOR BEHAVIOR, NAME=SOFT", "*CONNECTOR ELASTICITY, COMPONENT=1", f"{K1}",
        "*CONNECTOR DAMAGE INITIATION, COMPONENT=1, CRITERION=FORCE", f", {FU}",
        *evolution,
        "*CONNECTOR BEHAVIOR, NAME=STIFF", "*CONNECTOR ELASTICITY, COMPONENT=1", f"{K2}",
        "*NSET, NSET=N3", "3",
        "*BOUNDARY", "1, 1, 3", "2, 2, 3", "3, 2, 3",
        "*STEP, INC=100000", "*STATIC, DIRECT", f"{1.0 / n!r}, 1.",
        "*CONTROLS, PARAMETERS=FIELD", "1e-10, , , , 1e-10, 1e-12,",
        "*BOUNDARY", f"3, 1, 1, {UMAX}",
        "*OUTPUT, HISTORY", "*ELEMENT OUTPUT, ELSET=SOFT", "CU1, CTF1, CDMG",
        "*NODE OUTPUT, NSET=N3", "U1",
        "*END STEP", ""])


def run(clinch, work, name, text, repeat):
    deck = os.path.join(work, name + ".inp")
    with open(deck, "w") as f:
        f.write(text)
    walls = []
    for _ in range(repeat):
        start = time.perf_counter()
        proc = subprocess.run([clinch, "run", "--quiet", "--out", work, deck],
                              stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        walls.append(time.perf_counter() - start)
        if proc.returncode != 0:
            sys.exit(f"{deck}: exit {proc.returncode}\n{proc.stderr}")
    log = open(os.path.join(work, name + ".log")).read()
    iterations = int(re.search(r"(\d+) increments?, (\d+) iterations?", log).group(2))
    with open(os.path.join(work, name + ".history.csv")) as f:
        rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]
    return statistics.median(walls), iterations, rows


def interpolate(xs, ys, x):
    for i in range(1, len(xs)):
        if x <= xs[i]:
            s = (x - xs[i - 1]) / (xs[i] - xs[i - 1])
            return ys[i - 1] + s * (ys[i] - ys[i - 1])
    return ys[-1]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("clinch")
    ap.add_argument("--sizes", default="10,20,40,80,160,320")
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--work")
    args = ap.parse_args()
    work = args.work or tempfile.mkdtemp(prefix="damage-wp-")
    os.makedirs(work, exist_ok=True)
    sizes = [int(s) for s in args.sizes.split(",")]

    print("EXPONENTIAL softening (Δu_f = 0.2, a = 5) in series, U3 0 -> 0.4 in N increments")
    print("| N | wall s | Newton iterations | rows: max |CTF1 err|/90 | rows: max |CDMG err| |"
          " curve: max |CTF1 err|/90 | curve: max |CDMG err| |")
    print("|---|---|---|---|---|---|---|")
    evolution = ["*CONNECTOR DAMAGE EVOLUTION, TYPE=MOTION, SOFTENING=EXPONENTIAL", f"{DUF}, {A}"]
    for n in sizes:
        wall, its, rows = run(args.clinch, work, f"exponential_{n}", deck_text(n, evolution),
                              args.repeat)
        us = [r["U1@3"] for r in rows]
        row_f = row_d = 0.0
        failed = False
        for r in rows:
            _, f, d = exponential_reference(r["U1@3"])
            if failed:  # deleted: the reference force is 0 and d = 1 as well
                f, d = 0.0, 1.0
            row_f = max(row_f, abs(r["CTF1@1"] - f) / FU)
            row_d = max(row_d, abs(r["CDMG@1"] - d))
            failed = failed or r["CDMG@1"] >= 1.0
        curve_f = curve_d = 0.0
        for i in range(2001):
            u = UMAX * i / 2000
            _, f, d = exponential_reference(u)
            curve_f = max(curve_f, abs(interpolate(us, [r["CTF1@1"] for r in rows], u) - f) / FU)
            curve_d = max(curve_d, abs(interpolate(us, [r["CDMG@1"] for r in rows], u) - d))
        print(f"| {n} | {wall:.3f} | {its} | {row_f:.2e} | {row_d:.2e} | {curve_f:.2e} | {curve_d:.2e} |")

    print()
    print("ENERGY (G_f = 10) in series, U3 0 -> 0.4 in N increments: dissipated energy after initiation")
    print("| N | wall s | Newton iterations | area / G_f | |area - G_f| / G_f |"
          " |area - G_f (1 - e^(-W_s/G_f))| / G_f |")
    print("|---|---|---|---|---|---|")
    evolution = ["*CONNECTOR DAMAGE EVOLUTION, TYPE=ENERGY", f"{GF}"]
    for n in sizes:
        wall, its, rows = run(args.clinch, work, f"energy_{n}", deck_text(n, evolution), args.repeat)
        curve = []
        for r in rows:
            curve.append((r["CU1@1"], r["CTF1@1"]))
            if r["CDMG@1"] >= 1.0:
                break
        # The area from u_0: the segment that contains u_0 counts from u_0 (force k1 u_0 there).
        area = 0.0
        for (ua, fa), (ub, fb) in zip(curve, curve[1:]):
            if ub <= U0:
                continue
            if ua < U0:
                ua, fa = U0, FU
            area += 0.5 * (fa + fb) * (ub - ua)
        u_s = max(u for u, f in curve if f > 0.0)
        continuous = GF * (1.0 - math.exp(-0.5 * K1 * (u_s * u_s - U0 * U0) / GF))
        print(f"| {n} | {wall:.3f} | {its} | {area / GF:.6f} | {abs(area - GF) / GF:.2e} |"
              f" {abs(area - continuous) / GF:.2e} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
