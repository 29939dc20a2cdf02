"""Stress test of connector friction: random in-plane paths through `clinch run`.

Each path is one friction connector between a held node a and a node b: a SLIDE-PLANE (CONN3D2;
predefined friction, or CONTACT FORCE=<derived component> with a circular *CONNECTOR POTENTIAL, as
in friction.md 7.2), a SLOT on CONN3D2 or a SLOT on CONN2D2 (predefined), orientation GLOB at a.
Many independent connectors (own nodes, own behaviour, own amplitudes) share one deck, so a run
covers --per-deck paths (default 50) and the test stays short; each deck holds one connection
type. The normal load is a *CLOAD on the constrained DOF(s) of b with an amplitude that changes
sign, crosses zero inside segments, and holds at exactly zero for a while (lift-off with the
tangential motion going on, then re-contact). The tangential DOFs are driven in one of three ways:

- direct: *BOUNDARY with an amplitude on b (random walk with reversals, steps of 0.3-4 elastic
  slips F_lim/k, so stick, slip and full reversals all occur);
- series: the same on a node c joined to b by an elastic CARTESIAN connector (stiffness 0.5-2 k),
  so b's tangential DOFs are free and Newton iterates through stick/slip changes;
- load: a *CLOAD with an amplitude on b's tangential DOFs, up to twice mu times the peak normal
  load, with a soft elastic CARTESIAN connector (0.02-0.2 k) in parallel: load control with
  friction alone has no solution once the load exceeds mu F_N (or as soon as F_N = 0), so the
  parallel spring takes the excess.

Some behaviours add an internal contact force F_int (F_N = |g| + F_int) or a TAUMAX cap. The step
is *STATIC with automatic increments or *STATIC, DIRECT (chosen per deck); --direct makes every
deck DIRECT, with an increment drawn from the list given.

--inclined turns the slot of each SLOT CONN2D2 connector by a random angle theta (mu |tan theta|
<= 0.5), written as Abaqus/CAE writes a datum CSYS ("3, theta" under *ORIENTATION); the drive
spring of series and load paths takes the same orientation. Loads and drives then act in global
components: the normal load along e2, the tangential load (load) along e1 in one amplitude per
global DOF (a later *CLOAD on a DOF replaces an earlier one), the motion along e1 on both DOFs of
c (series), and for direct paths on b's X alone, with Y free so that b follows the slot. The
contact force is then a constraint reaction computed with round-off, zero to round-off during a
lift-off. A direct path wedges: b's Y equilibrium gives N = P - CSF1 tan(theta) instead of N = P.

Each step sets R_n and R_p of *CONTROLS, PARAMETERS=FIELD to --residual (default 1e-9) and the
zero-force threshold epsilon to 1e-12: with clinch's defaults (0.005, 0.02 after 9 iterations,
1e-5) an increment converges with an imbalance of a few force units, or, when the loads pass
through zero, on the correction test alone, too much for the equilibrium check below. Without
--line-search the decks leave the line search to clinch (on, N_ls = 5, in steps with friction);
--line-search N adds *CONTROLS, PARAMETERS=LINE SEARCH with N_ls = N (0 turns it off).

Every run must either complete (exit 0, last status line COMPLETED) or stop cleanly (exit 2 with a
last status line FAILED: ...). Anything else fails the test. Per connector, over every history row
(F_lim = min(mu CNF, TAUMAX); P = |CSF| over the friction components):

1. P <= F_lim + tol;
2. CSLIPST = 1  =>  |P - F_lim| <= tol;
3. CASU never decreases, and it does not change in a row with CSLIPST = 0;
4. CNF = |N| + F_int, N the constraint force: CTF1 (SLIDE-PLANE), sqrt(CTF2^2 + CTF3^2) (SLOT
   CONN3D2), CTF2 (SLOT CONN2D2); and |N| equals the applied normal load at that time (an inclined
   direct path: N = P - CSF1 tan(theta));
5. equilibrium of b in the tangential DOFs: CSF = applied load - CTF of the parallel spring (load),
   CSF = -CTF of the series connector (series), friction components only (CSF1 = 0 on SLIDE-PLANE);
6. SLIDE-PLANE: CNF2 = CNF3, CSLIPST2 = CSLIPST3, CASU2 = CASU3.

tol = --rtol (default 1e-6) times max(mu * peak normal load, F_int, 1) of the connector.
A path whose deck stopped early is checked on the rows it has. The test also requires the
convergence rate over paths (a path converges when its deck completes) to reach --min-rate.
The report gives, per connection type, paths and decks completed, increments, Newton iterations
(the .log's total, cut-back attempts included) per converged increment, the most equilibrium
iterations of a converged increment (.sta), cutbacks, and the number of slipping and lift-off
(applied normal load exactly 0) connector rows checked; then the rate per drive, the paths whose
deck completed without a cutback, and the Newton iterations per increment over all decks.

Without line search (--line-search 0), Newton cycles on load-driven paths: it alternates between
forward and backward slip (the same residual and correction norms every iteration) when the
normal force changes within an increment that ends in stick; 40-50% of the load-driven paths then
stop. That is why clinch turns a line search on in steps with friction. With --per-deck 1 the
rate per drive shows it. scripts/stress_friction.sh reports both.

With DIRECT increments (--direct 0.005,0.01,0.0137,0.02 --inclined) every path completes, one or
50 to a deck (seed 20261203: 200 of 200 either way). One line-search step s serves every
connector of a deck, so the search brackets the zero of the projected residual: a connector whose
stick band is much narrower than its Newton step gets a step into the band, where a secant
through s = 0 alone would swing between s = 1 and s = 0.25 and hold the other 49 connectors to a
quarter step per iteration until the iterations run out (docs/decisions.md, "Line search").

Usage: friction_paths.py CLINCH [--paths N] [--per-deck M] [--seed S] [--work DIR] [--min-rate R]
                         [--max-cutback-fraction F] [--rtol T] [--residual R_n]
                         [--line-search N_ls] [--modes direct,series,load]
                         [--kinds slide_plane,slot3d,slot2d] [--direct DT1,DT2,...] [--inclined]
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

KINDS = ["slide_plane", "slot3d", "slot2d"]
# Tangential (friction) and normal (constrained) components of each kind.
TANGENTIAL = {"slide_plane": [2, 3], "slot3d": [1], "slot2d": [1]}
NORMAL = {"slide_plane": [1], "slot3d": [2, 3], "slot2d": [2]}
MODES = ["direct", "series", "load"]


def fmt(x):
    return f"{x:.10g}"


def amplitude_lines(name, times, values):
    lines = [f"*AMPLITUDE, NAME={name}"]
    pairs = [f"{fmt(t)}, {fmt(v)}" for t, v in zip(times, values)]
    for i in range(0, len(pairs), 4):
        lines.append(", ".join(pairs[i:i + 4]))
    return lines


def time_grid(rng):
    """0 = t0 < t1 < ... < tn = 1, random spacing, 8 to 16 segments."""
    n = rng.randint(8, 16)
    cuts = sorted(rng.uniform(0.0, 1.0) for _ in range(n - 1))
    times = [0.0] + cuts + [1.0]
    # Keep the points apart (at least 0.01): merge close ones.
    out = [0.0]
    for t in times[1:-1]:
        if t - out[-1] >= 0.01 and 1.0 - t >= 0.01:
            out.append(round(t, 6))
    out.append(1.0)
    return out


def normal_values(rng, count):
    """Normal-load factors in [-1, 1] at the grid points: starts at 0, changes sign (within a
    segment and through exact zeros) and holds at exactly 0 for at least one segment."""
    values = [0.0]
    sign = rng.choice([-1.0, 1.0])
    for _ in range(count - 1):
        r = rng.random()
        if r < 0.3:
            sign = -sign
        if r > 0.85:
            values.append(0.0)
        else:
            values.append(sign * rng.uniform(0.2, 1.0))
    k = rng.randint(2, count - 3)  # a lift-off: two consecutive exact zeros (a zero segment)
    values[k] = values[k + 1] = 0.0
    positive = any(v > 0 for v in values)
    negative = any(v < 0 for v in values)
    if not (positive and negative):  # force a sign change after the lift-off
        j = rng.randint(k + 2, count - 1)
        values[j] = -values[j] if values[j] else -math.copysign(0.5, values[k - 1] or 1.0)
    return values


def walk(rng, count, unit):
    """A random walk with reversals: steps of 0.3-4 units, the direction flips with p = 0.45."""
    values = [0.0]
    direction = rng.choice([-1.0, 1.0])
    for _ in range(count - 1):
        if rng.random() < 0.45:
            direction = -direction
        values.append(values[-1] + direction * unit * rng.uniform(0.3, 4.0))
    return values


class Connector:
    """One path: its behaviour, its drive and its amplitudes."""

    def __init__(self, rng, kind, j, modes, inclined=False):
        self.kind, self.j = kind, j
        self.a, self.b, self.c = 3 * j + 1, 3 * j + 2, 3 * j + 3
        self.element, self.drive = 10000 + j, 20000 + j
        self.mode = rng.choices(MODES, weights=[0.4, 0.3, 0.3])[0]
        if self.mode not in modes:
            self.mode = modes[0]
        self.coupled = kind == "slide_plane" and rng.random() < 0.5
        self.mu = rng.uniform(0.1, 0.6)
        self.k = 10.0 ** rng.uniform(3.0, 5.0)
        self.load = rng.uniform(100.0, 2000.0)  # peak normal load
        self.fint = rng.uniform(0.0, 0.3) * self.load if rng.random() < 0.2 else 0.0
        self.taumax = (rng.uniform(0.3, 0.9) * self.mu * self.load
                       if rng.random() < 0.1 else None)
        self.kd = self.k * (rng.uniform(0.5, 2.0) if self.mode == "series"
                            else rng.uniform(0.02, 0.2))
        # An inclined SLOT on CONN2D2 (--inclined): e1 at theta to X, with mu |tan theta| <= 0.5, so
        # that the wedge of the direct drive (below) has one solution.
        self.theta = 0.0
        if inclined and kind == "slot2d":
            limit = math.degrees(math.atan(0.5 / self.mu))
            self.theta = round(rng.uniform(-limit, limit), 4)
        self.times = time_grid(rng)
        n = len(self.times)
        normal = normal_values(rng, n)
        if kind == "slot3d":  # the normal load turns in the 2-3 plane as it changes magnitude
            phi0, dphi = rng.uniform(0, 2 * math.pi), rng.uniform(-math.pi, math.pi)
            self.normal = [[v * self.load * math.cos(phi0 + dphi * t) for v, t in
                            zip(normal, self.times)],
                           [v * self.load * math.sin(phi0 + dphi * t) for v, t in
                            zip(normal, self.times)]]
        else:
            self.normal = [[v * self.load for v in normal]]
        capacity = self.mu * self.load
        slip = capacity / self.k * (1.0 + (self.k / self.kd if self.mode == "series" else 0.0))
        self.tangential = []
        for _ in TANGENTIAL[kind]:
            if self.mode == "load":
                self.tangential.append([0.0] + [rng.uniform(-2.0, 2.0) * capacity
                                                for _ in range(n - 1)])
            else:
                self.tangential.append(walk(rng, n, slip))

    def driven_node(self):
        return self.c if self.mode == "series" else self.b

    def orientation(self):
        return f"O{self.j}" if self.theta else "GLOB"

    def axes(self):
        """Global X, Y components of the slot's e1 and e2."""
        c, s = math.cos(math.radians(self.theta)), math.sin(math.radians(self.theta))
        return (c, s), (-s, c)

    def applied(self, table, t):
        """Piecewise-linear amplitude value at step time t."""
        times = self.times
        if t <= times[0]:
            return table[0]
        for i in range(1, len(times)):
            if t <= times[i]:
                s = (t - times[i - 1]) / (times[i] - times[i - 1])
                return table[i - 1] + s * (table[i] - table[i - 1])
        return table[-1]

    def model_lines(self):
        two_d = self.kind == "slot2d"
        x = "0., 0." if two_d else "0., 0., 0."
        lines = [f"*NODE", f"{self.a}, {x}", f"{self.b}, {x}"]
        if self.mode != "direct":
            lines.append(f"{self.c}, {x}")
        if self.theta:  # as Abaqus/CAE writes a datum CSYS turned about 3
            lines += [f"*ORIENTATION, NAME={self.orientation()}",
                      "1.0, 0.0, 0.0, 0.0, 1.0, 0.0", f"3, {fmt(self.theta)}"]
        etype = "CONN2D2" if two_d else "CONN3D2"
        lines += [f"*ELEMENT, TYPE={etype}, ELSET=FRIC", f"{self.element}, {self.a}, {self.b}",
                  f"*ELSET, ELSET=E{self.j}", f"{self.element}",
                  f"*CONNECTOR SECTION, ELSET=E{self.j}, BEHAVIOR=F{self.j}",
                  "SLIDE-PLANE," if self.kind == "slide_plane" else "SLOT,", self.orientation()]
        if self.mode != "direct":
            first = self.c if self.mode == "series" else self.a
            lines += [f"*ELEMENT, TYPE={etype}, ELSET=DRIVE", f"{self.drive}, {first}, {self.b}",
                      f"*ELSET, ELSET=D{self.j}", f"{self.drive}",
                      f"*CONNECTOR SECTION, ELSET=D{self.j}, BEHAVIOR=K{self.j}", "CARTESIAN,"]
            # Inclined: the drive spring acts along the slot's e1 too.
            if self.theta:
                lines.append(self.orientation())
            lines.append(f"*CONNECTOR BEHAVIOR, NAME=K{self.j}")
            for comp in TANGENTIAL[self.kind]:
                lines += [f"*CONNECTOR ELASTICITY, COMPONENT={comp}", fmt(self.kd)]
        lines.append(f"*CONNECTOR BEHAVIOR, NAME=F{self.j}")
        if self.coupled:
            lines.append(f"*CONNECTOR FRICTION, CONTACT FORCE=PRESS{self.j}, "
                         f"STICK STIFFNESS={fmt(self.k)}")
        else:
            lines.append(f"*CONNECTOR FRICTION, PREDEFINED, STICK STIFFNESS={fmt(self.k)}")
        if self.fint:
            lines.append(fmt(self.fint))
        if self.coupled:
            lines += ["*CONNECTOR POTENTIAL", "2", "3"]
        lines.append("*FRICTION" + (f", TAUMAX={fmt(self.taumax)}" if self.taumax else ""))
        lines.append(fmt(self.mu))
        if self.coupled:
            lines += [f"*CONNECTOR DERIVED COMPONENT, NAME=PRESS{self.j}", "1", "1.0"]
        # Held node a; the DOFs of c (series) that carry no drive stiffness are held too.
        lines += ["*BOUNDARY"]
        lines += [f"{self.a}, 1, 2", f"{self.a}, 6, 6"] if two_d else [f"{self.a}, 1, 6"]
        if self.mode == "series" and not self.theta:  # inclined: both DOFs of c are driven
            for dof in (1, 2) if two_d else (1, 2, 3):
                if dof not in TANGENTIAL[self.kind]:
                    lines.append(f"{self.c}, {dof}, {dof}")
        # The CARTESIAN connector makes its nodes' rotations active; nothing restrains them.
        if self.mode != "direct":
            rotations = "6, 6" if two_d else "4, 6"
            lines += [f"{self.b}, {rotations}"]
            if self.mode == "series":
                lines.append(f"{self.c}, {rotations}")
        for n, comp in enumerate(NORMAL[self.kind]):
            lines += amplitude_lines(f"N{self.j}_{comp}", self.times, self.normal[n])
        for n, comp in enumerate(TANGENTIAL[self.kind]):
            lines += amplitude_lines(f"T{self.j}_{comp}", self.times, self.tangential[n])
        if self.theta and self.mode == "load":
            # A later *CLOAD on the same DOF replaces the earlier one, so the normal and the
            # tangential load of an inclined slot go into one amplitude per global DOF.
            e1, e2 = self.axes()
            for d in range(2):
                lines += amplitude_lines(
                    f"L{self.j}_{d + 1}", self.times,
                    [n * e2[d] + t * e1[d] for n, t in zip(self.normal[0], self.tangential[0])])
        return lines

    def step_lines(self):
        if self.theta:
            return self.inclined_step_lines()
        lines = []
        for comp in NORMAL[self.kind]:
            lines += [f"*CLOAD, AMPLITUDE=N{self.j}_{comp}", f"{self.b}, {comp}, 1.0"]
        for comp in TANGENTIAL[self.kind]:
            if self.mode == "load":
                lines += [f"*CLOAD, AMPLITUDE=T{self.j}_{comp}", f"{self.b}, {comp}, 1.0"]
            else:
                lines += [f"*BOUNDARY, AMPLITUDE=T{self.j}_{comp}",
                          f"{self.driven_node()}, {comp}, {comp}, 1.0"]
        return lines

    def inclined_step_lines(self):
        """The loads and drives of an inclined slot in global components: the normal load along
        e2 (direct: its Y component) and the tangential load (load) along e1 on b; the motion along
        e1 of c (series, both DOFs), or of b through its X alone (direct: Y stays free, so b
        moves along the slot)."""
        (c1, s1), (c2, s2) = self.axes()
        n, t = f"N{self.j}_2", f"T{self.j}_1"
        if self.mode == "load":
            return [f"*CLOAD, AMPLITUDE=L{self.j}_1", f"{self.b}, 1, 1.0",
                    f"*CLOAD, AMPLITUDE=L{self.j}_2", f"{self.b}, 2, 1.0"]
        if self.mode == "series":
            return [f"*CLOAD, AMPLITUDE={n}", f"{self.b}, 1, {fmt(c2)}",
                    f"{self.b}, 2, {fmt(s2)}", f"*BOUNDARY, AMPLITUDE={t}",
                    f"{self.c}, 1, 1, {fmt(c1)}", f"{self.c}, 2, 2, {fmt(s1)}"]
        # direct: X of b is prescribed, so only Y takes a load
        return [f"*CLOAD, AMPLITUDE={n}", f"{self.b}, 2, {fmt(s2)}",
                f"*BOUNDARY, AMPLITUDE={t}", f"{self.b}, 1, 1, {fmt(c1)}"]


def write_deck(path, connectors, control, residual, line_search):
    lines = ["*HEADING", "Random friction paths (tests/stress/friction_paths.py)",
             "*ORIENTATION, NAME=GLOB", "1.0, 0.0, 0.0, 0.0, 1.0, 0.0"]
    for c in connectors:
        lines += c.model_lines()
    if control[0] == "direct":
        lines += ["*STEP, NAME=PATH, INC=100000", "*STATIC, DIRECT", f"{control[1]}, 1.0"]
    else:
        lines += ["*STEP, NAME=PATH, INC=100000", "*STATIC",
                  f"{control[1]}, 1.0, 1e-6, {control[2]}"]
    # R_n and R_p (which replaces R_n after I_P = 9 iterations) both tight, and the zero-force
    # threshold epsilon tiny: at a lift-off the largest force can drop below the default
    # 1e-5 q_bar, and then only the correction test applies. q_bar_0 = 100, the order of the
    # smallest peak load, is q_bar until a force appears: with the default 0.01, epsilon q_bar_0 =
    # 1e-14 lies below the round-off of k u (1e-13 here), and a step that starts with every force
    # zero to round-off (an inclined slot without normal load) could never pass R_n.
    lines += ["*CONTROLS, PARAMETERS=FIELD", f"{residual:g}, , 100., , {residual:g}, 1e-12,"]
    if line_search is not None:
        lines += ["*CONTROLS, PARAMETERS=LINE SEARCH", f"{line_search},"]
    for c in connectors:
        lines += c.step_lines()
    lines += ["*OUTPUT, HISTORY", "*ELEMENT OUTPUT, ELSET=FRIC", "CTF, CSF, CNF, CSLIPST, CASU"]
    if any(c.mode != "direct" for c in connectors):
        lines += ["*ELEMENT OUTPUT, ELSET=DRIVE", "CTF"]
    lines.append("*END STEP")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def run_deck(clinch, deck, out):
    proc = subprocess.run([clinch, "run", "--quiet", "--out", out, deck],
                          stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    job = os.path.splitext(os.path.basename(deck))[0]
    sta = os.path.join(out, job + ".sta")
    log = os.path.join(out, job + ".log")
    last = ""
    per_increment = []
    if os.path.exists(sta):
        with open(sta) as f:
            rows = [line.rstrip("\n") for line in f if line.strip()]
        last = rows[-1] if rows else ""
        for row in rows[1:]:
            fields = row.split()
            # "step inc att [U] equil total times...": an attempt that was cut back carries U
            # and has nine fields; a converged one has eight.
            if len(fields) == 8 and fields[0].isdigit():
                per_increment.append(int(fields[3]))
    cutbacks = iterations = increments = 0
    if os.path.exists(log):
        with open(log) as f:
            text = f.read()
        m = re.search(r"(\d+) increments, (\d+) iterations, (\d+) cutbacks", text)
        if m:
            increments, iterations, cutbacks = (int(g) for g in m.groups())
    rows = []
    table = os.path.join(out, job + ".history.csv")
    if os.path.exists(table):
        with open(table) as f:
            rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]
    return (proc.returncode, last, per_increment, increments, iterations, cutbacks, rows,
            proc.stderr)


def check_path(c, rows, rtol):
    """The invariants of the module docstring on one connector's history; returns
    (problems, slipped rows, lift-off rows, worst |P - F_lim| / tol in slip)."""
    e, d = c.element, c.drive
    tol = rtol * max(c.mu * c.load, c.fint, 1.0)
    problems, slipping, lifted, worst = [], 0, 0, 0.0
    comps = TANGENTIAL[c.kind]
    previous_casu = 0.0
    for r in rows:
        t = r["step_time"] if r["total_time"] > 0 else 0.0
        where = f"element {e} ({c.kind}, {c.mode}{', coupled' if c.coupled else ''}) at t={t:.6g}"

        def bad(text):
            if len(problems) < 3:
                problems.append(f"{where}: {text}")

        try:
            csf = [r[f"CSF{i}@{e}"] for i in comps]
            cnf = r[f"CNF{comps[0]}@{e}"]
            slip = r[f"CSLIPST{comps[0]}@{e}"]
            casu = r[f"CASU{comps[0]}@{e}"]
            ctf_n = [r[f"CTF{i}@{e}"] for i in NORMAL[c.kind]]
        except KeyError as missing:
            bad(f"history column {missing} missing")
            break
        p = math.hypot(*csf)
        flim = c.mu * cnf if c.taumax is None else min(c.mu * cnf, c.taumax)
        if p > flim + tol:
            bad(f"|CSF| = {p:.9g} > F_lim = {flim:.9g}")
        if slip not in (0.0, 1.0):
            bad(f"CSLIPST = {slip}")
        if slip == 1.0:
            slipping += 1
            worst = max(worst, abs(p - flim) / tol)
            if abs(p - flim) > tol:
                bad(f"slipping with |CSF| = {p:.9g} != F_lim = {flim:.9g}")
        if casu < previous_casu - tol / c.k:
            bad(f"CASU decreased from {previous_casu:.9g} to {casu:.9g}")
        if slip == 0.0 and casu != previous_casu:
            bad(f"CASU changed from {previous_casu:.9g} to {casu:.9g} while sticking")
        previous_casu = casu
        normal = math.hypot(*ctf_n)
        applied = math.hypot(*(c.applied(table, t) for table in c.normal))
        if applied == 0.0:
            lifted += 1
        if abs(cnf - (normal + c.fint)) > tol:
            bad(f"CNF = {cnf:.9g}, |N| + F_int = {normal + c.fint:.9g}")
        if c.theta and c.mode == "direct":
            # b's Y equilibrium, f1 sin(theta) + f2 cos(theta) = P cos(theta): the slot wedges.
            wedged = c.applied(c.normal[0], t) - csf[0] * math.tan(math.radians(c.theta))
            if abs(ctf_n[0] - wedged) > tol:
                bad(f"N = {ctf_n[0]:.9g}, normal load minus the wedge CSF1 tan(theta) "
                    f"{wedged:.9g}")
        elif abs(normal - applied) > tol:
            bad(f"|N| = {normal:.9g}, applied normal load {applied:.9g}")
        for n, i in enumerate(comps):
            if c.mode == "load":
                expect = c.applied(c.tangential[n], t) - r[f"CTF{i}@{d}"]
            elif c.mode == "series":
                expect = -r[f"CTF{i}@{d}"]
            else:
                continue
            if abs(csf[n] - expect) > tol:
                bad(f"CSF{i} = {csf[n]:.9g}, equilibrium of b gives {expect:.9g}")
        if c.kind == "slide_plane":
            if r[f"CSF1@{e}"] != 0.0:
                bad(f"CSF1 = {r[f'CSF1@{e}']} on the normal component")
            for var in ("CNF", "CSLIPST", "CASU"):
                if r[f"{var}2@{e}"] != r[f"{var}3@{e}"]:
                    bad(f"{var}2 = {r[f'{var}2@{e}']} != {var}3 = {r[f'{var}3@{e}']}")
    return problems, slipping, lifted, worst


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("clinch")
    parser.add_argument("--paths", type=int, default=500)
    parser.add_argument("--per-deck", type=int, default=50)
    parser.add_argument("--seed", type=int, default=20261203)
    parser.add_argument("--work")
    parser.add_argument("--min-rate", type=float, default=1.0)
    parser.add_argument("--max-cutback-fraction", type=float, default=1.0,
                        help="fail when more than this fraction of increments were cut back")
    parser.add_argument("--rtol", type=float, default=1e-6)
    parser.add_argument("--residual", type=float, default=1e-9,
                        help="R_n and R_p of *CONTROLS, PARAMETERS=FIELD (clinch's defaults 0.005 and 0.02 lets an "
                             "increment converge with an imbalance of a few force units, which "
                             "the equilibrium check would flag)")
    parser.add_argument("--modes", type=lambda v: v.split(","), default=MODES,
                        help="comma-separated drives to use (direct,series,load); a connector "
                             "drawn with another drive gets the first")
    parser.add_argument("--kinds", type=lambda v: v.split(","), default=KINDS,
                        help="comma-separated connection types, one per deck in turn "
                             "(slide_plane,slot3d,slot2d)")
    parser.add_argument("--direct", type=lambda v: [float(x) for x in v.split(",")],
                        default=None,
                        help="every deck *STATIC, DIRECT with an increment drawn from this "
                             "comma-separated list (default: 30%% of the decks DIRECT with 0.01 "
                             "or 0.02, the others automatic)")
    parser.add_argument("--inclined", action="store_true",
                        help="SLOT CONN2D2 connectors in a slot turned by a random angle, so "
                             "that their contact force is a constraint reaction computed with "
                             "round-off (zero to round-off where the normal load is 0)")
    parser.add_argument("--line-search", type=int, default=None,
                        help="N_ls of *CONTROLS, PARAMETERS=LINE SEARCH in the step (0: off; "
                             "default: none in the deck, clinch's choice)")
    args = parser.parse_args()
    work = args.work or tempfile.mkdtemp(prefix="clinch-friction-")
    os.makedirs(work, exist_ok=True)
    rng = random.Random(args.seed)
    problems = []
    # per kind: decks, completed decks, paths, paths in completed decks, increments, iterations,
    # cutbacks, most iterations in an increment, slipping rows, lift-off rows
    stats = {kind: [0] * 10 for kind in args.kinds}
    worst_slip = 0.0
    modes = {m: [0, 0] for m in MODES}  # paths, paths in completed decks
    remaining, deck_number = args.paths, 0
    uncut = 0
    while remaining > 0:
        kind = args.kinds[deck_number % len(args.kinds)]
        count = min(args.per_deck, remaining)
        connectors = [Connector(rng, kind, j, args.modes, args.inclined)
                      for j in range(1, count + 1)]
        if args.direct:
            control = ["direct", rng.choice(args.direct)]
        else:
            control = (["direct", rng.choice([0.01, 0.02])] if rng.random() < 0.3 else
                       ["auto", rng.choice([0.01, 0.02]), rng.choice([0.02, 0.05])])
        deck = os.path.join(work, f"friction{deck_number:03d}.inp")
        write_deck(deck, connectors, control, args.residual, args.line_search)
        code, last, per_inc, incs, its, cuts, rows, err = run_deck(
            args.clinch, deck, os.path.join(work, "out"))
        s = stats[kind]
        s[0] += 1
        s[2] += count
        if code == 0 and last == "COMPLETED":
            s[1] += 1
            s[3] += count
        elif code == 2 and last.startswith("FAILED:"):
            print(f"note: {deck} stopped cleanly: {last}")
        else:
            problems.append(f"{deck}: exit {code}, last status line {last!r}, "
                            f"stderr {err[-300:]!r}")
        s[4] += incs
        s[5] += its
        s[6] += cuts
        s[7] = max(s[7], max(per_inc, default=0))
        if not rows and code in (0, 2):
            problems.append(f"{deck}: no history rows")
        # Paths converged at the deck's own increments: a completed deck without a cutback.
        uncut += count if code == 0 and last == "COMPLETED" and cuts == 0 else 0
        for c in connectors:
            modes[c.mode][0] += 1
            modes[c.mode][1] += code == 0 and last == "COMPLETED"
            found, slipping, lifted, worst = check_path(c, rows, args.rtol)
            s[8] += slipping
            s[9] += lifted
            worst_slip = max(worst_slip, worst)
            problems += [f"{deck}: {p}" for p in found]
        remaining -= count
        deck_number += 1
    total = sum(s[2] for s in stats.values())
    converged = sum(s[3] for s in stats.values())
    print(f"{total} paths in {deck_number} decks (seed {args.seed}, {args.per_deck} per deck; "
          + ", ".join(f"{n[0]} {m}" for m, n in modes.items()) + f"), work directory {work}")
    for kind, s in stats.items():
        if not s[0]:
            continue
        mean = s[5] / s[4] if s[4] else 0.0
        print(f"  {kind:11s}: {s[3]}/{s[2]} paths converged ({s[1]}/{s[0]} decks), {s[4]} "
              f"increments, {mean:.2f} Newton iterations per increment (max {s[7]}), {s[6]} "
              f"cutbacks; {s[8]} slipping and {s[9]} lift-off connector rows")
    rate = converged / total if total else 0.0
    print("  by drive: " + ", ".join(f"{m} {n[1]}/{n[0]}" for m, n in modes.items() if n[0])
          + " paths converged")
    print(f"  convergence rate {rate:.4f}; in slip, largest |CSF - F_lim| = {worst_slip:.3g} "
          f"x tol (tol = {args.rtol:g} x max(mu x peak normal load, F_int, 1))")
    all_increments = sum(s[4] for s in stats.values())
    all_iterations = sum(s[5] for s in stats.values())
    print(f"  {uncut}/{total} paths converged without a cutback; "
          f"{all_iterations / all_increments if all_increments else 0.0:.2f} Newton iterations "
          f"per increment over all decks")
    for p in problems:
        print("PROBLEM:", p)
    if not args.work and not problems and rate >= args.min_rate:
        shutil.rmtree(work, ignore_errors=True)
    increments = sum(s[4] for s in stats.values())
    cutbacks = sum(s[6] for s in stats.values())
    if increments and cutbacks > args.max_cutback_fraction * increments:
        print(f"PROBLEM: {cutbacks} cutbacks in {increments} increments")
        return 1
    if problems or rate < args.min_rate:
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
