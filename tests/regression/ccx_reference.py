#!/usr/bin/env python3
"""Runs a CalculiX test deck through `clinch run` and checks the history table against the
deck's upstream golden `.dat` output, value by value, to the digits CalculiX prints.

usage: ccx_reference.py CLINCH DECK.inp REFERENCE.dat.ref [SCALE_TOLERANCE]

CalculiX prints 7 significant digits (%.6E). A value passes when clinch's value, rounded the same
way, equals the printed one (a difference below half a unit of the last printed digit). With
SCALE_TOLERANCE, a value also passes within that fraction of the largest printed magnitude of
its block: the components that are round-off of a larger solution (1e-8 of a reaction of 5)
are compared at the scale of the solution, not at their own. Nodal components that are not
active in clinch (no column) must be printed as 0 by CalculiX.
"""
import csv
import os
import re
import subprocess
import sys
import tempfile

BLOCK = re.compile(r"^\s*(displacements|forces) \((\w+),(\w+),(\w+)\) for set (\S+) and time\s+(\S+)")
VARIABLE = {"displacements": "U", "forces": "RF"}


def read_reference(path):
    blocks, current = [], None
    with open(path) as f:
        for line in f:
            m = BLOCK.match(line)
            if m:
                current = {"variable": VARIABLE[m.group(1)], "time": float(m.group(6)), "rows": []}
                blocks.append(current)
                continue
            fields = line.split()
            if current is not None and len(fields) == 4 and fields[0].isdigit():
                current["rows"].append((fields[0], [float(v) for v in fields[1:]]))
            elif fields and current is not None and current["rows"]:
                current = None
    return blocks


def matches(value, printed, floor=0.0):
    return (float(f"{value:.6E}") == printed or
            abs(value - printed) <= max(5e-7 * abs(printed), floor))


def main():
    clinch, deck, reference = sys.argv[1:4]
    scale_tolerance = float(sys.argv[4]) if len(sys.argv) > 4 else 0.0
    # The decks live beside the repository, not in it: without them the test is skipped (77).
    if not os.path.exists(deck):
        print(f"skipped: {deck} is not there")
        return 77
    job = os.path.splitext(os.path.basename(deck))[0]
    with tempfile.TemporaryDirectory() as out:
        run = subprocess.run([clinch, "run", deck, "--out", out, "--quiet"], capture_output=True,
                             text=True)
        if run.returncode != 0:
            print(f"clinch run exited with {run.returncode}\n{run.stderr}")
            return 1
        with open(os.path.join(out, job + ".history.csv")) as f:
            rows = list(csv.DictReader(f))
    blocks = read_reference(reference)
    if not blocks:
        print(f"no output blocks found in {reference}")
        return 1
    failures = checked = 0
    for block in blocks:
        row = next((r for r in reversed(rows) if float(r["total_time"]) == block["time"]), None)
        if row is None:
            print(f"no clinch row at total_time {block['time']}")
            return 1
        largest = max((abs(v) for _, values in block["rows"] for v in values), default=0.0)
        for node, values in block["rows"]:
            for k, printed in enumerate(values, start=1):
                column = f"{block['variable']}{k}@{node}"
                value = float(row[column]) if column in row else 0.0
                checked += 1
                if not matches(value, printed, scale_tolerance * largest):
                    failures += 1
                    print(f"FAIL {column} at t={block['time']}: clinch {value!r}, CalculiX {printed:.6E}")
    print(f"{checked - failures} of {checked} values match {os.path.basename(reference)}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
