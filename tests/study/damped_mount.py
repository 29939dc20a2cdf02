"""`clinch study` on a damped engine mount (tests/study/damped_mount.inp) against the closed form.

The mount's motion is prescribed, u(t) = A sin(w t) (A = 0.01, w = 2 pi), so the exact damping
force is c u'(t) = c A w cos(w t), and a *Static step's damping force at a row is
c (u(t) - u(t - dt))/dt (behaviors.md section 8): setting s (dt = 0.05 / 2^(s-1)) misses the exact
force by a known amount at each time. The study measures errors against the largest force of the
model (the largest |CEF1|, |CVF1|, |CRF1| = |k u + c du/dt| over every run and row), so:
- the study's scale of CVF1@1 is that largest force, computed here from the closed form;
- its estimated error of CVF1@1 at the coarse settings (1 and 2: 20 and 40 increments a cycle)
  is within 10 % of the true error, max over the coarse times |CVF1 - c u'| / scale. 10 %:
  Richardson's limit from the finest settings leaves an error of the order of (w dt)^2 / 6 of the
  force (below 1e-3 at 160 increments a cycle), and the observed order differs from 1 by O(w dt),
  so the estimate of a first-order error of 14 % is good to a few per cent of itself;
- the worst column of setting 1 is the damping force (CVF1@1) or the reaction that carries it
  (CRF1@1, which the driven motion makes -(CEF1 + CVF1)), with an error above 10 % of the force
  scale: the damping error at 20 increments a cycle is reported, not hidden;
- CTF1@1, which the motion's reaction balances to round-off, is left out and the output says so.

Usage: damped_mount.py CLINCH WORK
"""
import csv
import math
import os
import shutil
import subprocess
import sys

A, W, K, C = 0.01, 2.0 * math.pi, 100.0, 50.0
LEVELS, DT = 4, 0.05


def u(t):
    return A * math.sin(W * t)


def main():
    clinch, work = sys.argv[1:3]
    shutil.rmtree(work, ignore_errors=True)
    deck = os.path.join(os.path.dirname(os.path.abspath(__file__)), "damped_mount.inp")
    out = subprocess.run([clinch, "study", "--levels", str(LEVELS), "--no-plot", "--work", work,
                          deck], capture_output=True, text=True)
    assert out.returncode == 0, out.stdout + out.stderr
    assert "left out: 1 column zero to round-off" in out.stdout and "CTF1@1" in out.stdout, \
        out.stdout

    # The largest force over every setting and row (the rows of setting s are t = j dt_s).
    scale = 0.0
    for s in range(LEVELS):
        dt = DT / 2 ** s
        for j in range(1, round(1.0 / dt) + 1):
            t = j * dt
            viscous = C * (u(t) - u(t - dt)) / dt
            scale = max(scale, abs(K * u(t)), abs(viscous), abs(K * u(t) + viscous))
    coarse = [i * DT for i in range(1, 21)]
    true_error = []
    for s in range(LEVELS):
        dt = DT / 2 ** s
        worst = max(abs(C * (u(t) - u(t - dt)) / dt - C * A * W * math.cos(W * t))
                    for t in coarse)
        true_error.append(worst / scale)

    with open(os.path.join(work, "damped_mount.study-columns.csv"), newline="") as f:
        rows = [r for r in csv.DictReader(f) if r["column"] == "CVF1@1"]
    problems = []
    # The tabulated sine (400 points a cycle) differs from the sine by 3e-7 of A at most.
    if abs(float(rows[0]["column_scale"]) / scale - 1.0) > 1e-5:
        problems.append(f"scale {rows[0]['column_scale']} against {scale}")
    for s in (0, 1):
        estimate = float(rows[s]["estimated_error"])
        if abs(estimate / true_error[s] - 1.0) > 0.10:
            problems.append(f"setting {s + 1}: estimated {estimate:.4g}, true {true_error[s]:.4g}")
    with open(os.path.join(work, "damped_mount.study.csv"), newline="") as f:
        first = next(csv.DictReader(f))
    if first["worst_column"] not in ("CVF1@1", "CRF1@1") or float(first["estimated_error"]) < 0.1:
        problems.append(f"setting 1: worst column {first['worst_column']} "
                        f"{first['estimated_error']}")
    if problems:
        print("\n".join(problems), file=sys.stderr)
        return 1
    print(f"damping error at 20 and 40 increments a cycle: estimated "
          f"{float(rows[0]['estimated_error']):.4f}, {float(rows[1]['estimated_error']):.4f}; "
          f"true {true_error[0]:.4f}, {true_error[1]:.4f} of the force scale {scale:.5g}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
