"""The page of `clinch report`: one self-contained HTML file (every plot an inline SVG drawn by
matplotlib, no script, style or font fetched from anywhere) from the JSON document that
`clinch report` writes (src/report/report_data.cpp).

Sections: per connector, the parts of each component's force (CEF, CVF, CSF, -CRF, CTF) against
its motion, the components that carry nothing listed instead, and time histories with a panel per
quantity and the step names; per node, time histories; the Newton convergence of every increment attempt (residual and correction
norms, log scale) with cutbacks marked; per golden column, the result over the golden values
with the tolerance band of `clinch compare` and the worst deviation marked; the work-precision
plot of a study; per measured column of a fit, the measured points with the model before and
after (fit_plot.py).

Usage: report_page.py DATA.json PAGE.html [--quiet] [--study STUDY.csv] [--fit CURVES.csv]
Exit 4 when matplotlib cannot be imported (clinch then tries another interpreter).
"""
import html
import io
import json
import math
import os
import sys

try:
    import matplotlib
    matplotlib.use("Agg")
    from matplotlib.figure import Figure
except ImportError:
    print("report_page.py: matplotlib is not installed for this python "
          f"({sys.executable})", file=sys.stderr)
    sys.exit(4)

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import fit_plot  # noqa: E402
import work_precision_plot  # noqa: E402
from work_precision_plot import plain  # noqa: E402

matplotlib.rcParams["svg.fonttype"] = "none"

KEYS = ("step", "increment", "step_time", "total_time")
# A column whose largest |value| is at most this fraction of the largest of its quantity in the
# model (force, moment, displacement, rotation) is zero to round-off: below the default rtol of
# `clinch compare` (1e-6), so compare could not tell it from zero either. Such columns (the total
# force of a driven component, the constraint residual of a HINGE) are listed, not plotted.
NEGLIGIBLE = 1e-6
# The parts of a component's force (output-variables.md §2), in the order they are drawn
# against its motion, with what each is. CRF is drawn with its sign turned: -CRF is the force
# that the motion's actuator (or the constraint) applies, which the other parts balance.
PARTS = (("CEF", "elastic"), ("CVF", "damping"), ("CSF", "friction"),
         ("CRF", "actuator or reaction, sign turned"), ("CTF", "total"))
PANELS = (("force", "forces"), ("moment", "moments"), ("displacement", "displacements"),
          ("rotation", "rotations"), ("rate", "velocities and accelerations"),
          ("ratio", "damage and criteria"), ("status", "status codes"))


# Whole-model energies (docs/dynamics.md "Energies"), drawn together in one plot.
ENERGIES = {"ALLKE": "kinetic energy", "ALLIE": "internal energy",
            "ALLFD": "frictional dissipation", "ALLVD": "viscous dissipation",
            "ALLSD": "stabilization energy",
            "ALLWK": "work of loads and reactions", "ETOTAL": "energy balance"}


class Column:
    """A history column with its description from clinch (src/output/abaqus_labels.hpp)."""

    def __init__(self, name, index, label):
        self.name, self.index = name, index
        self.variable, self.component = label["variable"], label["component"]
        self.derived, self.where = label["derived"], label["where"]
        self.display, self.meaning = label["abaqus"], label["meaning"]
        self.quantity = label["quantity"]
        self.peak = 0.0

    @property
    def is_node(self):
        return self.variable in ("U", "RF", "CF", "V", "A")

    def unit(self):
        """Rotations are in radians (output-variables.md §1.3); the deck states no other unit."""
        return " [rad]" if self.quantity == "rotation" else ""

    def label(self):
        return plain(f"{self.display}: {self.meaning}{self.unit()}")


class Page:
    def __init__(self, progress):
        self.parts = []
        self.count = 0
        self.progress = progress  # shows the plots drawn so far (on a terminal)

    def add(self, html_text):
        self.parts.append(html_text)

    def figure(self, fig, kind, caption, css="", **data):
        self.count += 1
        if self.progress:
            sys.stderr.write(f"\rreport: drawing plot {self.count} ({kind})".ljust(50))
            sys.stderr.flush()
        matplotlib.rcParams["svg.hashsalt"] = f"plot-{self.count}"
        buffer = io.StringIO()
        fig.savefig(buffer, format="svg", metadata={"Date": None})
        svg = buffer.getvalue()
        svg = svg[svg.index("<svg"):]  # drop the XML declaration and DOCTYPE
        attributes = "".join(f' data-{k.replace("_", "-")}="{html.escape(str(v))}"'
                             for k, v in data.items())
        self.add(f'<figure class="plot {css}" data-kind="{kind}"{attributes}>{svg}'
                 f"<figcaption>{html.escape(caption)}</figcaption></figure>")


def series(history, column):
    t = [row[history["time"]] for row in history["rows"]]
    return t, [row[column.index] for row in history["rows"]]


def finite_peak(values):
    return max((abs(v) for v in values if v == v and abs(v) != math.inf), default=0.0)


def step_marks(history, names):
    """(total time, name) of each step's start after the first, and the first step's name."""
    rows, marks = history["rows"], []
    first = names.get(str(int(rows[0][0])), f"step {int(rows[0][0])}") if rows else ""
    for a, b in zip(rows, rows[1:]):
        if b[0] != a[0]:
            marks.append((a[history["time"]], names.get(str(int(b[0])), f"step {int(b[0])}")))
    return first, marks


def mark_steps(ax, history, names, top):
    """Grey lines where steps end, each step's name at its start (on the top panel only)."""
    first, marks = step_marks(history, names)
    for t_end, _ in marks:
        ax.axvline(t_end, color="0.6", linewidth=0.8, linestyle="--")
    if top:
        transform = ax.get_xaxis_transform()
        starts = [(history["rows"][0][history["time"]], first)] + marks if history["rows"] else []
        for t, name in starts:
            ax.text(t, 1.02, plain(f" {name}"), transform=transform, fontsize=8, color="0.3",
                    va="bottom", ha="left", gid=f"step-name-{name}")


def negligible(column, scales):
    return column.peak <= NEGLIGIBLE * scales.get(column.quantity, 0.0)


def force_motion(page, history, where, by_key, scales, choice):
    """One plot per component that moves and carries force: each part of its force against its
    motion. Returns the components left out, with why."""
    left_out = []
    for component in choice["components"] or range(1, 7):
        motion = by_key.get(("CU", component))
        parts = [(by_key.get((v, component)), v, what) for v, what in PARTS]
        parts = [(c, v, what) for c, v, what in parts if c is not None]
        if motion is None and not parts:
            continue
        live = [(c, v, what) for c, v, what in parts if not negligible(c, scales)]
        quiet = [c for c, _, _ in parts if negligible(c, scales)]
        moves = motion is not None and not negligible(motion, scales)
        if not moves or not live:
            if motion is None:
                why = "no motion column"
            elif not moves and live:
                why = (f"does not move ({motion.display} is zero to round-off): constrained; "
                       + ", ".join(f"{c.display} up to {c.peak:.3g}" for c, _, _ in live))
            elif moves:
                why = f"moves ({motion.display} up to {motion.peak:.3g}) but carries no force"
            else:
                why = "carries nothing: every column zero to round-off"
            left_out.append((component, why))
            continue
        fig = Figure(figsize=(4.6, 3.6))
        ax = fig.add_subplot()
        _, u = series(history, motion)
        names = []
        for c, variable, what in live:
            _, f = series(history, c)
            if variable == "CRF":
                f = [-x for x in f]
                name = f"-{c.display.split('@')[0]} ({what})"
            else:
                name = f"{c.display.split('@')[0]} ({what})"
            names.append(name)
            ax.plot(u, f, "-", marker="." if variable == "CTF" else None, markersize=3,
                    label=plain(name), gid=f"curve-{variable}")
        quantity = live[0][0].quantity
        ax.set_xlabel(motion.label(), fontsize=8)
        ax.set_ylabel(quantity, fontsize=8)
        ax.set_title(plain(f"connector {where}: {quantity}s against "
                           f"{motion.display.split('@')[0]}"), fontsize=9)
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=7)
        fig.tight_layout()
        caption = (f"Connector {where}, component {component}: "
                   + ", ".join(names) + f" against {motion.display} ({motion.meaning})")
        if quiet:
            caption += ("; zero to round-off, not drawn: "
                        + ", ".join(f"{c.display} (largest {c.peak:.2g})" for c in quiet))
        page.figure(fig, "force-motion", caption, connector=where, component=component,
                    curves=" ".join(v for _, v, _ in live))
    return left_out


def time_histories(page, history, where, columns, kind, scales, names):
    """One plot of the connector's (node's) columns against total time, a panel per quantity,
    so that forces and moments, displacements and rotations each have their own axis."""
    live = [c for c in columns if not negligible(c, scales) or c.quantity in ("ratio", "status")]
    quiet = [c for c in columns if c not in live]
    panels = [(q, title, [c for c in live if c.quantity == q]) for q, title in PANELS]
    panels = [p for p in panels if p[2]]
    what = "connector" if kind == "connector" else "node"
    if not panels:
        return quiet
    fig = Figure(figsize=(13.0, 0.9 + 2.0 * len(panels)))
    axes = fig.subplots(len(panels), 1, sharex=True, squeeze=False)[:, 0]
    for i, (ax, (quantity, title, members)) in enumerate(zip(axes, panels)):
        for c in members:
            t, v = series(history, c)
            ax.plot(t, v, label=plain(f"{c.display.split('@')[0]}: {c.meaning}"),
                    gid=f"history-{c.name}")
        mark_steps(ax, history, names, top=i == 0)
        ax.set_ylabel(plain(f"{quantity}{members[0].unit()}"), fontsize=9)
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=7, loc="center left", bbox_to_anchor=(1.005, 0.5))
    axes[-1].set_xlabel("total time (dashed lines: step ends; step names at the top)")
    fig.suptitle(plain(f"{what} {where}: " + ", ".join(t for _, t, _ in panels)
                       + " against total time"), fontsize=10)
    fig.tight_layout()
    caption = f"{what.capitalize()} {where}: " + ", ".join(c.display for c in live)
    if quiet:
        caption += "; zero to round-off, not drawn: " + ", ".join(c.display for c in quiet)
    page.figure(fig, f"history-{kind}", caption, where=where, panels=len(panels),
                css="wide")
    return quiet


def energy_history(page, history, columns, names):
    """The whole-model energies against total time in one plot; ETOTAL dashed, since a drift of
    it is what the analyst looks for."""
    fig = Figure(figsize=(13.0, 3.4))
    ax = fig.subplots()
    for c in columns:
        t, v = series(history, c)
        ax.plot(t, v, "--" if c.variable == "ETOTAL" else "-",
                label=f"{c.variable}: {ENERGIES[c.variable]}", gid=f"energy-{c.variable}")
    mark_steps(ax, history, names, top=True)
    ax.set_ylabel("energy", fontsize=9)
    ax.set_xlabel("total time (dashed lines: step ends; step names at the top)")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=7, loc="center left", bbox_to_anchor=(1.005, 0.5))
    fig.tight_layout()
    page.figure(fig, "energies", "Whole-model energies: " + ", ".join(c.variable for c in columns)
                + " (ETOTAL = ALLKE + ALLIE + ALLFD + ALLVD + ALLSD - ALLWK)", css="wide")


def choose(group, limit, choice, kind):
    """The connectors (nodes) to draw and a sentence that says how they were chosen."""
    if choice["elements"]:
        chosen = [w for w in choice["elements"] if w in group]
        return chosen, (f"{len(chosen)} of {len(group)} {kind}s chosen with "
                        "<code>--elements</code>.")
    if len(group) <= limit:
        return list(group), ""
    if kind == "connector":
        def load(where):
            force = [c.peak for c in group[where] if c.quantity == "force"]
            moment = [c.peak for c in group[where] if c.quantity == "moment"]
            return (max(force, default=0.0), max(moment, default=0.0))
        chosen = sorted(group, key=load, reverse=True)[:limit]
        order = list(group)
        chosen.sort(key=order.index)
        return chosen, (f"{len(group)} connectors have history columns; the {limit} most "
                        "loaded (largest |force| of any force column over the run, then largest "
                        "|moment|) are drawn (<code>clinch report --connectors N</code> draws "
                        "more, <code>--elements</code> chooses them).")
    return list(group)[:limit], (f"{len(group)} {kind}s have history columns; the first {limit} "
                                 "are drawn (<code>clinch report --connectors N</code> draws "
                                 "more).")


def drawable(norm):
    """The norm where a log scale can show it: zero norms (increments whose motions are all
    prescribed) and NaN or infinite ones (a Newton iteration that diverged) are left out."""
    return norm if 0.0 < norm < math.inf else math.nan


def convergence(page, data):
    iterations, attempts = data["iterations"], data["attempts"]
    if not iterations and not attempts:
        return
    # The attempts in order (from the .sta, else as the log shows them), each with its
    # iterations from the log; an attempt that failed before its first iteration still gets a
    # slot, so that every cutback is marked.
    by_attempt = {}
    for r in iterations:
        by_attempt.setdefault((r["step"], r["increment"], r["attempt"]), []).append(r)
    keys = [(a["step"], a["increment"], a["attempt"]) for a in attempts] or list(by_attempt)
    cut = {(a["step"], a["increment"], a["attempt"]) for a in attempts if a["cut_back"]}
    fig = Figure(figsize=(13.0, 3.8))
    ax = fig.add_subplot()
    x, residual, correction, spans, slot = [], [], [], [], 0
    for key in keys:
        records = by_attempt.get(key, [])
        first = slot + 1
        for r in records or [None]:
            x.append(slot := slot + 1)
            residual.append(drawable(r["residual"]) if r else math.nan)
            correction.append(drawable(r["correction"]) if r else math.nan)
        spans.append((key, first, slot))
        # A gap between attempts: each attempt's iterations make their own line.
        x.append(slot + 0.5)
        residual.append(math.nan)
        correction.append(math.nan)
    ax.plot(x, residual, "o-", markersize=3, label="residual norm", gid="norm-residual")
    ax.plot(x, correction, "s--", markersize=3, label="correction norm", gid="norm-correction")
    cutbacks = 0
    for key, first, last in spans:
        if key in cut:
            cutbacks += 1
            ax.axvspan(first - 0.5, last + 0.5, color="C3", alpha=0.25,
                       label="cut back" if cutbacks == 1 else None, gid=f"cutback-{cutbacks}")
        elif len(spans) <= 400:
            ax.axvline(first - 0.5, color="0.85", linewidth=0.6)
    if any(v == v for v in residual + correction):  # some norm is not NaN
        ax.set_yscale("log")
        ax.set_ylabel("norm (log scale)")
    else:
        ax.text(0.5, 0.5, "no norm is positive and finite (zero: all motions prescribed): "
                "nothing to draw on a log scale", transform=ax.transAxes, ha="center", fontsize=8)
        ax.set_ylabel("norm")
        ax.set_yticks([])
    ax.set_xlabel("Newton iteration (counted over the run; grey lines: a new increment attempt)")
    ax.set_title(f"Newton convergence: {len(spans)} increment attempts, {cutbacks} cut back",
                 fontsize=10)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    page.figure(fig, "convergence",
                "Residual and correction norms of every Newton iteration (from the .log); zero "
                "and non-finite norms are not drawn; red bands: attempts that were cut back "
                "(from the .sta)", css="wide", attempts=len(spans), cutbacks=cutbacks)


def interpolate(ts, vs, t):
    """Linear interpolation at t (rows matched by total_time, as `clinch compare`)."""
    if t <= ts[0]:
        return vs[0]
    for i in range(1, len(ts)):
        if ts[i] >= t:
            if ts[i] == t:
                return vs[i]
            w = (t - ts[i - 1]) / (ts[i] - ts[i - 1])
            return vs[i - 1] + w * (vs[i] - vs[i - 1])
    return vs[-1]


def golden_overlays(page, history, golden, columns_by_name):
    g_time = golden["columns"].index("total_time")
    rtol, atol = golden["rtol"], golden["atol"]
    for comparison in golden["comparison"]:
        name = comparison["name"]
        gi = golden["columns"].index(name)
        # The run's column of the same name, or the same column in the other naming (CTM1@7
        # is CTF4@7: the keys come from clinch's descriptions of both tables).
        label = golden["labels"][gi]
        column = columns_by_name.get(
            (label["variable"], label["component"], label["derived"], label["where"]))
        gt = [row[g_time] for row in golden["rows"]]
        gv = [row[gi] for row in golden["rows"]]
        fig = Figure(figsize=(6.4, 4.6))
        top, bottom = fig.subplots(2, 1, sharex=True, gridspec_kw={"height_ratios": [3, 2]})
        label = column.label() if column else plain(name)
        if column is None:
            top.text(0.5, 0.5, plain(f"{name}: no such column in the run"),
                     transform=top.transAxes, ha="center")
        else:
            t, v = series(history, column)
            top.plot(t, v, "-", color="C0", label="run", gid="result")
        top.plot(gt, gv, "o", color="k", fillstyle="none", label="golden", gid="golden")
        # cli-contract.md `clinch compare`: |r - g| <= atol + rtol max(|g|, largest |g|).
        scale = max((abs(x) for x in gv), default=0.0)
        allowed = [atol + rtol * max(abs(x), scale) for x in gv]
        top.fill_between(gt, [x - a for x, a in zip(gv, allowed)],
                         [x + a for x, a in zip(gv, allowed)], color="C2", alpha=0.3,
                         label="tolerance band", gid="band")
        bottom.fill_between(gt, [-a for a in allowed], allowed, color="C2", alpha=0.3,
                            gid="band-deviation")
        worst = comparison.get("worst")
        if column is not None:
            t, v = series(history, column)
            inside = [x for x in gt if t[0] <= x <= t[-1]]
            deviation = [interpolate(t, v, x) - gv[gt.index(x)] for x in inside]
            bottom.plot(inside, deviation, "o-", color="C0", markersize=3, gid="deviation")
        if worst is not None:
            signed = worst["result"] - worst["golden"]
            text = (f"worst |r - g| = {worst['difference']:.3g} at t = {worst['total_time']:g} "
                    f"(allowed {worst['allowed']:.3g})")
            top.plot([worst["total_time"]], [worst["result"]], "x", color="C3", markersize=12,
                     markeredgewidth=2, label="worst deviation", gid="worst-deviation")
            bottom.plot([worst["total_time"]], [signed], "x", color="C3", markersize=12,
                        markeredgewidth=2, gid="worst-deviation-point")
            bottom.text(0.01, 0.97, text, transform=bottom.transAxes, va="top", fontsize=8,
                        color="C3", gid="worst-deviation-text",
                        bbox={"facecolor": "white", "alpha": 0.8, "edgecolor": "none"})
        top.set_ylabel(plain(name), fontsize=9)
        top.set_title(f"{label}: {comparison['verdict'].upper()} "
                      f"(rtol {rtol:g}, atol {atol:g})", fontsize=9)
        top.grid(True, alpha=0.3)
        top.legend(fontsize=7)
        bottom.set_ylabel("run - golden", fontsize=9)
        bottom.set_xlabel("total time")
        bottom.grid(True, alpha=0.3)
        fig.tight_layout()
        caption = f"{name} against the golden table: {comparison['verdict']}"
        if worst is not None:
            caption += (f"; worst deviation {worst['difference']:.3g} at total time "
                        f"{worst['total_time']:g}, allowed {worst['allowed']:.3g}")
        page.figure(fig, "golden", caption, column=name, verdict=comparison["verdict"],
                    worst_time=worst["total_time"] if worst else "",
                    worst_difference=worst["difference"] if worst else "")


def summary_table(rows):
    cells = "".join(f"<tr><th>{html.escape(k)}</th><td>{html.escape(str(v))}</td></tr>"
                    for k, v in rows)
    return f"<table class=\"summary\">{cells}</table>"


def settings_table(settings):
    """The study's settings as `clinch study` printed them."""
    head = ("setting", "scale", "increments", "iterations", "cutbacks", "work", "wall s",
            "vs finest", "est. error", "worst column", "status")
    keys = ("setting", "scale", "increments", "iterations", "cutbacks", "work", "wall_seconds",
            "difference_to_finest", "estimated_error", "worst_column", "status")
    rows = []
    for s in settings:
        cells = []
        for key in keys:
            value = s.get(key, "")
            if key == "scale" and value:
                value = work_precision_plot.scale_text(float(value))
            elif key in ("difference_to_finest", "estimated_error") and value:
                value = (">" if key == "estimated_error" and s["estimate_is_bound"] == "1"
                         else "") + f"{float(value):.2e}"
            elif key == "wall_seconds" and value:
                value = f"{float(value):.3f}"
            cells.append(f"<td>{html.escape(value)}</td>")
        chosen = ' class="chosen"' if s.get("chosen") == "1" else ""
        rows.append(f"<tr{chosen}>{''.join(cells)}</tr>")
    header = "".join(f"<th>{h}</th>" for h in head)
    return f'<table class="study"><tr>{header}</tr>{"".join(rows)}</table>'


STYLE = """body{font-family:sans-serif;margin:1em 1.5em;color:#222}
figure.plot{display:inline-block;margin:.4em;vertical-align:top;border:1px solid #ddd;
padding:.3em;background:#fff;width:calc(33% - 1.6em);box-sizing:border-box}
figure.plot.wide{display:block;width:calc(100% - .8em)}
figure.plot svg{display:block;width:100%;height:auto}
figcaption{font-size:.8em;color:#444}table{border-collapse:collapse}
td,th{border:1px solid #ccc;padding:.2em .6em;text-align:left;font-size:.9em}
tr.chosen{background:#e3f4e3}"""


def number(value):
    """A number of the page data: clinch writes NaN and infinities as "nan", "inf", "-inf"."""
    return float(value) if isinstance(value, str) else value


def read_data(path):
    with open(path, encoding="utf-8") as f:
        data = json.load(f)
    tables = [data["history"]] + ([data["golden"]] if "golden" in data else [])
    for table in tables:
        table["rows"] = [[number(v) for v in row] for row in table["rows"]]
    for record in data["iterations"]:
        for key in ("residual", "correction", "constraint_violation"):
            record[key] = number(record[key])
    for comparison in data.get("golden", {}).get("comparison", []):
        worst = comparison.get("worst")
        if worst is not None:
            for key in worst:
                worst[key] = number(worst[key])
    return data


def main():
    args, study_csv, fit_csv, rest = [], None, None, sys.argv[1:]
    while rest:
        arg = rest.pop(0)
        if arg == "--study" and rest:
            # The path as given, not through the JSON text, which holds names only as UTF-8.
            study_csv = rest.pop(0)
        elif arg == "--fit" and rest:
            fit_csv = rest.pop(0)
        elif arg != "--quiet":
            args.append(arg)
    if len(args) != 2:
        print(__doc__, file=sys.stderr)
        return 3
    data = read_data(args[0])
    history = data["history"]
    history["time"] = history["columns"].index("total_time")
    labels = history["labels"]
    columns = [Column(n, i, labels[i]) for i, n in enumerate(history["columns"]) if n not in KEYS]
    # The scale of each quantity: the largest |value| of any column of it in the model.
    scales = {}
    for c in columns:
        c.peak = finite_peak(series(history, c)[1])
        scales[c.quantity] = max(scales.get(c.quantity, 0.0), c.peak)
    choice = data["choice"]
    step_names = data.get("step_names", {})
    # Progress as `clinch run` shows it: on a terminal only, and not with --quiet.
    page = Page(sys.stderr.isatty() and "--quiet" not in sys.argv)
    attempts = data["attempts"]
    page.add(f"<h1>clinch report: {html.escape(data['job'])}</h1>")
    page.add(summary_table([
        ("history table", history["path"]),
        ("how the run ended", data.get("ending", "(no status file)")),
        ("increments", sum(1 for a in attempts if not a["cut_back"])),
        ("Newton iterations", sum(a["iterations"] for a in attempts)),
        ("cutbacks", sum(1 for a in attempts if a["cut_back"])),
        ("history columns", len(columns)),
    ]))
    energies = [c for c in columns if c.variable in ENERGIES]
    connectors, nodes = {}, {}
    for c in columns:
        if c.variable in ENERGIES:
            continue
        if choice["variables"] and c.variable not in choice["variables"] and c.variable != "CU":
            continue
        (nodes if c.is_node else connectors).setdefault(c.where, []).append(c)
    limit = data["max_connectors"]
    for title, group, kind in (("Connectors", connectors, "connector"),
                               ("Nodes", nodes, "node")):
        if not group:
            continue
        chosen, how = choose(group, limit, choice, kind)
        if not chosen:
            continue
        page.add(f"<h2>{title}</h2>")
        if how:
            page.add(f"<p>{how}</p>")
        for where in chosen:
            members = group[where]
            if choice["variables"] and "CU" not in choice["variables"]:
                shown = [c for c in members if c.variable != "CU"]
            else:
                shown = members
            if choice["components"]:
                shown = [c for c in shown if c.component in choice["components"]]
            page.add(f"<h3>{kind} {html.escape(where)}</h3>")
            left_out = []
            if kind == "connector":
                by_key = {(c.variable, c.component): c for c in members}
                left_out = force_motion(page, history, where, by_key, scales, choice)
            time_histories(page, history, where, shown, kind, scales, step_names)
            if left_out:
                rows = "".join(f"<tr><td>{k}</td><td>{html.escape(why)}</td></tr>"
                               for k, why in left_out)
                page.add(f'<table class="left-out" data-connector="{html.escape(where)}">'
                         "<tr><th>component</th><th>not plotted against its motion: why"
                         f"</th></tr>{rows}</table>")
    if energies:
        page.add("<h2>Energies</h2>")
        energy_history(page, history, energies, step_names)
    if data["iterations"] or data["attempts"]:
        page.add("<h2>Newton convergence</h2>")
        convergence(page, data)
    if "golden" in data:
        golden = data["golden"]
        failed = [c["name"] for c in golden["comparison"] if c["verdict"] != "pass"]
        page.add(f"<h2>Golden comparison: {html.escape(golden['path'])}</h2>")
        page.add(f"<p>{len(golden['comparison'])} columns, {len(failed)} failing"
                 + (f" ({html.escape(', '.join(failed))})" if failed else "")
                 + f"; rtol {golden['rtol']:g}, atol {golden['atol']:g}; the band is "
                 "atol + rtol&middot;max(|g|, largest |g| of the column), as "
                 "<code>clinch compare</code>.</p>")
        golden_overlays(page, history, golden, {(c.variable, c.component, c.derived, c.where): c
                                                for c in columns})
    if study_csv is not None:
        settings = work_precision_plot.read_settings(study_csv)
        page.add(f"<h2>Work precision: {html.escape(data['study_csv'])}</h2>")
        page.figure(work_precision_plot.figure(settings), "work-precision",
                    "Estimated error of each setting of the study against its wall time",
                    settings=len(settings))
        page.add(settings_table(settings))
    if fit_csv is not None:
        try:
            curves = fit_plot.read_curves(fit_csv)
        except (OSError, ValueError, IndexError) as e:
            print(f"report_page.py: {e}", file=sys.stderr)
            return 3
        page.add(f"<h2>Fit: {html.escape(fit_csv)}</h2>")
        for (data_file, column), (abscissa, rows) in curves.items():
            page.figure(fit_plot.figure(abscissa, column, rows), "fit",
                        f"{column} of {data_file}: measured, and the model before and after "
                        "the fit", column=column, data=data_file)
    if page.progress:
        sys.stderr.write("\r" + " " * 50 + "\r")
    with open(args[1], "w", encoding="utf-8") as f:
        f.write("<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\">"
                f"<title>clinch report: {html.escape(data['job'])}</title>"
                f"<style>{STYLE}</style></head><body>\n" + "\n".join(page.parts)
                + "\n</body></html>\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
