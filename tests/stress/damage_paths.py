"""Stress test of connector damage: random softening paths through `clinch run`.

Each path is one damaged connector between a held node a and a node b (behaviors.md §7):
- force, motion: AXIAL, linear elasticity k, uncoupled FORCE or MOTION initiation (an upper and
  sometimes a lower limit), sometimes a second MOTION mechanism with MULTIPLICATIVE degradation;
- plastic: AXIAL with perfect plasticity F_y and PLASTIC MOTION initiation;
- coupled: CARTESIAN, k on 1-3, FORCE initiation through a potential on components 1 and 2,
  evolution through a potential on their motions or the default norm (both translations);
- coupled_plastic: CARTESIAN, k on 1-3, coupled plasticity with an elliptic potential on
  components 1 and 2 and perfect plasticity F_y, coupled PLASTIC MOTION initiation.
Evolution: TYPE=MOTION with LINEAR, EXPONENTIAL or TABULAR softening, or TYPE=ENERGY.

One deck holds --per-deck paths (default 5) of one drive, each with its own nodes, behaviour and
amplitude (a random walk with reversals over 8-16 segments, reaching several failure motions):
- direct: node b's displacement prescribed;
- series: node b free, joined to a driven node c by an elastic AXIAL connector (0.5-3 k), so
  Newton iterates on the softening branch (AXIAL kinds only);
- load: a *CLOAD on node b with an elastic AXIAL connector (0.05-1 k) in parallel with the damaged
  one; past the peak of the combination no equilibrium exists and the run must stop cleanly
  (AXIAL kinds only).
The step is *STATIC with automatic increments or *STATIC, DIRECT (per deck); R_n = R_p = 1e-9 so
that converged rows are in equilibrium to the checks below.

Every run must complete (exit 0, last status line COMPLETED) or stop cleanly (exit 2, last status
line FAILED: ...); anything else fails the test. Per connector, over every history row (the rows
are the converged increments, so a stopped run is checked on the rows it kept):
1. 0 <= CDMG <= 1, CDMG and the criterion (CDIF/CDIM/CDIP) never decrease, CDMG = 0 while the
   criterion is below 1, CDMG > 0 once it has passed 1.01 (every law grows from κ = 0);
2. once CDMG = 1 the element is deleted: every force is 0 from then on;
3. the degraded force: CTF_i = (1 - CDMG) k CU_i on the affected components (elastic kinds);
   |CTF1| <= (1 - CDMG) F_y (plastic); P(CTF) <= (1 - CDMG) F_y (coupled_plastic);
4. equilibrium: CTF of the damaged connector = CTF of the series connector (series); CTF of the
   damaged + parallel connectors = the applied load (load).
tol = --rtol (default 1e-6) times the connector's peak force.

The report gives, per kind and per drive, paths, how their decks ended (completed or stopped
cleanly), rows checked, paths that failed completely (deleted), and the mean Newton iterations
per converged increment (the .log's totals, cut-back attempts included); then the fraction of
displacement-driven paths whose deck completed, over all decks and over the decks without a path
that may snap back.

Usage: damage_paths.py CLINCH [--paths N] [--per-deck M] [--seed S] [--work DIR] [--rtol T]
                       [--min-completed R] [--min-completed-without-snap-back R]
                       [--riks] [--min-riks-completed R]
--min-completed: the least fraction of displacement-driven paths (direct, series) whose deck
completes (load-driven paths may stop: that is the expected clean stop past a limit point).
--min-completed-without-snap-back: the same over the decks where no series spring is softer than
its path's steepest softening slope (a snap-back leaves no solution near the last one, and the
run stops cleanly; the report counts the decks that hold such a path apart).
--riks: each load-driven deck is run again as a *STATIC, RIKS step (docs/riks.md) with each
path's largest load as its reference and the LPF up to 1, past the limit points a load-driven
run stops at; checks 1-4 hold with the applied load LPF times the reference.
--min-riks-completed: the least fraction of those rerun paths whose deck completes: its step
ends at the maximum LPF 1 (a run that ends at INC short of it, having followed another
equilibrium path, is counted apart and not as complete).
"""

import argparse
import csv
import math
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile

KINDS = ["force", "motion", "plastic", "coupled", "coupled_plastic"]
DRIVES = ["direct", "series", "load"]
CRITERION_OUTPUT = {"force": "CDIF", "motion": "CDIM", "plastic": "CDIP", "coupled": "CDIF",
                    "coupled_plastic": "CDIP"}
TWO_D = ("coupled", "coupled_plastic")  # CARTESIAN, driven in x and y


def fmt(x):
    return f"{x:.10g}"


def time_grid(rng):
    n = rng.randint(8, 16)
    cuts = sorted(rng.uniform(0.0, 1.0) for _ in range(n - 1))
    out = [0.0]
    for t in cuts:
        if t - out[-1] >= 0.02 and 1.0 - t >= 0.02:
            out.append(round(t, 6))
    out.append(1.0)
    return out


def walk(rng, count, unit, bias):
    """Random walk from 0 with reversals (p = 0.35), steps of 0.3-3 units, drifting by `bias`."""
    values = [0.0]
    direction = 1.0
    for _ in range(count - 1):
        if rng.random() < 0.35:
            direction = -direction
        values.append(values[-1] + direction * unit * rng.uniform(0.3, 3.0) + bias * unit)
    return values


def amplitude_lines(name, times, values):
    lines = [f"*AMPLITUDE, NAME={name}"]
    pairs = [f"{fmt(t)}, {fmt(v)}" for t, v in zip(times, values)]
    for i in range(0, len(pairs), 4):
        lines.append(", ".join(pairs[i:i + 4]))
    return lines


def interpolate(times, values, t):
    for i in range(1, len(times)):
        if t <= times[i]:
            s = (t - times[i - 1]) / (times[i] - times[i - 1])
            return values[i - 1] + s * (values[i] - values[i - 1])
    return values[-1]


class Path:
    def __init__(self, rng, j, drive):
        self.j, self.drive = j, drive
        self.kind = rng.choice(KINDS if drive == "direct" else KINDS[:3])
        self.a, self.b, self.c = 3 * j + 1, 3 * j + 2, 3 * j + 3
        self.element, self.other = 10000 + j, 20000 + j
        self.k = 10.0 ** rng.uniform(2.5, 3.5)
        self.duf = rng.uniform(0.05, 0.4)
        self.softening = rng.choice(["LINEAR", "EXPONENTIAL", "TABULAR", "ENERGY"])
        self.exponent = rng.uniform(1.0, 8.0)
        self.second = self.kind in ("force", "motion") and rng.random() < 0.25
        if self.kind == "motion":
            self.limit = rng.uniform(0.03, 0.15)
            self.peak = self.k * self.limit
        elif self.kind in ("plastic", "coupled_plastic"):
            self.fy = rng.uniform(50.0, 150.0)
            self.ubar0 = rng.uniform(0.01, 0.1)
            self.limit = self.fy
            self.peak = self.fy
        else:
            self.limit = rng.uniform(50.0, 150.0)
            self.peak = self.limit
        self.lower = -self.limit * rng.uniform(0.5, 1.5) if rng.random() < 0.5 else None
        self.energy = self.peak * self.duf * rng.uniform(0.2, 1.0)
        # The steepest softening slope of the envelope, over k (behaviors.md §7.4): a series
        # spring stiffer than it keeps displacement control free of snap-back, a parallel one
        # keeps load control free of limit points. Most paths get one; the rest may stop cleanly.
        # (peak force / Δu_f times the law's initial steepness, the same for PLASTIC MOTION,
        # where the peak is F_y and δ the plastic motion).
        shape = {"LINEAR": 1.0, "EXPONENTIAL": self.exponent / (1.0 - math.exp(-self.exponent)),
                 "TABULAR": 1.4, "ENERGY": 5.0}[self.softening]
        steepest = self.peak / (self.k * self.duf) * shape * (2.0 if self.second else 1.0)
        stable = rng.random() < 0.9
        self.ratio = (steepest * rng.uniform(1.2, 3.0) if stable else
                      rng.uniform(0.5, 3.0) if drive == "series" else rng.uniform(0.05, 1.0))
        # A series spring softer than that slope snaps back: past the peak the displacement of c
        # no longer determines the state, and there is no solution near the last one (the run
        # stops cleanly). The estimate is the one above (exact for LINEAR softening).
        self.snap_back = drive == "series" and self.ratio < steepest
        self.radii = [rng.uniform(0.5, 1.5), rng.uniform(0.5, 1.5)]
        self.evolution_potential = rng.random() < 0.5
        self.times = time_grid(rng)
        n = len(self.times)
        unit = self.peak / self.k + (self.ubar0 if self.kind == "plastic" else 0.0) + 0.3 * self.duf
        if drive == "series":
            unit *= 1.0 + 1.0 / self.ratio
        if drive == "load":
            self.values = [0.0] + [rng.uniform(-0.8, 1.6) * self.peak * (1.0 + self.ratio)
                                   for _ in range(n - 1)]
        else:
            self.values = walk(rng, n, unit, 0.4)
            if self.kind in TWO_D:
                self.values_y = walk(rng, n, unit, 0.2 * rng.choice([-1.0, 1.0]))

    def riks_load(self):
        """The reference load of the Riks rerun: the largest the random walk asks for."""
        return max(abs(v) for v in self.values)

    def behavior_lines(self):
        lines = [f"*CONNECTOR BEHAVIOR, NAME=B{self.j}"]
        for comp in (1, 2, 3) if self.kind in TWO_D else (1,):
            lines += [f"*CONNECTOR ELASTICITY, COMPONENT={comp}", fmt(self.k)]
        if self.kind == "coupled_plastic":
            lines += ["*CONNECTOR PLASTICITY", "*CONNECTOR HARDENING, TYPE=ISOTROPIC",
                      f"{fmt(self.fy)}, 0.", "*CONNECTOR POTENTIAL",
                      f"1, {fmt(self.radii[0])}", f"2, {fmt(self.radii[1])}",
                      "*CONNECTOR DAMAGE INITIATION, CRITERION=PLASTIC MOTION", fmt(self.ubar0)]
        elif self.kind == "plastic":
            lines += ["*CONNECTOR PLASTICITY, COMPONENT=1", "*CONNECTOR HARDENING, TYPE=ISOTROPIC",
                      f"{fmt(self.fy)}, 0."]
            lines += ["*CONNECTOR DAMAGE INITIATION, COMPONENT=1, CRITERION=PLASTIC MOTION",
                      fmt(self.ubar0)]
        else:
            criterion = "MOTION" if self.kind == "motion" else "FORCE"
            component = "" if self.kind == "coupled" else "COMPONENT=1, "
            lower = fmt(self.lower) if self.lower is not None else ""
            lines += [f"*CONNECTOR DAMAGE INITIATION, {component}CRITERION={criterion}",
                      f"{lower}, {fmt(1.0 if self.kind == 'coupled' else self.limit)}"]
            if self.kind == "coupled":
                lines += ["*CONNECTOR POTENTIAL", f"1, {fmt(self.limit * self.radii[0])}",
                          f"2, {fmt(self.limit * self.radii[1])}"]
        lines += self.evolution_lines("MAXIMUM")
        if self.kind == "coupled" and self.evolution_potential:
            lines += ["*CONNECTOR POTENTIAL", "1, 1.", "2, 1."]
        if self.second:
            lines += ["*CONNECTOR DAMAGE INITIATION, COMPONENT=1, CRITERION=MOTION",
                      f", {fmt(1.5 * self.peak / self.k)}",
                      "*CONNECTOR DAMAGE EVOLUTION, TYPE=MOTION, DEGRADATION=MULTIPLICATIVE",
                      fmt(2.0 * self.duf)]
        return lines

    def evolution_lines(self, degradation):
        if self.softening == "ENERGY":
            return [f"*CONNECTOR DAMAGE EVOLUTION, TYPE=ENERGY, DEGRADATION={degradation}",
                    fmt(self.energy)]
        head = (f"*CONNECTOR DAMAGE EVOLUTION, TYPE=MOTION, SOFTENING={self.softening}, "
                f"DEGRADATION={degradation}")
        if self.softening == "LINEAR":
            return [head, fmt(self.duf)]
        if self.softening == "EXPONENTIAL":
            return [head, f"{fmt(self.duf)}, {fmt(self.exponent)}"]
        return [head, "0., 0.", f"0.4, {fmt(0.3 * self.duf)}", f"1., {fmt(self.duf)}"]

    def model_lines(self):
        y = 5.0 * self.j
        lines = ["*NODE", f"{self.a}, 0., {fmt(y)}, 0.", f"{self.b}, 10., {fmt(y)}, 0."]
        if self.drive == "series":
            lines.append(f"{self.c}, 20., {fmt(y)}, 0.")
        section = "CARTESIAN," if self.kind in TWO_D else "AXIAL,"
        lines += ["*ELEMENT, TYPE=CONN3D2, ELSET=DAMAGED", f"{self.element}, {self.a}, {self.b}",
                  f"*ELSET, ELSET=E{self.j}", f"{self.element}",
                  f"*CONNECTOR SECTION, ELSET=E{self.j}, BEHAVIOR=B{self.j}", section]
        lines += self.behavior_lines()
        if self.drive != "direct":
            first, second = (self.b, self.c) if self.drive == "series" else (self.a, self.b)
            lines += ["*ELEMENT, TYPE=CONN3D2, ELSET=OTHER", f"{self.other}, {first}, {second}",
                      f"*ELSET, ELSET=O{self.j}", f"{self.other}",
                      f"*CONNECTOR SECTION, ELSET=O{self.j}, BEHAVIOR=K{self.j}", "AXIAL,",
                      f"*CONNECTOR BEHAVIOR, NAME=K{self.j}", "*CONNECTOR ELASTICITY, COMPONENT=1",
                      fmt(self.ratio * self.k)]
        lines += ["*BOUNDARY", f"{self.a}, 1, 6" if self.kind in TWO_D else f"{self.a}, 1, 3"]
        if self.kind in TWO_D:
            lines += [f"{self.b}, 3, 3"]
        else:
            lines += [f"{self.b}, 2, 3"]
            if self.drive == "series":
                lines.append(f"{self.c}, 2, 3")
        lines += amplitude_lines(f"A{self.j}", self.times, self.values)
        if self.kind in TWO_D:
            lines += amplitude_lines(f"Y{self.j}", self.times, self.values_y)
        return lines

    def step_lines(self, riks=False):
        if self.drive == "load" and riks:
            return ["*CLOAD", f"{self.b}, 1, {fmt(self.riks_load())}"]
        if self.drive == "load":
            return [f"*CLOAD, AMPLITUDE=A{self.j}", f"{self.b}, 1, 1.0"]
        node = self.c if self.drive == "series" else self.b
        lines = [f"*BOUNDARY, AMPLITUDE=A{self.j}", f"{node}, 1, 1, 1.0"]
        if self.kind in TWO_D:
            lines += [f"*BOUNDARY, AMPLITUDE=Y{self.j}", f"{node}, 2, 2, 1.0"]
        return lines


def write_deck(path, paths, control, riks=False):
    lines = ["*HEADING", "Random damage paths (tests/stress/damage_paths.py)"]
    for p in paths:
        lines += p.model_lines()
    if riks:
        # The Riks rerun of a load-driven deck: each path's largest load as the reference, the
        # LPF up to 1 (or 300 increments), whatever limit points lie on the way (docs/riks.md).
        lines += ["*STEP, NAME=PATH, INC=300", "*STATIC, RIKS", "0.05, 1., 1e-7, 0.2, 1."]
    elif control[0] == "direct":
        lines += ["*STEP, NAME=PATH, INC=100000", "*STATIC, DIRECT", f"{control[1]}, 1.0"]
    else:
        lines += ["*STEP, NAME=PATH, INC=100000", "*STATIC", f"{control[1]}, 1.0, 1e-7, {control[2]}"]
    lines += ["*CONTROLS, PARAMETERS=FIELD", "1e-9, , , , 1e-9, 1e-12,"]
    for p in paths:
        lines += p.step_lines(riks)
    lines += ["*OUTPUT, HISTORY", "*ELEMENT OUTPUT, ELSET=DAMAGED", "CU, CTF, CDMG, CDIF, CDIM, CDIP"]
    if any(p.drive != "direct" for p in paths):
        lines += ["*ELEMENT OUTPUT, ELSET=OTHER", "CTF1"]
    lines.append("*END STEP")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def run_deck(clinch, deck, out):
    proc = subprocess.run([clinch, "run", "--quiet", "--out", out, deck],
                          stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    job = os.path.splitext(os.path.basename(deck))[0]
    last, increments, iterations = "", 0, 0
    sta = os.path.join(out, job + ".sta")
    if os.path.exists(sta):
        with open(sta) as f:
            lines = [line.rstrip("\n") for line in f if line.strip()]
        last = lines[-1] if lines else ""
    log = os.path.join(out, job + ".log")
    if os.path.exists(log):
        m = re.search(r"(\d+) increments?, (\d+) iterations?", open(log).read())
        if m:
            increments, iterations = int(m.group(1)), int(m.group(2))
    rows = []
    table = os.path.join(out, job + ".history.csv")
    if os.path.exists(table):
        with open(table) as f:
            rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]
    return proc.returncode, last, increments, iterations, rows, proc.stderr


def check_path(p, rows, rtol):
    e = p.element
    tol = rtol * max(p.peak * (1.0 + (p.ratio if p.drive == "load" else 0.0)), 1.0)
    problems = []
    criterion = CRITERION_OUTPUT[p.kind]
    previous_d = previous_r = 0.0
    failed = False
    comps = (1, 2) if p.kind in TWO_D else (1,)
    for r in rows:
        where = f"element {e} ({p.kind}, {p.drive}, {p.softening}) at t={r['total_time']:.6g}"
        d, crit = r[f"CDMG@{e}"], r[f"{criterion}@{e}"]
        if not (0.0 <= d <= 1.0) or d < previous_d or crit < previous_r - 1e-12:
            problems.append(f"{where}: CDMG {d} (was {previous_d}), {criterion} {crit}")
        if d > 0.0 and max(crit, r.get(f"CDIM@{e}", 0.0)) < 1.0 - 1e-9:
            problems.append(f"{where}: damage {d} before initiation ({criterion} {crit})")
        if d == 0.0 and crit > 1.01:
            problems.append(f"{where}: no damage although {criterion} = {crit} passed 1")
        previous_d, previous_r = d, max(previous_r, crit)
        forces = [r[f"CTF{i}@{e}"] for i in comps]
        if failed and any(f != 0.0 for f in forces):
            problems.append(f"{where}: force {forces} after deletion")
        failed = failed or d >= 1.0
        if p.kind == "plastic":
            if abs(forces[0]) > (1.0 - d) * p.fy + tol:
                problems.append(f"{where}: |CTF1| {forces[0]} above (1 - d) F_y")
        elif p.kind == "coupled_plastic":
            size = math.hypot(forces[0] / p.radii[0], forces[1] / p.radii[1])
            if size > (1.0 - d) * p.fy + tol:
                problems.append(f"{where}: P(CTF) {size} above (1 - d) F_y")
        else:
            for i, f in zip(comps, forces):
                expected = (1.0 - d) * p.k * r[f"CU{i}@{e}"] if not failed else 0.0
                if abs(f - expected) > tol:
                    problems.append(f"{where}: CTF{i} {f}, (1 - d) k CU{i} = {expected}")
        if p.drive == "series" and abs(forces[0] - r[f"CTF1@{p.other}"]) > tol:
            problems.append(f"{where}: series forces {forces[0]} and {r[f'CTF1@{p.other}']}")
        if p.drive == "load":
            applied = (r["LPF"] * p.riks_load() if "LPF" in r else
                       interpolate(p.times, p.values, r["step_time"] if r["total_time"] > 0 else 0))
            if abs(forces[0] + r[f"CTF1@{p.other}"] - applied) > tol:
                problems.append(f"{where}: {forces[0]} + {r[f'CTF1@{p.other}']} != load {applied}")
    return problems, failed


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("clinch")
    ap.add_argument("--paths", type=int, default=300)
    ap.add_argument("--per-deck", type=int, default=5)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--work")
    ap.add_argument("--rtol", type=float, default=1e-6)
    ap.add_argument("--min-completed", type=float, default=0.0)
    ap.add_argument("--min-completed-without-snap-back", type=float, default=0.0)
    ap.add_argument("--riks", action="store_true")
    ap.add_argument("--min-riks-completed", type=float, default=0.0)
    args = ap.parse_args()
    rng = random.Random(args.seed)
    work = args.work or tempfile.mkdtemp(prefix="damage-paths-")
    os.makedirs(work, exist_ok=True)
    stats = {}
    problems = []
    total_increments = total_iterations = 0
    snap_decks = [0, 0]  # decks holding a path that may snap back, and those that completed
    smooth = [0, 0]  # displacement-driven paths in the other decks, and those that completed
    # Load-driven paths rerun with *STATIC, RIKS; those whose deck reached LPF 1; those whose deck
    # ended at INC short of it.
    riks = [0, 0, 0]
    done = 0
    deck_index = 0
    while done < args.paths:
        count = min(args.per_deck, args.paths - done)
        drive = rng.choices(DRIVES, weights=[0.4, 0.3, 0.3])[0]
        paths = [Path(rng, done + i, drive) for i in range(count)]
        control = (("direct", rng.choice([0.002, 0.005])) if rng.random() < 0.3 else
                   ("auto", rng.choice([0.01, 0.05, 0.1]), rng.choice([0.1, 0.2, 1.0])))
        deck = os.path.join(work, f"damage_{deck_index:04d}.inp")
        write_deck(deck, paths, control)
        status, last, increments, iterations, rows, stderr = run_deck(args.clinch, deck, work)
        total_increments += increments
        total_iterations += iterations
        clean = (status == 0 and last == "COMPLETED") or (status == 2 and last.startswith("FAILED:"))
        if not clean:
            problems.append(f"{deck}: exit {status}, last status line {last!r}\n{stderr[-2000:]}")
        snap = any(p.snap_back for p in paths)
        if snap:
            snap_decks[0] += 1
            snap_decks[1] += status == 0
        for p in paths:
            path_problems, failed = check_path(p, rows, args.rtol)
            if p.drive != "load" and not snap:
                smooth[0] += 1
                smooth[1] += status == 0
            problems += [f"{deck}: {x}" for x in path_problems[:3]]
            for key in (("kind", p.kind), ("drive", p.drive)):
                s = stats.setdefault(key, {"paths": 0, "completed": 0, "stopped": 0, "rows": 0,
                                           "deleted": 0})
                s["paths"] += 1
                s["completed" if status == 0 else "stopped"] += 1
                s["rows"] += len(rows)
                s["deleted"] += failed
        if args.riks and drive == "load":
            riks_deck = os.path.join(work, f"damage_{deck_index:04d}_riks.inp")
            write_deck(riks_deck, paths, control, riks=True)
            status, last, _, _, rows, stderr = run_deck(args.clinch, riks_deck, work)
            if not ((status == 0 and last == "COMPLETED") or
                    (status == 2 and last.startswith("FAILED:"))):
                problems.append(f"{riks_deck}: exit {status}, last status line {last!r}\n"
                                f"{stderr[-2000:]}")
            for p in paths:
                problems += [f"{riks_deck}: {x}" for x in check_path(p, rows, args.rtol)[0][:3]]
            # Complete: the step ended at its maximum LPF 1. A run that ends at INC below it
            # followed another equilibrium path (the elastic unloading branch behind a limit
            # point, into compression) and counts apart.
            reached = status == 0 and bool(rows) and rows[-1].get("LPF", 0.0) >= 1.0 - 1e-9
            riks[0] += count
            riks[1] += count * reached
            riks[2] += count * (status == 0 and not reached)
        done += count
        deck_index += 1
    print(f"{args.paths} damage paths in {deck_index} decks (seed {args.seed}), work dir {work}")
    print(f"{'':22}{'paths':>7}{'completed':>11}{'stopped':>9}{'deleted':>9}{'rows':>9}")
    for key in sorted(stats):
        s = stats[key]
        print(f"{key[0] + ' ' + key[1]:22}{s['paths']:>7}{s['completed']:>11}{s['stopped']:>9}"
              f"{s['deleted']:>9}{s['rows']:>9}")
    mean = total_iterations / total_increments if total_increments else 0.0
    print(f"Newton iterations per converged increment: {mean:.3f} "
          f"({total_iterations} iterations, {total_increments} increments)")
    displacement = [stats.get(("drive", d), {"paths": 0, "completed": 0}) for d in ("direct", "series")]
    paths_d = sum(s["paths"] for s in displacement)
    rate = sum(s["completed"] for s in displacement) / paths_d if paths_d else 1.0
    print(f"displacement-driven paths whose deck completed: {rate:.3f}")
    if smooth[0]:
        print(f"  in decks without a path that may snap back: {smooth[1]}/{smooth[0]} "
              f"({smooth[1] / smooth[0]:.3f}); decks with one: {snap_decks[1]} of "
              f"{snap_decks[0]} completed")
    if riks[0]:
        print(f"load-driven paths rerun with *STATIC, RIKS whose deck reached LPF 1: "
              f"{riks[1]}/{riks[0]} ({riks[1] / riks[0]:.3f}); ended at INC short of it: "
              f"{riks[2]}")
    for x in problems[:20]:
        print("FAIL:", x)
    if problems:
        print(f"{len(problems)} problems")
        return 1
    if rate < args.min_completed:
        print(f"FAIL: completion rate {rate:.3f} below {args.min_completed}")
        return 1
    smooth_rate = smooth[1] / smooth[0] if smooth[0] else 1.0
    if smooth_rate < args.min_completed_without_snap_back:
        print(f"FAIL: completion rate without snap-back {smooth_rate:.3f} below "
              f"{args.min_completed_without_snap_back}")
        return 1
    riks_rate = riks[1] / riks[0] if riks[0] else 1.0
    if riks_rate < args.min_riks_completed:
        print(f"FAIL: Riks completion rate {riks_rate:.3f} below {args.min_riks_completed}")
        return 1
    if not args.work:
        shutil.rmtree(work)
    return 0


if __name__ == "__main__":
    sys.exit(main())
