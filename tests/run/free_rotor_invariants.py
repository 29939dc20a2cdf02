"""The spatial angular momentum and the kinetic energy of a torque-free rigid body under the
finite-rotation update (docs/dynamics.md "Finite rotations") stay constant.

Usage: free_rotor_invariants.py CLINCH OUTDIR. Runs decks/verification/dynamic_free_rigid_rotor
and reads every output row (UR = the rotation vector phi of R = exp(phi), VR = the spatial angular
velocity omega); with J the deck's tensor (the body's, in the reference axes), pi = R J R^T omega
and T = omega . R J R^T omega / 2. The scheme conserves both exactly; what is left is Newton's
stopping point in each of the 400 increments (the deck's moment tolerance of 1e-10 of *CONTROLS)
and rounding: the measured drift is 1.7e-8 of pi and 3.3e-8 of T at the end of the run. 1e-6
bounds it with margin, while it is far below the discretisation error of the angular velocity
itself (2.5e-6, the verification case's README), which a scheme that only approximates the
invariants would show in them as well."""
import csv
import math
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
CASE = os.path.join(HERE, "..", "..", "decks", "verification", "dynamic_free_rigid_rotor")
J = [[2.0, 0.1, -0.2], [0.1, 3.0, 0.15], [-0.2, 0.15, 4.0]]
TOLERANCE = 1e-6


def expm(v):
    t = math.sqrt(sum(c * c for c in v))
    k = [[0.0, -v[2], v[1]], [v[2], 0.0, -v[0]], [-v[1], v[0], 0.0]]
    k2 = [[sum(k[i][m] * k[m][j] for m in range(3)) for j in range(3)] for i in range(3)]
    a = math.sin(t) / t if t > 1e-8 else 1.0
    b = (1.0 - math.cos(t)) / (t * t) if t > 1e-8 else 0.5
    return [[(i == j) + a * k[i][j] + b * k2[i][j] for j in range(3)] for i in range(3)]


def main():
    clinch, out = sys.argv[1], sys.argv[2]
    deck = os.path.join(CASE, "dynamic_free_rigid_rotor.inp")
    run = subprocess.run([clinch, "run", "--quiet", "--out", out, deck], capture_output=True,
                         text=True)
    if run.returncode != 0:
        sys.exit(f"FAIL: clinch run exited {run.returncode}: {run.stderr}")
    with open(os.path.join(out, "dynamic_free_rigid_rotor.history.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    first = None
    for row in rows:
        r = expm([float(row[f"UR{d}@1"]) for d in (1, 2, 3)])
        omega = [float(row[f"VR{d}@1"]) for d in (1, 2, 3)]
        w = [sum(r[m][i] * omega[m] for m in range(3)) for i in range(3)]  # R^T omega
        jw = [sum(J[i][m] * w[m] for m in range(3)) for i in range(3)]
        pi = [sum(r[i][m] * jw[m] for m in range(3)) for i in range(3)]
        energy = 0.5 * sum(w[i] * jw[i] for i in range(3))
        if first is None:
            first = (pi, energy)
            continue
        drift = max(abs(a - b) for a, b in zip(pi, first[0])) / max(abs(c) for c in first[0])
        if drift > TOLERANCE or abs(energy - first[1]) > TOLERANCE * first[1]:
            sys.exit(f"FAIL: at t = {row['total_time']}: pi = {pi} (from {first[0]}, relative "
                     f"{drift:.3e}), T = {energy!r} (from {first[1]!r})")
    print(f"PASS: angular momentum and kinetic energy kept over {len(rows)} rows")


if __name__ == "__main__":
    main()
