"""`clinch study` stopped from outside while a setting runs (docs/study-and-report.md, "Stopping
a study"), on a deck whose finer settings run for tens of seconds, with one run at a time:
- SIGTERM and SIGINT: the study forwards the signal to its running `clinch run`, waits for it,
  writes its table (setting 1 completed, setting 2 interrupted by the signal, setting 3 not run)
  and exits with 2; no child survives it;
- SIGKILL: the running child is sent SIGTERM by the kernel when the study dies, and stops as
  `clinch run` does on it.
The signal is sent once setting 2 has written history rows, so that it finds the run under way.

usage: stop_study.py CLINCH WORKDIR"""

import csv
import os
import shutil
import signal
import subprocess
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "run"))
from run_output_lib import write_chain_deck  # noqa: E402

WAIT = 300.0  # seconds: only a bound for a hung study, not a measure of speed


def children(pid):
    """The processes whose parent is `pid`."""
    found = []
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open(f"/proc/{entry}/stat") as f:
                fields = f.read().rsplit(")", 1)[1].split()
        except OSError:
            continue
        if int(fields[1]) == pid:
            found.append(int(entry))
    return found


def alive(pid):
    """True while `pid` runs (a zombie has ended)."""
    try:
        with open(f"/proc/{pid}/stat") as f:
            return f.read().rsplit(")", 1)[1].split()[0] != "Z"
    except OSError:
        return False


def history_rows(path):
    try:
        with open(path, "rb") as f:
            return f.read().count(b"\n") - 1
    except OSError:
        return 0


def last_line(path):
    with open(path) as f:
        return f.read().rstrip("\n").rsplit("\n", 1)[-1]


def start_study(clinch, deck, work):
    """Starts the study and returns it once setting 2 runs, with its `clinch run` child."""
    study = subprocess.Popen(
        [clinch, "study", "--jobs", "1", "--levels", "3", "--ratio", "100", "--no-plot",
         "--work", work, deck],
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
        env=dict(os.environ, OPENBLAS_NUM_THREADS="1"))
    history = os.path.join(work, "setting-2", "chain.history.csv")
    deadline = time.monotonic() + WAIT
    while history_rows(history) < 2:
        if study.poll() is not None or time.monotonic() > deadline:
            study.kill()
            out, err = study.communicate()
            raise SystemExit(f"FAIL: setting 2 never ran (exit {study.returncode}): {err}")
        time.sleep(0.01)
    runs = children(study.pid)
    if len(runs) != 1:
        study.kill()
        raise SystemExit(f"FAIL: {len(runs)} children while setting 2 runs, 1 expected")
    return study, runs[0]


def stopped_cleanly(clinch, deck, work, sig):
    problems = []
    name = signal.Signals(sig).name
    study, run = start_study(clinch, deck, work)
    study.send_signal(sig)
    try:
        out, err = study.communicate(timeout=WAIT)
    except subprocess.TimeoutExpired:
        study.kill()
        return [f"{name}: the study did not end"]
    if study.returncode != 2:
        problems.append(f"{name}: exit {study.returncode}, 2 expected; stderr: {err}")
    if alive(run):
        problems.append(f"{name}: its clinch run {run} survived it")
    expected_error = f"clinch: error: interrupted by {name}: 1 of 3 settings completed"
    if expected_error not in err:
        problems.append(f"{name}: stderr lacks {expected_error!r}: {err}")
    table = os.path.join(work, "chain.study.csv")
    if not os.path.exists(table):
        return problems + [f"{name}: no {table}"]
    with open(table, newline="") as f:
        rows = list(csv.DictReader(f))
    states = [(r["setting"], r["state"]) for r in rows]
    if states != [("1", "completed"), ("2", "failed"), ("3", "not-run")]:
        problems.append(f"{name}: settings {states}")
    elif not rows[1]["status"].startswith(f"FAILED: interrupted by {name} (step 1, increment "):
        problems.append(f"{name}: setting 2 status {rows[1]['status']!r}")
    elif rows[2]["status"] != f"not run: the study was interrupted by {name}":
        problems.append(f"{name}: setting 3 status {rows[2]['status']!r}")
    elif not rows[0]["increments"] == "100":
        problems.append(f"{name}: setting 1 has {rows[0]['increments']} increments, 100 expected")
    return problems


def killed(clinch, deck, work):
    study, run = start_study(clinch, deck, work)
    study.send_signal(signal.SIGKILL)
    study.communicate()
    deadline = time.monotonic() + WAIT
    while alive(run) and time.monotonic() < deadline:
        time.sleep(0.01)
    if alive(run):
        os.kill(run, signal.SIGKILL)
        return ["SIGKILL: the clinch run of setting 2 outlived the study"]
    status = last_line(os.path.join(work, "setting-2", "chain.sta"))
    if not status.startswith("FAILED: interrupted by SIGTERM"):
        return [f"SIGKILL: setting 2 ended with {status!r}, not stopped by SIGTERM"]
    return []


def main():
    if len(sys.argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    clinch, base = sys.argv[1], sys.argv[2]
    shutil.rmtree(base, ignore_errors=True)
    os.makedirs(base)
    deck = os.path.join(base, "chain.inp")
    # 100 increments in setting 1, 10⁴ in setting 2, 10⁶ in setting 3.
    write_chain_deck(deck, connectors=2000, increment=1e-2, first_only=True)
    problems = []
    for sig in (signal.SIGTERM, signal.SIGINT):
        problems += stopped_cleanly(clinch, deck, os.path.join(base, signal.Signals(sig).name),
                                    sig)
    problems += killed(clinch, deck, os.path.join(base, "SIGKILL"))
    for p in problems:
        print("FAIL:", p)
    if not problems:
        print("SIGTERM, SIGINT: exit 2, table written, no child left; SIGKILL: child stopped")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
