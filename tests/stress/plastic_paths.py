"""Stress test of coupled plasticity: random load paths through `clinch run`.

Each path is one deck: a spot weld (BUSHING, the elliptical potential of
derived-components-and-potentials.md section 3 with beta = 1.5) or a MAX potential (CARTESIAN,
a square truncated by a circle, so that returns land on corners and edges; behaviors.md 6.6)
between a fixed node 1 and a free node 2, driven through an elastic connector of the same
stiffness from node 3, whose motions are prescribed over several steps. Node 2 is free, so
Newton iterates on it with the plastic consistent tangent; the elastic connector in series keeps
every path solvable even where the hardening table ends (perfect plasticity). Steps mix proportional loading,
reversals, crossings of f3 = 0 (the Macaulay kink of the spot weld's normal measure) and random
non-proportional moves. Increments are automatic, so cutbacks are allowed and counted.

Every path must either complete (exit 0, last status line COMPLETED) or stop cleanly (exit 2 with
a last status line FAILED: ...). Anything else (a crash, another exit code, a missing status
line) fails the test. The paths are displacement-driven with hardening, so each has a solution;
the test also requires the convergence rate to reach --min-rate (default 1.0).

Usage: plastic_paths.py CLINCH [--paths N] [--seed S] [--work DIR] [--min-rate R]
                        [--max-cutback-fraction F] [--line-search N_ls]
"""

import argparse
import csv
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))


def elasticity(name, stiffnesses):
    """A *CONNECTOR BEHAVIOR with linear uncoupled elasticity, component i + 1 of stiffness k_i."""
    lines = [f"*CONNECTOR BEHAVIOR, NAME={name}"]
    for i, k in enumerate(stiffnesses, start=1):
        lines += [f"*CONNECTOR ELASTICITY, COMPONENT={i}", f"{k}"]
    return "\n".join(lines) + "\n"


def read(path):
    with open(path) as f:
        return f.read()


# The weld of decks/bench/spot_weld_behavior.inp, driven through an elastic BUSHING with the
# weld's stiffnesses.
SPOT_WELD_BEHAVIOR = """*NODE
1, 0., 0., 0.
2, 0., 0., 0.
3, 0., 0., 0.
*ELEMENT, TYPE=CONN3D2, ELSET=WELD
1, 1, 2
*ELEMENT, TYPE=CONN3D2, ELSET=DRIVE
2, 3, 2
*ORIENTATION, NAME=GLOBAL
1., 0., 0., 0., 1., 0.
*CONNECTOR SECTION, ELSET=WELD, BEHAVIOR=weld
BUSHING,
GLOBAL
*CONNECTOR SECTION, ELSET=DRIVE, BEHAVIOR=drive
BUSHING,
GLOBAL
""" + elasticity("drive", ["1.0e5", "1.0e5", "2.0e5", "1.0e6", "1.0e6", "5.0e5"]) + read(
    os.path.join(HERE, "..", "..", "decks", "bench", "spot_weld_behavior.inp")) + """*BOUNDARY
1, 1, 6
3, 4, 6
"""

MAX_BEHAVIOR = """*NODE
1, 0., 0., 0.
2, 0., 0., 0.
3, 0., 0., 0.
*ELEMENT, TYPE=CONN3D2, ELSET=WELD
1, 1, 2
*ELEMENT, TYPE=CONN3D2, ELSET=DRIVE
2, 3, 2
*CONNECTOR SECTION, ELSET=WELD, BEHAVIOR=box
CARTESIAN,
*CONNECTOR SECTION, ELSET=DRIVE, BEHAVIOR=drive
CARTESIAN,
""" + elasticity("drive", ["1000.", "1500.", "800."]) + elasticity(
    "box", ["1000.", "1500.", "800."]) + """*CONNECTOR PLASTICITY
*CONNECTOR HARDENING, DEFINITION=TABULAR
100., 0.
150., 0.2
*CONNECTOR POTENTIAL, OPERATOR=MAX
1, 1., , ABS, ,
2, 1., , ABS, ,
radial, 1.2, , ABS, ,
3, 0.8, , ABS, ,
*CONNECTOR DERIVED COMPONENT, NAME=radial
1, 2
1.0, 1.0
*BOUNDARY
1, 1, 6
3, 4, 6
"""

# Motion scales of node 3: about six times the first-yield motion of each component of the weld
# (the series connector takes half of the motion while the weld is elastic).
SPOT_WELD_SCALE = [0.06, 0.06, 0.024, 0.006, 0.006, 0.012]
MAX_SCALE = [0.6, 0.4, 0.6]


def random_path(rng, dimension):
    """Targets of node b's DOFs at the end of each step, in units of the motion scale."""
    targets = []
    current = [0.0] * dimension
    for _ in range(rng.randint(3, 6)):
        kind = rng.choice(["proportional", "reverse", "kink", "random", "unload"])
        if kind == "proportional" and any(current):
            factor = rng.uniform(1.2, 2.0)
            nxt = [factor * x for x in current]
        elif kind == "reverse" and any(current):
            nxt = [-rng.uniform(0.5, 1.5) * x for x in current]
        elif kind == "kink":
            nxt = [rng.uniform(-1.5, 1.5) for _ in range(dimension)]
            nxt[2] = -current[2] if current[2] else rng.choice([-1.0, 1.0])  # cross f3 = 0
        elif kind == "unload":
            nxt = [0.5 * x for x in current]
        else:
            nxt = [rng.uniform(-1.5, 1.5) for _ in range(dimension)]
        targets.append(nxt)
        current = nxt
    return targets


def write_deck(path, behavior, dofs, scale, targets, initial_increment, line_search):
    lines = ["*HEADING", "Random load path (tests/stress/plastic_paths.py)", behavior.rstrip()]
    for step, target in enumerate(targets, start=1):
        lines += [f"*STEP, NAME=S{step}", "*STATIC", f"{initial_increment}, 1.0"]
        if line_search:
            lines += ["*CONTROLS, PARAMETERS=LINE SEARCH", f"{line_search},"]
        lines.append("*BOUNDARY")
        for k, dof in enumerate(dofs):
            lines.append(f"3, {dof}, {dof}, {target[k] * scale[k]:.10g}")
        lines.append("*END STEP")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def run_path(clinch, deck, out):
    proc = subprocess.run([clinch, "run", "--quiet", "--out", out, deck],
                          stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    job = os.path.splitext(os.path.basename(deck))[0]
    sta = os.path.join(out, job + ".sta")
    log = os.path.join(out, job + ".log")
    last = ""
    per_increment = []
    if os.path.exists(sta):
        with open(sta) as f:
            rows = [line.rstrip("\n") for line in f if line.strip()]
        last = rows[-1] if rows else ""
        for row in rows[1:]:
            fields = row.split()
            # "step inc att [U] equil total times...": an attempt that was cut back carries U
            # and has nine fields; a converged one has eight.
            if len(fields) == 8 and fields[0].isdigit():
                per_increment.append(int(fields[3]))
    # Whether the path yielded: the equivalent plastic motion of the weld at the last row.
    yielded = False
    table = os.path.join(out, job + ".history.csv")
    if os.path.exists(table):
        with open(table) as f:
            last_row = list(csv.DictReader(f))[-1]
        yielded = float(last_row.get("CUPEQ@1", "0")) > 0.0
    cutbacks = iterations = increments = 0
    if os.path.exists(log):
        with open(log) as f:
            text = f.read()
        m = re.search(r"(\d+) increments, (\d+) iterations, (\d+) cutbacks", text)
        if m:
            increments, iterations, cutbacks = (int(g) for g in m.groups())
    return (proc.returncode, last, per_increment, increments, iterations, cutbacks, yielded,
            proc.stderr)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("clinch")
    parser.add_argument("--paths", type=int, default=500)
    parser.add_argument("--seed", type=int, default=20261201)
    parser.add_argument("--work")
    parser.add_argument("--min-rate", type=float, default=1.0)
    parser.add_argument("--max-cutback-fraction", type=float, default=1.0,
                        help="fail when more than this fraction of increments were cut back")
    parser.add_argument("--line-search", type=int, default=0,
                        help="N_ls of *CONTROLS, PARAMETERS=LINE SEARCH in every step (0: off)")
    args = parser.parse_args()
    work = args.work or tempfile.mkdtemp(prefix="clinch-stress-")
    os.makedirs(work, exist_ok=True)
    rng = random.Random(args.seed)
    problems = []
    # paths, converged, increments, iterations, cutbacks, most iterations in an increment, yielded
    stats = {"spot_weld": [0, 0, 0, 0, 0, 0, 0], "max": [0, 0, 0, 0, 0, 0, 0]}
    for n in range(args.paths):
        kind = "spot_weld" if n % 2 == 0 else "max"
        if kind == "spot_weld":
            behavior, dofs, scale, dim = SPOT_WELD_BEHAVIOR, [1, 2, 3, 4, 5, 6], SPOT_WELD_SCALE, 6
        else:
            behavior, dofs, scale, dim = MAX_BEHAVIOR, [1, 2, 3], MAX_SCALE, 3
        deck = os.path.join(work, f"path{n:04d}.inp")
        write_deck(deck, behavior, dofs, scale, random_path(rng, dim), rng.choice([0.1, 0.25, 0.5]),
                   args.line_search)
        code, last, per_inc, incs, its, cuts, yielded, err = run_path(
            args.clinch, deck, os.path.join(work, "out"))
        s = stats[kind]
        s[0] += 1
        if code == 0 and last == "COMPLETED":
            s[1] += 1
        elif code == 2 and last.startswith("FAILED:"):
            pass
        else:
            problems.append(f"{deck}: exit {code}, last status line {last!r}, stderr {err[-300:]!r}")
        s[2] += incs
        s[3] += its
        s[4] += cuts
        s[5] = max(s[5], max(per_inc, default=0))
        s[6] += yielded
    total = sum(s[0] for s in stats.values())
    converged = sum(s[1] for s in stats.values())
    print(f"{total} paths (seed {args.seed}), work directory {work}")
    for kind, s in stats.items():
        mean = s[3] / s[2] if s[2] else 0.0
        print(f"  {kind:9s}: {s[1]}/{s[0]} converged ({s[6]} yielded), {s[2]} increments, "
              f"{mean:.2f} Newton iterations per increment (max {s[5]}), {s[4]} cutbacks")
    rate = converged / total if total else 0.0
    print(f"  convergence rate {rate:.4f}")
    for p in problems:
        print("PROBLEM:", p)
    if not args.work and not problems and rate >= args.min_rate:
        shutil.rmtree(work, ignore_errors=True)
    increments = sum(s[2] for s in stats.values())
    cutbacks = sum(s[4] for s in stats.values())
    if increments and cutbacks > args.max_cutback_fraction * increments:
        print(f"PROBLEM: {cutbacks} cutbacks in {increments} increments")
        return 1
    if problems or rate < args.min_rate:
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
