"""A snap-back under displacement control (tests/run/snap_back_driven*.inp): the run completes,
and every history row lies on the equilibrium path computed here independently.

Connector 1 (k = 100, FORCE initiation at 10, linear softening over 0.02: damage_lib's
ElasticDamage along the run's u2) in series with connector 2 (k = 20); node 3 prescribed at
0.8 t. Per row: U1@3 = 0.8 t, CTF1@1 and CDMG@1 = the reference at U1@2, CTF1@2 = 20 (u3 - u2) =
CTF1@1. Past u3 = 0.6 the only equilibrium is the failed connector (d = 1, u2 = u3), which the
rows must show. Tolerance 1e-8 of the peak force 10: the deck asks for residuals of 1e-10 of the
force flux.

Usage: check_snap_back_driven.py CLINCH DECK OUTDIR [RUN OPTION...]
CLINCH may be a command line (split as a shell would: "mpirun -n 2 clinch"); the options after
OUTDIR are passed to `clinch run` (--solver petsc).
"""
import csv
import os
import shlex
import subprocess
import sys

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "decks",
                                "verification"))
import damage_lib  # noqa: E402


def main(clinch, deck, out, *options):
    job = os.path.splitext(os.path.basename(deck))[0]
    proc = subprocess.run([*shlex.split(clinch), "run", "--quiet", "--out", out, *options, deck],
                          stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    failures = []
    if proc.returncode != 0:
        failures.append(f"exit {proc.returncode}: {proc.stderr[-500:]}")
    with open(os.path.join(out, job + ".history.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    soft = damage_lib.ElasticDamage(100.0, 10.0, ("LINEAR", 0.02))
    tol = 1e-8 * 10.0
    failed = False
    for r in rows:
        t, u2, u3 = (float(r[k]) for k in ("step_time", "U1@2", "U1@3"))
        force, damage, spring = (float(r[k]) for k in ("CTF1@1", "CDMG@1", "CTF1@2"))
        expected_force, expected_damage, _ = soft.update(u2)
        checks = [("U1@3 = 0.8 t", u3 - 0.8 * t),
                  ("CTF1@1 = reference", force - expected_force),
                  ("CDMG@1 = reference", 10.0 * (damage - expected_damage)),
                  ("CTF1@2 = 20 (u3 - u2)", spring - 20.0 * (u3 - u2)),
                  ("CTF1@2 = CTF1@1", spring - force)]
        for what, error in checks:
            if abs(error) > tol:
                failures.append(f"increment {r['increment']}: {what}: off by {error:.3e}")
        if u3 > 0.6 + 1e-9 and damage != 1.0:
            failures.append(f"increment {r['increment']}: u3 = {u3} past the snap-back, d = {damage}")
        failed = failed or damage == 1.0
    if not failed:
        failures.append("no row past the snap-back")
    with open(os.path.join(out, job + ".log")) as f:
        if "the path inside an increment" not in f.read():
            failures.append("the log does not say that the path inside an increment was followed")
    for line in failures:
        print(line)
    print(f"{job}: {len(rows) - 1} increments checked, {len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:]))
