"""`clinch run` stopped from outside, at random times (fixed seed), on a deck of many small
increments that runs a few seconds:
- SIGKILL: the history parses, every complete row is a converged increment of the uninterrupted
  run with increasing time, only the last line may be cut short, and the status file is never
  ahead of the history (each converged attempt it lists has its row);
- SIGINT and SIGTERM: exit 2, the status file ends with `FAILED: interrupted by SIGxxx (step S,
  increment I, time T)`, and the history holds every increment before I, whole.

usage: kill_run.py CLINCH WORKDIR [--kills N] [--seed S]"""

import argparse
import os
import random
import re
import shutil
import signal
import subprocess
import sys
import time

from run_output_lib import (check_history, job_files, last_line, read_lines, status_problems,
                            write_chain_deck)


def start(clinch, deck, out):
    env = dict(os.environ, OPENBLAS_NUM_THREADS="1")
    return subprocess.Popen([clinch, "run", "--quiet", "--out", out, "--job", "job", deck],
                            env=env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)


def wait_for_rows(path, process, rows=2, timeout=20.0):
    """Waits until the history has `rows` rows, so that the signal finds the run under way."""
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline and process.poll() is None:
        if os.path.exists(path):
            with open(path, "rb") as f:
                if f.read().count(b"\n") > rows:
                    return
        time.sleep(0.005)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("clinch")
    parser.add_argument("work")
    parser.add_argument("--kills", type=int, default=10)
    parser.add_argument("--seed", type=int, default=20261202)
    args = parser.parse_args()
    rng = random.Random(args.seed)
    shutil.rmtree(args.work, ignore_errors=True)
    os.makedirs(args.work)
    deck = os.path.join(args.work, "chain.inp")
    write_chain_deck(deck, connectors=2000, increment=1e-3, first_only=True)

    reference_dir = os.path.join(args.work, "reference")
    began = time.monotonic()
    reference = start(args.clinch, deck, reference_dir)
    reference.communicate()
    duration = time.monotonic() - began
    if reference.returncode != 0:
        print(f"FAIL: the uninterrupted run exited with {reference.returncode}")
        return 1
    reference_lines, _ = read_lines(job_files(reference_dir, "job")["history.csv"])
    print(f"uninterrupted run: {len(reference_lines) - 1} rows in {duration:.2f} s")

    problems = []
    trials = [signal.SIGKILL] * args.kills + [signal.SIGINT, signal.SIGTERM] * 2
    stopped_early = 0
    for number, sig in enumerate(trials):
        out = os.path.join(args.work, f"trial-{number}")
        files = job_files(out, "job")
        process = start(args.clinch, deck, out)
        wait_for_rows(files["history.csv"], process)
        time.sleep(rng.uniform(0.0, 0.6 * duration))
        if process.poll() is None:
            process.send_signal(sig)
        _, stderr = process.communicate()
        name = signal.Signals(sig).name
        history_problems, rows = check_history(files["history.csv"], reference_lines)
        trial = history_problems + status_problems(files)
        if rows + 1 < len(reference_lines):
            stopped_early += 1
        if sig != signal.SIGKILL:
            end = last_line(files["sta"])
            stop = re.fullmatch(rf"FAILED: interrupted by {name} \(step 1, increment (\d+), "
                                r"time [0-9.e+-]+\)", end)
            if process.returncode != 2:
                trial.append(f"exit status {process.returncode}, expected 2; stderr: "
                             f"{stderr.decode()[-300:]}")
            if not stop:
                trial.append(f"the status file ends with {end!r}")
            elif rows - 1 != int(stop.group(1)) - 1:  # row 0 is the initial state
                trial.append(f"interrupted at increment {stop.group(1)} but the history's last "
                             f"increment is {rows - 1}")
            if read_lines(files["history.csv"])[1]:
                trial.append("the history ends with a partial line")
        problems += [f"{name} trial {number}: {p}" for p in trial]
        print(f"{name} trial {number}: exit {process.returncode}, {rows} rows"
              f"{'' if not trial else ', FAILED'}")
    if stopped_early < len(trials) // 2:
        problems.append(f"only {stopped_early} of {len(trials)} runs were stopped before the "
                        f"end: the deck is too short for this machine")
    for p in problems:
        print("FAIL:", p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
