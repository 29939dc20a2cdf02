"""`clinch report --connectors 2` on a run with 5 connectors draws the 2 most loaded ones: those
with the largest |CTF1|, |CTF2| or |CTF3| over the run, found here from the history table; and the
page says how many connectors there are and how the drawn ones were chosen.

Usage: most_loaded_connectors.py CLINCH DECK WORK
"""
import csv
import os
import re
import shutil
import subprocess
import sys


def main():
    clinch, deck, work = sys.argv[1:4]
    shutil.rmtree(work, ignore_errors=True)
    subprocess.run([clinch, "run", "--quiet", "--out", work, deck], check=True)
    subprocess.run([clinch, "report", "--quiet", "--connectors", "2", work], check=True)
    job = os.path.splitext(os.path.basename(deck))[0]
    with open(os.path.join(work, job + ".history.csv"), newline="") as f:
        rows = list(csv.reader(f))
    load = {}
    for j, name in enumerate(rows[0]):
        m = re.match(r"CTF[123]@(.+)$", name)
        if m:
            peak = max(abs(float(r[j])) for r in rows[1:])
            load[m.group(1)] = max(load.get(m.group(1), 0.0), peak)
    most = sorted(sorted(load, key=lambda w: -load[w])[:2])
    with open(os.path.join(work, job + ".report.html"), encoding="utf-8") as f:
        page = f.read()
    drawn = sorted(re.findall(r'data-kind="history-connector" data-where="([^"]*)"', page))
    assert drawn == most, (drawn, most, load)
    assert f"{len(load)} connectors have history columns; the 2 most loaded" in page
    print(f"drew {drawn}, the most loaded of {load}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
