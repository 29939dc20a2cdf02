"""`clinch study --rtol R` on a verification case: the estimated error of the setting it chooses
must be within a factor of 3 of that setting's true error, measured against the continuous-path
solution computed independently of clinch.

The continuous path (the limit of zero increment) comes from each case's own Python return
mapping, run at two fine increment counts and extrapolated to zero increment (Richardson, first
order, the order of backward Euler): spot_weld_paths/reference.py (nested bisections) and
plastic_lib.QuadraticCoupled (scalar bisection) for plastic_coupled_circle, whose element 1
(circle, perfectly plastic) is also checked against the closed form of the continuous radial
path, tan(theta/2 + pi/4) = tan(theta0/2 + pi/4) exp(k du2 / F_y). friction_square_path has a
closed form along the whole path (decks/bench/friction_work_precision.py).

True and estimated errors are measured as the study measures them: at the times of the
coarsest setting, the largest |value - reference| of a column over the scale of its kind in the
model (forces and moments: the largest |force or moment|; motions: the largest |motion|), and the
worst of the columns the reference computes.

Usage: estimate_vs_reference.py CLINCH CASE WORK RTOL [LEVELS]
"""
import csv
import json
import math
import os
import re
import shutil
import subprocess
import sys

sys.dont_write_bytecode = True
HERE = os.path.dirname(os.path.abspath(__file__))
VERIFICATION = os.path.join(HERE, "..", "..", "decks", "verification")
sys.path.insert(0, VERIFICATION)


SPOT_WELD_ROWS = """
import importlib.util, json, sys
sys.dont_write_bytecode = True
sys.path.insert(0, sys.argv[1])
spec = importlib.util.spec_from_file_location("ref", sys.argv[1] + "/spot_weld_paths/reference.py")
ref = importlib.util.module_from_spec(spec)
spec.loader.exec_module(ref)
names, rows = ref.path_rows(ref.TARGETS, int(sys.argv[2]), {el: ref.SpotWeld() for el in ref.TARGETS})
json.dump([names, [(r[3], r[4]) for r in rows]], sys.stdout)
"""


# Variables by kind (output-variables.md §2, §3), for the study's scales.
FORCES = {"CTF", "CTM", "CEF", "CEM", "CVF", "CVM", "CSF", "CSM", "CRF", "CRM", "CCF", "CCM",
          "CNF", "CNM", "CALPHAF", "CALPHAM", "CSFC", "CNFC", "CDERF", "RF", "RM", "CF", "CM", "S"}
MOTIONS = {"CU", "CUR", "CCU", "CCUR", "CP", "CPR", "CUE", "CURE", "CUP", "CURP", "CUPEQ",
           "CUPEQC", "CASU", "CASUC", "CDERU", "U", "UR", "E"}
RATIOS = {"CDMG", "CDMGR", "CDIF", "CDIFR", "CDIFC", "CDIM", "CDIMR", "CDIMC", "CDIP", "CDIPR",
          "CDIPC"}

def spot_weld_rows(increments):
    """The reference's return mapping along the paths. Run with -O: its assertion that trial
    states stay 1e-6 away from the yield surface (kept for the golden table's five increments)
    trips at fine increments, where loading that continues plastically gives trial states just
    outside the surface; the return itself is the same (as decks/bench/spot_weld_work_precision.py
    runs it)."""
    out = subprocess.run([sys.executable, "-O", "-c", SPOT_WELD_ROWS, VERIFICATION,
                          str(increments)], check=True, capture_output=True, text=True).stdout
    names, rows = json.loads(out)
    return names, [tuple(r) for r in rows]


def circle_rows(increments):
    import plastic_lib as pl
    k = 1000.0
    models = {1: pl.QuadraticCoupled([k, k], [1.0, 1.0], [0.0, 0.0], pl.Hardening([(100.0, 0.0)])),
              2: pl.QuadraticCoupled([k, k], [1.0, 2.0], [0.0, 0.0],
                                     pl.Hardening([(100.0, 0.0), (300.0, 1.0)]))}
    paths = {1: [(0.1, 0.1), (0.1, 0.2)], 2: [(0.1, 0.1), (0.15, 0.2)]}
    names = [f"{v}@{el}" for el in (1, 2) for v in ("CTF1", "CTF2", "CUP1", "CUP2", "CUPEQ")]
    rows = [(0.0, [0.0] * len(names))]
    u = {1: (0.0, 0.0), 2: (0.0, 0.0)}
    for step in range(2):
        start = dict(u)
        for inc in range(1, increments + 1):
            tau = inc / increments
            values = []
            for el in (1, 2):
                target = paths[el][step]
                u[el] = tuple(a + (b - a) * tau for a, b in zip(start[el], target))
                f, _ = models[el].update(list(u[el]))
                values += [f[0], f[1], models[el].up[0], models[el].up[1], models[el].ubar]
            rows.append((step + tau, values))
    return names, rows


def circle_closed_form_check(names, limit_rows):
    """Element 1 at the end of step 2: the force has turned on the yield circle F_y = 100 from
    45 degrees, with d(theta)/cos(theta) = (k/F_y) du2 and du2 = 0.1."""
    theta0 = math.pi / 4
    g = math.log(math.tan(theta0 / 2 + math.pi / 4)) + 1000.0 / 100.0 * 0.1
    theta = 2.0 * (math.atan(math.exp(g)) - math.pi / 4)
    t, values = limit_rows[-1]
    f1, f2 = values[names.index("CTF1@1")], values[names.index("CTF2@1")]
    exact = (100.0 * math.cos(theta), 100.0 * math.sin(theta))
    error = max(abs(f1 - exact[0]), abs(f2 - exact[1])) / 100.0
    print(f"circle closed form at t = {t}: CTF1, CTF2 = {exact[0]:.9g}, {exact[1]:.9g}; "
          f"extrapolated reference {f1:.9g}, {f2:.9g} (relative {error:.1e})")
    assert error < 1e-5, error


def friction_rows(increments):
    """friction_square_path in closed form (decks/bench/friction_work_precision.py exact_side:
    stick until |f| reaches F_lim, then the force turns towards the side's direction with
    tan(theta/2) decaying as exp(-(k/F_lim) s)), at `increments` points per step; exact at
    every point, so no extrapolation is needed. Step 1 presses (no tangential motion), steps
    2-9 drive node b around the square twice."""
    sys.path.insert(0, os.path.join(VERIFICATION, "..", "bench"))
    import friction_work_precision as wp
    k, flim, side = 1.0e4, 0.25 * 410.0, 0.02
    wp.STICK, wp.CAPACITY = k, flim
    corners = [(0.0, 0.0)] + [(side, 0.0), (side, side), (0.0, side), (0.0, 0.0)] * 2
    names = ["CSF2@40", "CSF3@40", "CSF2@41", "CSF3@41", "CASUC@41"]
    rows = [(i / increments, [0.0] * len(names)) for i in range(increments + 1)]
    f, gamma = (0.0, 0.0), 0.0
    for n, (p, q) in enumerate(zip(corners, corners[1:]), start=1):
        length = math.hypot(q[0] - p[0], q[1] - p[1])
        e = ((q[0] - p[0]) / length, (q[1] - p[1]) / length)
        for i in range(1, increments + 1):
            fi, gi = wp.exact_side(f, gamma, e, length * i / increments)
            rows.append((n + i / increments, [fi[0], fi[1], fi[0], fi[1], gi]))
        f, gamma = fi, gi
    return names, rows


CASES = {
    "spot_weld_paths": (spot_weld_rows, 1024, None),
    "friction_square_path": (friction_rows, 0, None),
    "plastic_coupled_circle": (circle_rows, 4096, circle_closed_form_check),
}


def interpolate(times, values, t):
    for i in range(1, len(times)):
        if times[i] >= t - 1e-12:
            if abs(times[i] - t) <= 1e-12:
                return values[i]
            w = (t - times[i - 1]) / (times[i] - times[i - 1])
            return values[i - 1] + w * (values[i] - values[i - 1])
    return values[-1]


def main():
    clinch, case, work, rtol = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4]
    levels = sys.argv[5] if len(sys.argv) > 5 else "6"
    rows_of, fine, check = CASES[case]
    deck = os.path.join(VERIFICATION, case, case + ".inp")
    shutil.rmtree(work, ignore_errors=True)
    subprocess.run([clinch, "study", deck, "--work", work, "--levels", levels, "--rtol", rtol,
                    "--no-plot"], check=True)
    with open(os.path.join(work, case + ".study.csv"), newline="") as f:
        settings = list(csv.DictReader(f))
    chosen = [s for s in settings if s["chosen"] == "1"]
    assert len(chosen) == 1, f"--rtol {rtol} chose no setting"
    chosen = chosen[0]
    with open(os.path.join(work, case + ".study-columns.csv"), newline="") as f:
        estimates = {r["column"]: float(r["estimated_error"]) for r in csv.DictReader(f)
                     if r["setting"] == chosen["setting"]}

    if fine == 0:  # a closed form along the whole path
        names, limit = rows_of(64)
    else:
        names, rows_fine = rows_of(fine)
        _, rows_half = rows_of(fine // 2)
        half_at = {round(t, 12): v for t, v in rows_half}
        limit = [(t, [2.0 * a - b for a, b in zip(v, half_at[round(t, 12)])])
                 for t, v in rows_fine if round(t, 12) in half_at]
    if check:
        check(names, limit)

    def history(setting):
        path = os.path.join(work, f"setting-{setting}", case + ".history.csv")
        with open(path, newline="") as f:
            return list(csv.DictReader(f))

    # The study measures a column's error against the scale of its kind in the model
    # (docs/study-and-report.md): forces and moments by the largest |force or moment| of any
    # column in any completed setting, motions by the largest |motion|, damage and criteria by 1.
    def kind(name):
        variable = re.match(r"[A-Z]+", name).group(0)
        if variable in FORCES:
            return "force"
        if variable in MOTIONS:
            return "motion"
        return "ratio" if variable in RATIOS else name

    kind_scale = {"ratio": 1.0}
    for s in settings:
        if s["state"] != "completed":
            continue
        for r in history(s["setting"]):
            for name, value in r.items():
                if name in ("step", "increment", "step_time", "total_time"):
                    continue
                k = kind(name)
                kind_scale[k] = max(kind_scale.get(k, 0.0), abs(float(value)))

    coarsest = [float(r["total_time"]) for r in history(settings[0]["setting"])]
    run = history(chosen["setting"])
    run_times = [float(r["total_time"]) for r in run]
    limit_times = [t for t, _ in limit]
    true_error, estimated, worst = 0.0, 0.0, ""
    for j, name in enumerate(names):
        ref = [interpolate(limit_times, [v[j] for _, v in limit], t) for t in coarsest]
        got = [interpolate(run_times, [float(r[name]) for r in run], t) for t in coarsest]
        scale = kind_scale[kind(name)]
        if max(abs(x) for x in ref) <= 1e-6 * scale:  # zero to round-off: the study leaves it out
            continue
        err = max(abs(a - b) for a, b in zip(got, ref)) / scale
        if err > true_error:
            true_error, worst = err, name
        estimated = max(estimated, estimates[name])
    ratio = estimated / true_error
    print(f"{case}: --rtol {rtol} chose setting {chosen['setting']} (scale {chosen['scale']}, "
          f"{chosen['increments']} increments): estimated error {estimated:.3e}, true error "
          f"{true_error:.3e} (worst column {worst}), ratio {ratio:.2f}")
    assert 1.0 / 3.0 <= ratio <= 3.0, ratio
    return 0


if __name__ == "__main__":
    sys.exit(main())
