"""`clinch run` stopped by SIGINT or SIGTERM while it reads the deck: exit 2, as for a signal
during the analysis (cli-contract.md), and a status file whose last line says where it stopped.
The deck comes on standard input and the signal is sent once clinch catches it (its SigCgt in
/proc) but before the deck's last line is written, so the signal finds the run reading, every
time, without a race.

usage: signal_while_reading.py CLINCH WORKDIR"""

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
                return int(line.split()[1], 16) >> (sig - 1) & 1 == 1
    return False


def trial(clinch, work, deck_text, sig):
    """Problems (a list) of one run stopped by `sig` while it reads the deck."""
    name = signal.Signals(sig).name
    out = os.path.join(work, name)
    env = dict(os.environ, OPENBLAS_NUM_THREADS="1")
    process = subprocess.Popen([clinch, "run", "--quiet", "--out", out, "--job", "job", "-"],
                               env=env, stdin=subprocess.PIPE, stdout=subprocess.DEVNULL,
                               stderr=subprocess.PIPE)
    deadline = time.monotonic() + 20.0
    while not catches(process.pid, sig):
        if time.monotonic() > deadline or process.poll() is not None:
            process.kill()
            process.communicate()
            return [f"{name}: clinch did not catch {name} while it waited for the deck"]
        time.sleep(0.005)
    process.send_signal(sig)
    _, stderr = process.communicate(deck_text.encode())
    expected = (f"FAILED: interrupted by {name} while reading the deck, before the first "
                f"increment (step 1, increment 0, time 0)")
    problems = []
    if process.returncode != 2:
        problems.append(f"{name}: exit status {process.returncode}, expected 2")
    sta = os.path.join(out, "job.sta")
    end = last_line(sta) if os.path.exists(sta) else None
    if end != expected:
        problems.append(f"{name}: the status file ends with {end!r}, expected {expected!r}")
    message = f"analysis stopped: {expected[len('FAILED: '):]}"
    if message not in stderr.decode():
        problems.append(f"{name}: stderr does not say {message!r}: {stderr.decode()[-300:]!r}")
    return problems


def main():
    clinch, work = sys.argv[1], sys.argv[2]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    deck = os.path.join(work, "chain.inp")
    write_chain_deck(deck, connectors=3, increment=0.1)
    with open(deck) as f:
        deck_text = f.read()
    problems = []
    for sig in (signal.SIGTERM, signal.SIGINT):
        problems += trial(clinch, work, deck_text, sig)
    for p in problems:
        print("FAIL:", p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
