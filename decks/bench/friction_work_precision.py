"""Work-precision table of connector friction: a SLIDE-PLANE driven around a square.

One SLIDE-PLANE connector (CONN3D2, predefined friction, mu = 0.5, STICK STIFFNESS k = 1e4,
orientation GLOBAL at node a, node a held) is pressed with a constant normal force F_N = 100
(a *CLOAD of -100 on DOF 1 of node b, step 1), so F = mu F_N = 50 and F / k = 0.005. Then node b is
driven around the square (0,0) -> (a,0) -> (a,a) -> (0,a) -> (0,0) in components 2-3 (global y, z)
for --laps laps (default 2), one step per side (*STATIC, DIRECT, N increments per side, *BOUNDARY
ramped from the previous corner). The side a = 0.01 = 2 F / k is short enough that the friction
force has not turned into the new direction by the end of a side, so every side is mostly a
corner transient.

Reference: the exact solution of the rate-independent friction law along the square, in closed
form per side (not a fine-increment run). Along a side of direction e, from the force f0 at the
corner: stick while |f0 + k s e| < F, up to s* = (-f0.e + sqrt((f0.e)^2 - |f0|^2 + F^2)) / k;
then slip with |f| = F. Writing f = F (cos th e + sin th e_perp), the law f' = k (e - lambda' f/F)
gives th' = -(k/F) sin th and lambda' = cos th along the path, so with t = tan(th/2):
t(s) = t(s*) exp(-(k/F)(s - s*)) and the accumulated slip grows by
(s - s*) + (F/k) ln((1 + t^2) / (1 + t(s*)^2)). The radial return of clinch (backward Euler) is
exact on a side once the force points along e (th = 0), but not in the corner transients, where
its error is first order in the increment.

For each N, clinch runs the deck --repeat times (median wall time of the whole `clinch run`,
process start included); Newton iterations are the .log's total. Errors over every history row
of steps 2 on: max |CSF - f_ref| / F (CSF as the vector (CSF2, CSF3)) and
max |CASU2 - gamma_ref| / gamma_ref at the end of the path. The last column is the largest
difference from the same radial return written in Python at the same increments (CSF, and CASU
times k), over F: clinch's algorithm, not its accuracy, so it should be round-off.

Usage: friction_work_precision.py CLINCH [--sizes 4,8,16,32,64,128] [--repeat 5] [--laps 2]
                                  [--work DIR]
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

MU, NORMAL, STICK, SIDE = 0.5, 100.0, 1.0e4, 0.01
CAPACITY = MU * NORMAL


def corners(laps):
    square = [(SIDE, 0.0), (SIDE, SIDE), (0.0, SIDE), (0.0, 0.0)]
    return [(0.0, 0.0)] + square * laps


def exact_side(f0, gamma0, e, s):
    """Force and accumulated slip after a path length s along direction e from (f0, gamma0)."""
    k, cap = STICK, CAPACITY
    fe = f0[0] * e[0] + f0[1] * e[1]
    ff = f0[0] ** 2 + f0[1] ** 2
    s_stick = max(0.0, (-fe + math.sqrt(max(fe * fe - ff + cap * cap, 0.0))) / k)
    if s <= s_stick:
        return (f0[0] + k * s * e[0], f0[1] + k * s * e[1]), gamma0
    g = (f0[0] + k * s_stick * e[0], f0[1] + k * s_stick * e[1])
    perp = (-e[1], e[0])
    theta0 = math.atan2(g[0] * perp[0] + g[1] * perp[1], g[0] * e[0] + g[1] * e[1])
    t0 = math.tan(theta0 / 2.0)
    sigma = s - s_stick
    t = t0 * math.exp(-k / cap * sigma)
    theta = 2.0 * math.atan(t)
    f = (cap * (math.cos(theta) * e[0] + math.sin(theta) * perp[0]),
         cap * (math.cos(theta) * e[1] + math.sin(theta) * perp[1]))
    return f, gamma0 + sigma + cap / k * math.log((1.0 + t * t) / (1.0 + t0 * t0))


def reference(laps, increments):
    """(f, gamma) at the end of every increment of steps 2 on, N increments per side."""
    points = corners(laps)
    f, gamma, rows = (0.0, 0.0), 0.0, []
    for p, q in zip(points, points[1:]):
        length = math.hypot(q[0] - p[0], q[1] - p[1])
        e = ((q[0] - p[0]) / length, (q[1] - p[1]) / length)
        for i in range(1, increments + 1):
            rows.append(exact_side(f, gamma, e, length * i / increments))
        f, gamma = rows[-1]
    return rows


def backward_euler(laps, increments):
    """The radial return of friction.md 4.1 at the same increments (clinch's algorithm, written
    again here): it should agree with clinch to round-off."""
    points = corners(laps)
    f, gamma, u, rows = (0.0, 0.0), 0.0, (0.0, 0.0), []
    for p, q in zip(points, points[1:]):
        for i in range(1, increments + 1):
            v = (p[0] + (q[0] - p[0]) * i / increments, p[1] + (q[1] - p[1]) * i / increments)
            trial = (f[0] + STICK * (v[0] - u[0]), f[1] + STICK * (v[1] - u[1]))
            size = math.hypot(*trial)
            if size > CAPACITY:
                f = (CAPACITY * trial[0] / size, CAPACITY * trial[1] / size)
                gamma += (size - CAPACITY) / STICK
            else:
                f = trial
            u = v
            rows.append((f, gamma))
    return rows


def deck_text(laps, increments):
    lines = ["*HEADING", "SLIDE-PLANE friction around a square (friction_work_precision.py)",
             "*NODE", "1, 0., 0., 0.", "2, 0., 0., 0.",
             "*ELEMENT, TYPE=CONN3D2, ELSET=SP", "1, 1, 2",
             "*ORIENTATION, NAME=GLOBAL", "1., 0., 0., 0., 1., 0.",
             "*CONNECTOR SECTION, ELSET=SP, BEHAVIOR=FR", "SLIDE-PLANE,", "GLOBAL",
             "*CONNECTOR BEHAVIOR, NAME=FR",
             f"*CONNECTOR FRICTION, PREDEFINED, STICK STIFFNESS={STICK:g}", "*FRICTION", f"{MU:g}",
             "*BOUNDARY", "1, 1, 6",
             "*STEP, NAME=PRESS", "*STATIC", "1.0, 1.0", "*CLOAD", f"2, 1, {-NORMAL:g}",
             "*BOUNDARY", "2, 2, 3, 0.0",
             "*OUTPUT, HISTORY", "*ELEMENT OUTPUT, ELSET=SP", "CSF2, CSF3, CNF2, CSLIPST2, CASU2",
             "*END STEP"]
    for n, (y, z) in enumerate(corners(laps)[1:], start=1):
        lines += [f"*STEP, NAME=SIDE{n}, INC={max(100, increments)}", "*STATIC, DIRECT",
                  f"{1.0 / increments!r}, 1.0", "*BOUNDARY", f"2, 2, 2, {y!r}", f"2, 3, 3, {z!r}",
                  "*END STEP"]
    return "\n".join(lines) + "\n"


def run(clinch, deck, out, repeat):
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        proc = subprocess.run([clinch, "run", "--quiet", "--out", out, deck],
                              stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        times.append(time.perf_counter() - start)
        if proc.returncode != 0:
            sys.exit(f"{deck}: clinch exited {proc.returncode}: {proc.stderr[-300:]}")
    job = os.path.splitext(os.path.basename(deck))[0]
    with open(os.path.join(out, job + ".log")) as f:
        m = re.search(r"(\d+) increments, (\d+) iterations, (\d+) cutbacks", f.read())
    with open(os.path.join(out, job + ".history.csv")) as f:
        rows = [r for r in csv.DictReader(f) if int(r["step"]) >= 2]
    return statistics.median(times), int(m.group(2)), int(m.group(3)), rows


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("clinch")
    parser.add_argument("--sizes", default="4,8,16,32,64,128")
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--laps", type=int, default=2)
    parser.add_argument("--work")
    args = parser.parse_args()
    work = args.work or tempfile.mkdtemp(prefix="clinch-friction-wp-")
    os.makedirs(work, exist_ok=True)
    print(f"SLIDE-PLANE around a square: side {SIDE:g} = 2 F/k, F = mu F_N = {CAPACITY:g}, "
          f"k = {STICK:g}, {args.laps} laps; wall time = median of {args.repeat} runs")
    print()
    print("| increments per side | wall s | Newton iterations | cutbacks | error CSF | error CASU "
          "| vs backward Euler |")
    print("|---|---|---|---|---|---|---|")
    for n in (int(x) for x in args.sizes.split(",")):
        deck = os.path.join(work, f"square{n}.inp")
        with open(deck, "w") as f:
            f.write(deck_text(args.laps, n))
        wall, iterations, cutbacks, rows = run(args.clinch, deck, os.path.join(work, "out"),
                                               args.repeat)
        ref = reference(args.laps, n)
        if len(rows) != len(ref):
            sys.exit(f"{deck}: {len(rows)} history rows after step 1, expected {len(ref)}")
        gamma_end = ref[-1][1]
        err_f = max(math.hypot(float(r["CSF2@1"]) - fr[0], float(r["CSF3@1"]) - fr[1])
                    for r, (fr, _) in zip(rows, ref)) / CAPACITY
        err_g = max(abs(float(r["CASU2@1"]) - g) for r, (_, g) in zip(rows, ref)) / gamma_end
        be = backward_euler(args.laps, n)
        be_diff = max(max(abs(float(r["CSF2@1"]) - fb[0]), abs(float(r["CSF3@1"]) - fb[1]),
                          abs(float(r["CASU2@1"]) - gb) * STICK) for r, (fb, gb) in zip(rows, be))
        be_diff /= CAPACITY
        print(f"| {n} | {wall:.4f} | {iterations} | {cutbacks} | {err_f:.2e} | {err_g:.2e} "
              f"| {be_diff:.1e} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
