#!/usr/bin/env python3
"""Runs one example deck and checks a history value against its closed form.

    check_key_number.py CLINCH DECK OUT_DIR COLUMN TOTAL_TIME EXPECTED RTOL

EXPECTED is a Python expression (math's functions allowed, e.g. "100*(1-(1-exp(-1.5))/(1-exp(-3)))"),
so that the test states the closed form rather than a number copied from a run. The value of
COLUMN in the row at TOTAL_TIME must satisfy |value - expected| <= RTOL * max(|expected|, 1e-300).
Exit 0 when it does, 1 when it does not or the run fails.
"""
import csv
import math
import os
import subprocess
import sys


def main():
    if len(sys.argv) != 8:
        sys.exit(__doc__)
    clinch, deck, out_dir, column, time_text, expected_text, rtol_text = sys.argv[1:]
    expected = float(eval(expected_text, {"__builtins__": {}}, vars(math)))
    rtol = float(rtol_text)
    os.makedirs(out_dir, exist_ok=True)
    run = subprocess.run([clinch, "run", "--quiet", "--out", out_dir, deck],
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if run.returncode != 0:
        print(run.stderr)
        print(f"clinch run exited with {run.returncode}")
        return 1
    job = os.path.splitext(os.path.basename(deck))[0]
    with open(os.path.join(out_dir, job + ".history.csv"), newline="") as table:
        rows = list(csv.reader(table))
    header = rows[0]
    if column not in header:
        print(f"no column {column} in {header}")
        return 1
    time = float(time_text)
    matches = [row for row in rows[1:]
               if abs(float(row[header.index("total_time")]) - time) <= 1e-12 * max(1.0, time)]
    if not matches:
        print(f"no row at total_time {time}")
        return 1
    value = float(matches[-1][header.index(column)])
    error = abs(value - expected)
    allowed = rtol * max(abs(expected), 1e-300)
    verdict = "ok" if error <= allowed else "FAILED"
    print(f"{job}: {column} at total_time {time}: {value!r}, closed form {expected_text} = "
          f"{expected!r}, |difference| {error:.3g} (allowed {allowed:.3g}): {verdict}")
    return 0 if error <= allowed else 1


if __name__ == "__main__":
    sys.exit(main())
