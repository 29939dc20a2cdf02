"""`clinch run` stopped by SIGINT or SIGTERM before its first increment: exit 2, as for a signal
during the analysis (cli-contract.md), and a status file whose last line says where it stopped.
- While reading: the deck comes on standard input, and the signal is sent once clinch catches it
  (its SigCgt in /proc) but before the deck's last line is written, so the signal finds the run
  reading, every time, without a race.
- While planning: a deck of 50 000 connectors, whose plan takes a good part of a second, and the
  signal sent as soon as the log exists (it is created when reading ends). A signal that still
  lands at the end of reading, or in the first increment, must end the run the same way, with the
  status line of that point: all three are accepted, and the one met is printed.

usage: signal_before_analysis.py CLINCH WORKDIR"""

import os
import shutil
import signal
import subprocess
import sys
import time

from run_output_lib import last_line, write_chain_deck


def catches(pid, sig):
    """Whether process `pid` has a handler for `sig` (the SigCgt mask of /proc/PID/status)."""
    with open(f"/proc/{pid}/status") as f:
        for line in f:
            if line.startswith("SigCgt:"):
                return (int(line.split()[1], 16) >> (sig - 1)) & 1 == 1
    return False


def start(clinch, out, deck, stdin=None):
    env = dict(os.environ, OPENBLAS_NUM_THREADS="1")
    return subprocess.Popen([clinch, "run", "--quiet", "--out", out, "--job", "job", deck],
                            env=env, stdin=stdin, stdout=subprocess.DEVNULL,
                            stderr=subprocess.PIPE)


def stop_line(name, where):
    return (f"FAILED: interrupted by {name} {where}, before the first increment "
            f"(step 1, increment 0, time 0)")


def outcome_problems(trial, process, stderr, out, accepted):
    """Problems (a list) of a run that a signal stopped: exit 2, a status file that ends with one
    of the lines `accepted`, and stderr that says the same."""
    problems = []
    if process.returncode != 2:
        problems.append(f"{trial}: exit status {process.returncode}, expected 2")
    sta = os.path.join(out, "job.sta")
    end = last_line(sta) if os.path.exists(sta) else None
    if end not in accepted:
        problems.append(f"{trial}: the status file ends with {end!r}, expected one of {accepted!r}")
    elif f"analysis stopped: {end[len('FAILED: '):]}" not in stderr.decode():
        problems.append(f"{trial}: stderr does not say why: {stderr.decode()[-300:]!r}")
    else:
        print(f"{trial}: {end}")
    return problems


def while_reading(clinch, work, deck_text, sig):
    """Problems (a list) of one run stopped by `sig` while it reads the deck."""
    name = signal.Signals(sig).name
    out = os.path.join(work, f"reading-{name}")
    process = start(clinch, out, "-", stdin=subprocess.PIPE)
    deadline = time.monotonic() + 20.0
    while not catches(process.pid, sig):
        if time.monotonic() > deadline or process.poll() is not None:
            process.kill()
            process.communicate()
            return [f"{name} while reading: clinch did not catch {name} while it waited for the "
                    f"deck"]
        time.sleep(0.005)
    process.send_signal(sig)
    _, stderr = process.communicate(deck_text.encode())
    return outcome_problems(f"{name} while reading", process, stderr, out,
                            [stop_line(name, "while reading the deck")])


def while_planning(clinch, work, deck):
    """Problems (a list) of a run stopped by SIGTERM as soon as its deck has been read."""
    out = os.path.join(work, "planning-SIGTERM")
    log = os.path.join(out, "job.log")
    process = start(clinch, out, deck)
    deadline = time.monotonic() + 60.0
    while not os.path.exists(log):
        if time.monotonic() > deadline or process.poll() is not None:
            process.kill()
            process.communicate()
            return ["SIGTERM while planning: the run ended or took too long before its log "
                    "existed"]
        time.sleep(0.001)
    process.send_signal(signal.SIGTERM)
    _, stderr = process.communicate()
    return outcome_problems("SIGTERM while planning", process, stderr, out,
                            [stop_line("SIGTERM", "while planning the analysis"),
                             stop_line("SIGTERM", "while reading the deck"),
                             "FAILED: interrupted by SIGTERM (step 1, increment 1, time 0)"])


def main():
    clinch, work = sys.argv[1], sys.argv[2]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    small = os.path.join(work, "small.inp")
    write_chain_deck(small, connectors=3, increment=0.1)
    with open(small) as f:
        small_text = f.read()
    large = os.path.join(work, "large.inp")
    write_chain_deck(large, connectors=50000, increment=0.5, first_only=True)
    problems = []
    for sig in (signal.SIGTERM, signal.SIGINT):
        problems += while_reading(clinch, work, small_text, sig)
    problems += while_planning(clinch, work, large)
    for p in problems:
        print("FAIL:", p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
