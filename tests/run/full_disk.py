"""A disk that fills during a run (cli-contract.md: exit 3 = I/O error): `clinch run` writes into a
64 kB tmpfs, in a mount namespace of its own so that nothing is left mounted, decks whose
outputs outgrow it: one whose history fills it, one whose log does. The run must exit with 3,
say on stderr which file could not be written at which step and increment, never claim
completion, and leave a history whose complete rows are the converged increments of the same
run on a normal disk, with the status file not ahead of it.

With `--mpi N` both runs are `mpirun -n N ... --solver petsc` (a distributed model): rank 0
writes the outputs, fails alone, and stops every rank at the same point (docs/parallel.md).

usage: full_disk.py CLINCH WORKDIR [--mpi N]; exits with 77 (CTest SKIP_RETURN_CODE) when no
size-limited filesystem can be mounted here."""

import os
import re
import shutil
import subprocess
import sys

from run_output_lib import (check_history, job_files, last_line, read_lines, status_problems,
                            write_chain_deck)

SKIP = 77
# Mounts a 64 kB tmpfs on $1, runs the command that follows $2 (clinch run and its deck) into it
# (job full), and copies what the run wrote to $2 before the namespace and its mount go away.
INSIDE = """
mount -t tmpfs -o size=64k tmpfs "$1" || exit 125
mnt=$1 kept=$2
shift 2
"$@" --out "$mnt" --job full 2>"$kept/stderr"
status=$?
cp "$mnt"/full.* "$kept"/
exit $status
"""


def fill(clinch, work, deck_options, launcher):
    """Runs the deck that `deck_options` describe on a normal disk and on the small one, each
    through `launcher` (a list: nothing, or mpirun and its options); returns the problems (a
    list), or None when no small filesystem can be mounted."""
    shutil.rmtree(work, ignore_errors=True)
    mount_point, kept, normal = (os.path.join(work, d) for d in ("mnt", "kept", "normal"))
    for d in (mount_point, kept, normal):
        os.makedirs(d)
    deck = os.path.join(work, "chain.inp")
    write_chain_deck(deck, **deck_options)

    env = dict(os.environ, OPENBLAS_NUM_THREADS="1", OMPI_ALLOW_RUN_AS_ROOT="1",
               OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    command = launcher + [clinch, "run", "--quiet", deck]
    if launcher:
        command += ["--solver", "petsc"]
    reference = subprocess.run(command + ["--out", normal, "--job", "full"], env=env, timeout=600)
    if reference.returncode != 0:
        return [f"the run on a normal disk exited with {reference.returncode}"]
    reference_lines, _ = read_lines(job_files(normal, "full")["history.csv"])

    status = None
    for unshare in (["unshare", "-m"], ["unshare", "-r", "-m"]):
        if shutil.which(unshare[0]) is None:
            break
        run = subprocess.run(unshare + ["sh", "-c", INSIDE, "sh", mount_point, kept] + command,
                             env=env, stderr=subprocess.DEVNULL, timeout=600)
        if run.returncode != 125 and os.path.exists(os.path.join(kept, "stderr")):
            status = run.returncode
            break
    if status is None:
        return None

    problems = []
    if status != 3:
        problems.append(f"exit status {status}, expected 3")
    with open(os.path.join(kept, "stderr")) as f:
        stderr = f.read()
    failed = re.search(r"cannot write '" + re.escape(mount_point) +
                       r"/full\.(history\.csv|sta|log)': No space left on device "
                       r"\(step 1, increment (\d+), time [0-9.e+-]+\)", stderr)
    if not failed:
        problems.append(f"stderr does not say which file failed where:\n{stderr}")
    files = job_files(kept, "full")
    sta_end = last_line(files["sta"])
    if "COMPLETED" in sta_end or "COMPLETED" in stderr:
        problems.append("the run claims completion")
    if sta_end.startswith("FAILED") and "No space left on device" not in sta_end:
        problems.append(f"the status file ends with another failure: {sta_end}")
    history_problems, rows = check_history(files["history.csv"], reference_lines)
    problems += history_problems + status_problems(files, deck_options.get("frequency", 1))
    if rows + 1 >= len(reference_lines):
        problems.append(f"the run wrote its whole history ({rows} rows)")
    if not problems:
        print(f"ok: {failed.group(1)} filled at increment {failed.group(2)}; the history keeps "
              f"{rows} of {len(reference_lines) - 1} rows, each a converged increment; "
              f"status file ends with: {sta_end}")
    return problems


def main():
    clinch, work = sys.argv[1], sys.argv[2]
    launcher = []
    if sys.argv[3:4] == ["--mpi"]:
        launcher = ["mpirun", "--oversubscribe", "-n", sys.argv[4]]
    problems = []
    # A wide history fills the disk first; then a narrow one, written every 10 increments, where
    # the log and the status file do.
    for name, deck_options in (("wide", dict(connectors=40, increment=1e-3)),
                               ("narrow", dict(connectors=40, increment=1e-3, first_only=True,
                                               frequency=10))):
        found = fill(clinch, os.path.join(work, name), deck_options, launcher)
        if found is None:
            print("SKIP: cannot mount a size-limited tmpfs in a new mount namespace here "
                  "(needs root or unprivileged user namespaces)")
            return SKIP
        problems += [f"{name} history: {p}" for p in found]
    for p in problems:
        print("FAIL:", p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
