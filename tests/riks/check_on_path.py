"""Every converged point of a Riks run lies on the equilibrium path, computed here independently,
the path passes its limit point, and the step ends where its data line says (docs/riks.md).

Usage: check_on_path.py series|weld|spotweld|truss|kink|series_kink HISTORY.csv STATUS.sta

series (series_snap_back.inp): two AXIAL connectors in series pulled by 100 LPF at node 3. The
  first follows its table (F = 100 u exp(1 - u) at u = 0, 0.1, ..., 8, interpolated linearly),
  the second is linear (20); both carry the load. The path also snaps back: u3 falls while the
  first connector keeps stretching. The step ends at the first increment where u3 crosses 7.
weld (weld_under_load.inp): a BUSHING weld sheared by 1000 LPF; component 1 is elastic (1e5)
  with FORCE damage initiation at 800 and exponential motion softening (0.02, 3), the reference
  of decks/verification/damage_lib.py (ElasticDamage) along the run's increasing u1. The step
  ends where u1 crosses 0.025.
spotweld (spot_weld_pull.inp): the spot weld of decks/examples/spot_weld_damage.inp pulled along
  its axis by 1000 LPF. Under pure normal pull its potential is f3/R_n (R_n = 0.02): it yields at
  f3 = 800, flows with u3^pl = ū/R_n (the flow direction ∂P/∂f3 = 1/R_n, ū the equivalent plastic
  motion) at that load, and softens with PLASTIC MOTION damage of ū (initiation 0.0005,
  exponential over 0.002, 3). In the motion u3 R_n this is damage_lib.PlasticDamage with
  stiffness 1e5/R_n. The plateau has no stiffness along the flow: the bordered matrix is solved
  whole there. The step ends where u3 crosses 0.1.
truss (truss_snap_through.inp): the von Mises truss, two SPRINGA (k = 1000) from (±1, 0) to the
  apex at (0, 0.5), pushed down by 100 LPF under NLGEOM: at the apex's descent w the bars have
  length L = sqrt(1 + (0.5 - w)^2) and P = 2k(L0 - L)(0.5 - w)/L. The path passes the limit
  point, snaps through (P < 0) and inverts; the step ends where u2 crosses -1.2.
kink (parallel_kink.inp): two AXIAL connectors in parallel pulled by 15 LPF: the first elastic
  (100) with FORCE damage initiation at 10 and linear motion softening over 0.02
  (damage_lib.ElasticDamage), the second linear (20). Its limit point sits on the kink of the
  first's law, where the path turns by more than a right angle; the first is deleted at
  u = 0.12 and the second carries the load on. The step ends where u crosses 0.6.
series_kink (series_kink.inp): the first connector of kink, from node 1 to node 2, in series
  with the linear one (20) from node 2 to node 3, pulled by 15 LPF at node 3: past the peak on
  the law's kink node 3 snaps back by about 0.5 while node 2 moves on. The step ends where u2
  crosses 0.118, at the complete failure of the first connector (u2 = 0.12, where the load is 0).

Tolerance: 1e-8 of each quantity's scale (the largest load on the path). The runs' *CONTROLS ask
for residuals of 1e-10 of the force flux, which leaves errors near 1e-10 of these scales.
"""
import csv
import math
import os
import sys

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "decks",
                                "verification"))
import damage_lib  # noqa: E402

TABLE_U = [i / 10 for i in range(81)]
TABLE_F = [100 * u * math.exp(1 - u) for u in TABLE_U]


def table_force(u):
    for i in range(len(TABLE_U) - 1):
        if TABLE_U[i] <= u <= TABLE_U[i + 1]:
            t = (u - TABLE_U[i]) / (TABLE_U[i + 1] - TABLE_U[i])
            return TABLE_F[i] + t * (TABLE_F[i + 1] - TABLE_F[i])
    raise AssertionError(f"u = {u} is outside the table")


def series_errors(rows):
    """(what, error) of each row against the path; the monitored values."""
    out = []
    for r in rows:
        lpf, u2, u3, force = (float(r[k]) for k in ("LPF", "U1@2", "U1@3", "CTF1@1"))
        out.append([("first connector = its table", force - table_force(u2)),
                    ("first connector = load", force - 100.0 * lpf),
                    ("second connector = load", 20.0 * (u3 - u2) - 100.0 * lpf)])
    return out, [float(r["U1@3"]) for r in rows]


def weld_errors(rows):
    weld = damage_lib.ElasticDamage(1.0e5, 800.0, ("EXPONENTIAL", 0.02, 3.0))
    out = []
    for r in rows:
        lpf, u, force = (float(r[k]) for k in ("LPF", "U1@2", "CTF1@1"))
        expected = weld.update(u)[0]
        out.append([("weld force = reference", force - expected),
                    ("weld force = load", force - 1000.0 * lpf)])
    return out, [float(r["U1@2"]) for r in rows]


def spot_weld_errors(rows):
    r_n = 0.02
    weld = damage_lib.PlasticDamage(1.0e5 / r_n, 800.0, 0.0005, ("EXPONENTIAL", 0.002, 3.0))
    out = []
    for r in rows:
        lpf, u, force = (float(r[k]) for k in ("LPF", "U3@2", "CTF3@1"))
        expected = weld.update(u * r_n)[0]
        out.append([("weld force = reference", force - expected),
                    ("weld force = load", force - 1000.0 * lpf)])
    return out, [float(r["U3@2"]) for r in rows]


def kink_errors(rows):
    soft = damage_lib.ElasticDamage(100.0, 10.0, ("LINEAR", 0.02))
    out = []
    for r in rows:
        lpf, u, force, spring = (float(r[k]) for k in ("LPF", "U1@2", "CTF1@1", "CTF1@2"))
        out.append([("softening connector = reference", force - soft.update(u)[0]),
                    ("spring = 20 u", spring - 20.0 * u),
                    ("connectors = load", force + spring - 15.0 * lpf)])
    return out, [float(r["U1@2"]) for r in rows]


def series_kink_errors(rows):
    soft = damage_lib.ElasticDamage(100.0, 10.0, ("LINEAR", 0.02))
    out = []
    for r in rows:
        lpf, u2, u3, force, spring = (float(r[k]) for k in ("LPF", "U1@2", "U1@3", "CTF1@1",
                                                            "CTF1@2"))
        out.append([("softening connector = reference", force - soft.update(u2)[0]),
                    ("spring = 20 (u3 - u2)", spring - 20.0 * (u3 - u2)),
                    ("spring = load", spring - 15.0 * lpf)])
    return out, [float(r["U1@2"]) for r in rows]


def truss_errors(rows):
    out = []
    length0 = math.sqrt(1.25)
    for r in rows:
        lpf, w = float(r["LPF"]), -float(r["U2@3"])
        length = math.sqrt(1.0 + (0.5 - w) ** 2)
        load = 2 * 1000.0 * (length0 - length) * (0.5 - w) / length
        out.append([("apex equilibrium", 100.0 * lpf - load)])
    return out, [float(r["U2@3"]) for r in rows]


CASES = {"series": (series_errors, 100.0, 7.0, "DOF 1 of the monitored node crossed 7"),
         "weld": (weld_errors, 800.0, 0.025, "DOF 1 of the monitored node crossed 0.025"),
         "spotweld": (spot_weld_errors, 800.0, 0.1, "DOF 3 of the monitored node crossed 0.1"),
         "truss": (truss_errors, 100.0, -1.2, "DOF 2 of the monitored node crossed -1.2"),
         "kink": (kink_errors, 12.0, 0.6, "DOF 1 of the monitored node crossed 0.6"),
         "series_kink": (series_kink_errors, 10.0, 0.118,
                         "DOF 1 of the monitored node crossed 0.118")}


def main(case, history, status):
    errors_of, scale, end, ended = CASES[case]
    with open(history, newline="") as f:
        rows = list(csv.DictReader(f))
    failures = []
    errors, monitored = errors_of(rows)
    for row, row_errors in zip(rows, errors):
        for what, error in row_errors:
            if abs(error) > 1e-8 * scale:
                failures.append(f"increment {row['increment']}: {what}: off by {error:.3e}")
    lpfs = [float(r["LPF"]) for r in rows]
    # Past the limit point: the LPF falls below half of a maximum it reached before.
    peak = next((i for i in range(1, len(lpfs)) if min(lpfs[i:]) < 0.5 * max(lpfs[:i])), None)
    if peak is None:
        failures.append("the path does not pass its limit point")
        peak = 0
    snap_back = {"series": "U1@3", "series_kink": "U1@3"}
    if case in snap_back:
        u3 = [float(r[snap_back[case]]) for r in rows]
        if not any(u3[i + 1] < u3[i] for i in range(peak, len(u3) - 1)):
            failures.append("the path does not snap back (u3 never falls)")
    crossed = [(m - end) * (monitored[0] - end) <= 0 for m in monitored]
    if not (crossed[-1] and not any(crossed[:-1])):
        failures.append(f"the step does not end at the first crossing of {end}")
    with open(status) as f:
        if f"STEP 1 ENDED: {ended}" not in f.read():
            failures.append("the .sta does not say why the step ended")
    for line in failures:
        print(line)
    print(f"{case}: {len(rows) - 1} increments checked, {len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:]))
