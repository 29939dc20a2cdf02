"""Runs a deck whose forces cancel at the nodes (a bolt preloaded by a connector load, a
mechanism driven by a connector motion, a frame whose reactions cancel) and the same deck with a
small real load elsewhere: an extra AXIAL spring, away from the model, pulled by a *Cload of 1.
Both must complete with the default controls, in the same number of increments, and the deck in
no more Newton iterations than its loaded variant (the counts of the log's last line,
"COMPLETED: N increments, M iterations, ..."). `--expect COLUMN=VALUE` checks the last history
row of the deck itself against a closed form (absolute tolerance 1e-6 of max(1, |VALUE|)).

usage: iterations.py CLINCH DECK OUT_DIR [--expect COLUMN=VALUE]..."""

import csv
import os
import re
import subprocess
import sys

# Nodes 901 (held) and 902 (free along x), far from any model node, joined by an AXIAL spring.
EXTRA_MODEL = """** The real load elsewhere (added by iterations.py)
*Node
901, 1000., 1000., 1000.
902, 1001., 1000., 1000.
*Element, type=CONN3D2, elset=ExtraSpring
901, 901, 902
*Connector Section, elset=ExtraSpring, behavior=ExtraK
Axial,
*Connector Behavior, name=ExtraK
*Connector Elasticity, component=1
1000.,
*Boundary
901, 1, 3
902, 2, 3
"""
EXTRA_LOAD = """*Cload
902, 1, 1.
"""


def loaded_variant(text):
    lines = text.splitlines(keepends=True)
    step = next(i for i, l in enumerate(lines) if re.match(r"\*step\b", l, re.I))
    end = next(i for i, l in enumerate(lines) if re.match(r"\*end step\b", l, re.I))
    return "".join(lines[:step] + [EXTRA_MODEL] + lines[step:end] + [EXTRA_LOAD] + lines[end:])


def run(clinch, deck, out, job):
    result = subprocess.run([clinch, "run", "--quiet", "--out", out, "--job", job, deck],
                            capture_output=True, text=True)
    with open(os.path.join(out, job + ".log")) as f:
        last = f.read().rstrip("\n").splitlines()[-1]
    match = re.search(r"COMPLETED: (\d+) increments?, (\d+) iterations?, (\d+) cutbacks?", last)
    if result.returncode != 0 or not match:
        sys.exit(f"{job}: exit {result.returncode}, log ends with: {last}")
    return tuple(int(v) for v in match.groups())


def main():
    clinch, deck, out = sys.argv[1:4]
    expects = []
    rest = sys.argv[4:]
    while rest:
        if rest[0] != "--expect" or len(rest) < 2:
            sys.exit(__doc__)
        column, value = rest[1].rsplit("=", 1)
        expects.append((column, float(value)))
        rest = rest[2:]
    os.makedirs(out, exist_ok=True)
    name = os.path.splitext(os.path.basename(deck))[0]
    with open(deck) as f:
        variant = os.path.join(out, name + "_loaded.inp")
        with open(variant, "w") as g:
            g.write(loaded_variant(f.read()))
    alone = run(clinch, deck, out, name)
    loaded = run(clinch, variant, out, name + "_loaded")
    print(f"{name}: {alone[0]} increments, {alone[1]} iterations, {alone[2]} cutbacks; "
          f"with a real load elsewhere: {loaded[0]} increments, {loaded[1]} iterations, "
          f"{loaded[2]} cutbacks")
    problems = []
    if alone[0] != loaded[0] or alone[2] != loaded[2]:
        problems.append("the increments or cutbacks differ from the loaded variant's")
    if alone[1] > loaded[1]:
        problems.append("more Newton iterations than the loaded variant")
    if expects:
        with open(os.path.join(out, name + ".history.csv")) as f:
            rows = list(csv.DictReader(f))
        for column, value in expects:
            got = float(rows[-1][column])
            if abs(got - value) > 1e-6 * max(1.0, abs(value)):
                problems.append(f"{column} = {got!r}, expected {value!r}")
    for p in problems:
        print(f"{name}: {p}")
    sys.exit(1 if problems else 0)


if __name__ == "__main__":
    main()
