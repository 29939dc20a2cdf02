"""`mpirun -n 2 clinch run` stopped by SIGTERM sent to one rank mid-analysis (docs/parallel.md
"What each rank does"): every rank stops at the same point, mpirun exits 2, the status file's last
line says where, and every history row written before is complete (the header's columns).
The deck is a chain of CARTESIAN connectors with 5000 DIRECT increments, assembled by rows; the
signal goes to rank 1 once the history holds a few rows.

usage: mpi_signal_stop.py CLINCH WORKDIR"""

import os
import shutil
import signal
import subprocess
import sys
import time

from run_output_lib import write_chain_deck


def main():
    clinch, work = sys.argv[1], sys.argv[2]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    deck = os.path.join(work, "chain.inp")
    write_chain_deck(deck, 2000, 2e-4, first_only=True)
    out = os.path.join(work, "out")
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OPENBLAS_NUM_THREADS="1", OMP_NUM_THREADS="1")
    run = subprocess.Popen(["mpirun", "--oversubscribe", "-n", "2", clinch, "run", "--quiet",
                            "--solver", "petsc", "--out", out, "--job", "job", deck],
                           env=env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    history = os.path.join(out, "job.history.csv")
    deadline = time.time() + 120
    while time.time() < deadline and run.poll() is None:
        if os.path.exists(history) and open(history).read().count("\n") >= 6:
            break
        time.sleep(0.05)
    if run.poll() is not None:
        print(f"the run ended before the signal (exit {run.returncode})")
        return 1
    # The ranks are mpirun's children; rank 1 is the one started second.
    ranks = subprocess.run(["pgrep", "-P", str(run.pid), "-f", out], capture_output=True,
                           text=True).stdout.split()
    if len(ranks) != 2:
        print(f"expected 2 ranks under mpirun, found {ranks}")
        run.kill()
        return 1
    os.kill(int(sorted(ranks, key=int)[1]), signal.SIGTERM)
    try:
        _, err = run.communicate(timeout=60)
    except subprocess.TimeoutExpired:
        run.kill()
        print("the ranks did not stop within 60 s of the signal")
        return 1
    failures = []
    if run.returncode != 2:
        failures.append(f"mpirun exited {run.returncode}, expected 2: {err.decode()[-400:]}")
    left = subprocess.run(["pgrep", "-f", out], capture_output=True, text=True).stdout.split()
    if left:
        failures.append(f"ranks still running: {left}")
    with open(os.path.join(out, "job.sta")) as f:
        last = f.read().splitlines()[-1]
    if not (last.startswith("FAILED: interrupted by SIGTERM") and "increment" in last):
        failures.append(f"status line: {last!r}")
    with open(history) as f:
        text = f.read()
    rows = text.split("\n")
    if not text.endswith("\n"):
        failures.append("the history ends in a partial row")
    header = rows[0].count(",")
    for row in rows[1:-1]:
        if row.count(",") != header:
            failures.append(f"incomplete history row: {row!r}")
    print(f"stopped: {last}; {len(rows) - 2} history rows")
    for failure in failures:
        print(failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
