#!/usr/bin/env python3
"""The IFToMM multibody benchmarks A01 (simple pendulum) and A02 (N-four-bar mechanism) over their
full horizons (A01: 2000 s; A02: N = 40, 20 s), which the verification cases iftomm_simple_pendulum
and iftomm_n_four_bar shorten to 5 s and N = 2, 3 s. The deck is the case's deck with the
problem's size, horizon, time increment and HHT alpha; the reference is the case's own exact
motion (reference.py). Prints the worst absolute error of each reference quantity over the
benchmark's output times, against the benchmark's tolerances (1e-1 low, 1e-3 high precision),
and the run's wall time.

Usage: scripts/iftomm_full_horizon.py A01|A02 [--dt DT] [--horizon T] [--alpha A] [--windows N]
       [--outputs K] [--require low|high] [--clinch PATH] [--keep DIR]
The benchmark measures at 4000 (A01) and 400 (A02) output steps over its horizon; --outputs
changes that count. --require makes the exit status 1 when a quantity is outside that precision.
"""
import argparse
import csv
import importlib.util
import math
import os
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CASES = os.path.join(ROOT, "decks", "verification")
sys.dont_write_bytecode = True


def load_reference(case):
    """The case's reference.py as a module (its golden.csv is written only when run directly)."""
    spec = importlib.util.spec_from_file_location(case, os.path.join(CASES, case, "reference.py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def operator_line(alpha):
    return "" if alpha is None else f", ALPHA={alpha}"


def pendulum_deck(dt, horizon, alpha, interval):
    return f"""*HEADING
IFToMM A01: simple pendulum, 1 kg on a massless link of 1 m, released at rest from the horizontal
*NODE
1, 0., 0., 0.
2, 1., 0., 0.
*NSET, NSET=P1
2
*ELEMENT, TYPE=CONN3D2, ELSET=ROD
1, 1, 2
*CONNECTOR SECTION, ELSET=ROD
LINK
*ELEMENT, TYPE=MASS, ELSET=LUMP
5, 2
*MASS, ELSET=LUMP
1.
*BOUNDARY
1, 1, 3
2, 3, 3
*STEP, NAME=Swing, NLGEOM, INC=100000000
*DYNAMIC, DIRECT{operator_line(alpha)}
{dt!r}, {horizon!r}
*DLOAD
, GRAV, 9.81, 0., -1., 0.
*OUTPUT, HISTORY, TIME INTERVAL={interval!r}
*NODE OUTPUT, NSET=P1
U1, U2
*END STEP
"""


def four_bar_deck(windows, dt, horizon, alpha, interval):
    """The deck of iftomm_n_four_bar for `windows` windows (README.md of the case): crank i is a
    rigid body with reference node at its ground pivot (i, 0) and tie nodes at its centre and
    tip; coupler j a rigid body from B_(j-1) to B_j with its reference node at the centre; JOIN
    pins between coincident end nodes; 1/6 kg at each end of a bar and 2/3 kg at its centre."""
    nodes, bodies, pins, ends, mids = [], [], [], [], []
    node = 0

    def add(x, y):
        nonlocal node
        node += 1
        nodes.append(f"{node}, {x!r}, {y!r}, 0.0")
        return node

    tips = []
    for i in range(windows + 1):
        pivot, centre, tip = add(float(i), 0.0), add(float(i), 0.5), add(float(i), 1.0)
        bodies.append((pivot, [centre, tip]))
        ends += [pivot, tip]
        mids.append(centre)
        tips.append(tip)
    couplers = []
    for j in range(1, windows + 1):
        left, centre, right = add(j - 1.0, 1.0), add(j - 0.5, 1.0), add(float(j), 1.0)
        bodies.append((centre, [left, right]))
        couplers.append(centre)
        ends += [left, right]
        mids.append(centre)
        pins += [(tips[j - 1], left), (tips[j], right)]
    lines = ["*HEADING", f"IFToMM A02: N-four-bar mechanism, N = {windows}", "*NODE"] + nodes
    lines += ["*NSET, NSET=B0", str(tips[0])]
    for k, (ref, tie) in enumerate(bodies):
        lines += [f"*NSET, NSET=BAR{k}", ", ".join(map(str, tie)),
                  f"*RIGID BODY, REF NODE={ref}, TIE NSET=BAR{k}"]
    lines.append("*ELEMENT, TYPE=CONN3D2, ELSET=PINS")
    lines += [f"{k + 1}, {a}, {b}" for k, (a, b) in enumerate(pins)]
    lines += ["*CONNECTOR SECTION, ELSET=PINS", "JOIN"]
    element = 100000
    for name, where, mass in (("END", ends, "0.16666666666666667"),
                              ("MID", mids, "0.66666666666666667")):
        lines.append(f"*ELEMENT, TYPE=MASS, ELSET={name}")
        for n in where:
            element += 1
            lines.append(f"{element}, {n}")
        lines += [f"*MASS, ELSET={name}", mass]
    lines.append("*BOUNDARY")
    lines += [f"{ref}, 1, 5" for ref, _ in bodies[:windows + 1]]
    lines += [f"{c}, 4, 4" for c in couplers]
    lines.append("*INITIAL CONDITIONS, TYPE=VELOCITY")
    lines += [f"{ref}, 6, -1." for ref, _ in bodies[:windows + 1]]
    lines += [f"{c}, 1, 1." for c in couplers]
    lines += ["*STEP, NAME=Motion, NLGEOM, INC=100000000",
              f"*DYNAMIC, DIRECT{operator_line(alpha)}", f"{dt!r}, {horizon!r}",
              "*DLOAD", ", GRAV, 9.81, 0., -1., 0.",
              f"*OUTPUT, HISTORY, TIME INTERVAL={interval!r}",
              "*NODE OUTPUT, NSET=B0", "U1, U2, V1, V2", "*END STEP"]
    return "\n".join(lines) + "\n"


def read_history(path):
    with open(path, newline="", encoding="utf-8") as f:
        rows = [r for r in csv.reader(line for line in f if not line.startswith("#"))]
    header, body = rows[0], rows[1:]
    time_col = header.index("total_time")
    return header, [(float(r[time_col]), r) for r in body]


def worst_errors(header, rows, exact, names):
    """Largest |clinch - exact| per column over the output rows (t > 0), with its time."""
    cols = [next(i for i, h in enumerate(header) if h.split("@")[0] == n) for n in names]
    worst = {n: (0.0, 0.0) for n in names}
    for t, row in rows:
        if t <= 0.0:
            continue
        ref = exact(t)
        for n, c, r in zip(names, cols, ref):
            err = abs(float(row[c]) - r)
            if err > worst[n][0]:
                worst[n] = (err, t)
    return worst


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("problem", choices=["A01", "A02"])
    parser.add_argument("--dt", type=float)
    parser.add_argument("--horizon", type=float)
    parser.add_argument("--alpha", type=float, help="HHT alpha (default: the deck's default)")
    parser.add_argument("--windows", type=int, default=40, help="A02: N (default 40)")
    parser.add_argument("--outputs", type=int, help="output steps over the horizon")
    parser.add_argument("--require", choices=["low", "high"])
    parser.add_argument("--clinch", default=os.path.join(ROOT, "build", "clinch"))
    parser.add_argument("--keep", help="keep the deck and the outputs in this directory")
    args = parser.parse_args()

    if args.problem == "A01":
        horizon, dt, outputs = args.horizon or 2000.0, args.dt or 0.002, args.outputs or 4000
        reference = load_reference("dynamic_pendulum")
        names = ["U1", "U2"]

        def exact(t):
            return reference.state(t)[:2]
        deck = pendulum_deck(dt, horizon, args.alpha, horizon / outputs)
    else:
        horizon, dt, outputs = args.horizon or 20.0, args.dt or 0.001, args.outputs or 400
        reference = load_reference("iftomm_n_four_bar")
        names = ["U1", "U2", "V1", "V2"]
        interval = horizon / outputs
        times = [interval * k for k in range(1, outputs + 1)]
        states = dict(zip(times, reference.integrate(times, 1e-4, args.windows)))

        def exact(t):
            nearest = min(times, key=lambda s: abs(s - t))
            if abs(nearest - t) > 1e-9 * horizon:
                raise SystemExit(f"no reference at t = {t}")
            return reference.b0_motion(*states[nearest])
        deck = four_bar_deck(args.windows, dt, horizon, args.alpha, interval)

    workdir = args.keep or tempfile.mkdtemp(prefix="iftomm_")
    os.makedirs(workdir, exist_ok=True)
    stem = f"iftomm_{args.problem.lower()}"
    with open(os.path.join(workdir, stem + ".inp"), "w", encoding="utf-8") as f:
        f.write(deck)
    start = time.monotonic()
    run = subprocess.run([args.clinch, "run", stem + ".inp"], cwd=workdir,
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    wall = time.monotonic() - start
    summary = [line for line in run.stdout.splitlines() if stem in line]
    print(summary[-1] if summary else run.stdout[-2000:])
    if run.returncode != 0:
        return run.returncode
    header, rows = read_history(os.path.join(workdir, stem + ".history.csv"))
    worst = worst_errors(header, rows, exact, names)
    count = sum(1 for t, _ in rows if t > 0.0)
    print(f"{args.problem}: dt = {dt}, horizon = {horizon} s, alpha = "
          f"{'default' if args.alpha is None else args.alpha}, {count} output times, "
          f"wall {wall:.2f} s")
    for n in names:
        err, t = worst[n]
        grade = "high" if err <= 1e-3 else "low" if err <= 1e-1 else "outside"
        print(f"  worst |{n} - exact| = {err:.3e} at t = {t:g} ({grade} precision)")
    if not args.keep:
        for name in os.listdir(workdir):
            os.remove(os.path.join(workdir, name))
        os.rmdir(workdir)
    bound = {"low": 1e-1, "high": 1e-3}.get(args.require, math.inf)
    return 0 if all(err <= bound for err, _ in worst.values()) else 1


if __name__ == "__main__":
    sys.exit(main())
