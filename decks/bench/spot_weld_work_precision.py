"""Work-precision table of coupled plasticity: the spot weld's mixed paths at increment sizes
from coarse to fine.

The deck is decks/verification/spot_weld_paths (the spot weld of
derived-components-and-potentials.md §3 on five BUSHING connectors: tension, shear, bending and
two paths that cross f3 = 0, the Macaulay kink of the normal measure, while yielding), with N
increments per step (*STATIC, DIRECT). For each N, clinch runs it (median wall time of --repeat runs) and its CTF and
CUP at the end of each of the three steps are compared with the continuous-path reference: the
independent backward-Euler return mapping of spot_weld_paths/reference.py (nested bisections)
run at --reference-increments per step, extrapolated to zero increment (Richardson, first order:
2 u(N_ref) - u(N_ref/2)). The error is the largest difference over the step ends divided by the
largest |value| of that variable over the step ends.

Usage: spot_weld_work_precision.py CLINCH [--sizes 1,2,4,...] [--repeat 3]
                                        [--reference-increments 1024] [--work DIR]
"""

import argparse
import csv
import importlib.util
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
CASE = os.path.join(HERE, "..", "verification", "spot_weld_paths")
ELEMENTS = (1, 2, 3, 4, 5)


def load_reference_module():
    sys.dont_write_bytecode = True
    sys.path.insert(0, os.path.join(CASE, ".."))
    spec = importlib.util.spec_from_file_location("spot_weld_reference",
                                                  os.path.join(CASE, "reference.py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def reference_step_ends(ref, increments):
    """CTF (= F) and CUP of each element at the end of each step, N increments per step."""
    welds = {el: ref.SpotWeld() for el in ELEMENTS}
    _, rows = ref.path_rows({el: ref.TARGETS[el] for el in ELEMENTS}, increments, welds)
    ends = []
    for step in range(1, 4):
        values = [r for r in rows if r[0] == step][-1][4]
        ends.append({el: (values[k * ref.COLUMNS:k * ref.COLUMNS + 6],
                          values[k * ref.COLUMNS + 6:k * ref.COLUMNS + 12])
                     for k, el in enumerate(ELEMENTS)})
    return ends


def deck_text(template, increments):
    """The verification deck with N increments per step."""
    out = []
    for line in template.splitlines():
        if line.strip().replace(" ", "").startswith("0.2,1."):
            line = f"{1.0 / increments!r}, 1."
        elif line.upper().startswith("*STEP,"):
            line = line + f", INC={max(100, increments)}"
        out.append(line)
    return "\n".join(out) + "\n"


def clinch_step_ends(clinch, deck, work, repeat):
    job = "wp"
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        proc = subprocess.run([clinch, "run", "--quiet", "--out", work, "--job", job, deck],
                              stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        times.append(time.perf_counter() - start)
        if proc.returncode != 0:
            raise RuntimeError(f"clinch run failed ({proc.returncode}): {proc.stderr[-500:]}")
    with open(os.path.join(work, job + ".history.csv")) as f:
        rows = list(csv.DictReader(f))
    last_of_step = {}
    for row in rows:
        last_of_step[int(row["step"])] = row
    ends = []
    for step in (1, 2, 3):
        row = last_of_step[step]
        ends.append({el: ([float(row[f"CTF{i}@{el}"]) for i in range(1, 7)],
                          [float(row[f"CUP{i}@{el}"]) for i in range(1, 7)]) for el in ELEMENTS})
    with open(os.path.join(work, job + ".log")) as f:
        log = f.read()
    iterations = int(log.rsplit(" increments, ", 1)[1].split(" iterations")[0])
    return statistics.median(times), iterations, ends


def relative_error(ends, ref, which):
    scale = max(abs(x) for e in ref for el in ELEMENTS for x in e[el][which])
    worst = max(abs(a - b) for e, r in zip(ends, ref) for el in ELEMENTS
                for a, b in zip(e[el][which], r[el][which]))
    return worst / scale


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("clinch")
    parser.add_argument("--sizes", default="1,2,4,8,16,32,64,128,256")
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--reference-increments", type=int, default=1024)
    parser.add_argument("--work")
    args = parser.parse_args()
    work = args.work or tempfile.mkdtemp(prefix="clinch-wp-")
    os.makedirs(work, exist_ok=True)

    cache = os.path.join(work, f"reference-{args.reference_increments}.json")
    if os.path.exists(cache):
        with open(cache) as f:
            reference = json.load(f)
    else:
        ref = load_reference_module()
        started = time.perf_counter()
        fine = reference_step_ends(ref, args.reference_increments)
        half = reference_step_ends(ref, args.reference_increments // 2)
        reference = []
        for e_fine, e_half in zip(fine, half):
            reference.append({str(el): [[2 * a - b for a, b in zip(e_fine[el][w], e_half[el][w])]
                                        for w in (0, 1)] for el in ELEMENTS})
        spread = max(relative_error(fine, [{el: r[str(el)] for el in ELEMENTS} for r in reference],
                                    w) for w in (0, 1))
        print(f"reference: {args.reference_increments} and {args.reference_increments // 2} "
              f"increments per step, extrapolated; |fine - extrapolated| = {spread:.2e} "
              f"(relative); {time.perf_counter() - started:.0f} s")
        with open(cache, "w") as f:
            json.dump(reference, f)
    reference = [{el: r[str(el)] for el in ELEMENTS} for r in reference]

    with open(os.path.join(CASE, "spot_weld_paths.inp")) as f:
        template = f.read()
    print(f"{'inc/step':>8} {'wall s':>9} {'Newton it':>9} {'err CTF':>9} {'err CUP':>9}")
    for n in (int(s) for s in args.sizes.split(",")):
        deck = os.path.join(work, f"spot_weld_{n}.inp")
        with open(deck, "w") as f:
            f.write(deck_text(template, n))
        seconds, iterations, ends = clinch_step_ends(args.clinch, deck, work, args.repeat)
        print(f"{n:8d} {seconds:9.4f} {iterations:9d} {relative_error(ends, reference, 0):9.2e} "
              f"{relative_error(ends, reference, 1):9.2e}")


if __name__ == "__main__":
    sys.exit(main())
