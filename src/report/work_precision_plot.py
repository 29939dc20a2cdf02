"""The work-precision plot of `clinch study`: for each completed setting, its wall time against
its estimated error (worst history column, relative to the column's largest |value|), log-log,
with the difference from the finest setting beside it, the --rtol line and the setting it chose.

Usage: work_precision_plot.py STUDY.csv PLOT.svg
Exit 4 when matplotlib cannot be imported (clinch then tries another interpreter).
"""
import csv
import math
import os
import sys

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.ticker
    from matplotlib.figure import Figure
except ImportError:
    print("work_precision_plot.py: matplotlib is not installed for this python "
          f"({sys.executable})", file=sys.stderr)
    sys.exit(4)

# Text stays text in the SVG, so that the page can be searched and its labels checked.
matplotlib.rcParams["svg.fonttype"] = "none"
matplotlib.rcParams["svg.hashsalt"] = "clinch-study"


def plain(text):
    """`text` as matplotlib shows it literally: a pair of '$' would start mathematics (or fail to
    parse), so every '$' is escaped; an escaped '$' never starts mathematics, and matplotlib
    turns it back into '$' (outside mathematics no other character is special)."""
    return str(text).replace("$", r"\$")


def read_settings(path):
    # The study writes paths and column names as the bytes they are; those that are not UTF-8
    # are shown as U+FFFD rather than stop the plot.
    with open(path, newline="", encoding="utf-8", errors="replace") as f:
        return list(csv.DictReader(f))


def scale_text(scale):
    if scale == 1.0:
        return "1"
    inverse = 1.0 / scale
    if scale < 1.0 and abs(inverse - round(inverse)) < 1e-9 * inverse:
        return f"1/{round(inverse)}"
    return f"{scale:.4g}"


def figure(settings):
    """The plot as a matplotlib Figure (also drawn by report_page.py)."""
    fig = Figure(figsize=(6.4, 4.2))
    ax = fig.add_subplot()
    done = [s for s in settings if s["state"] == "completed" and s["estimated_error"]]
    points = [(float(s["wall_seconds"]), float(s["estimated_error"]), s) for s in done]
    drawn = [(t, e, s) for t, e, s in points if e > 0.0]
    ax.plot([t for t, _, _ in drawn], [e for _, e, _ in drawn], "o-", color="C0",
            label="estimated error (Richardson)", gid="estimated-error")
    for t, e, s in drawn:
        ax.annotate(scale_text(float(s["scale"])), (t, e), textcoords="offset points",
                    xytext=(5, 4), fontsize=8)
        if s["estimate_is_bound"] == "1":
            ax.plot([t], [e], "^", color="C3", markersize=8, gid="lower-bound")
    diff = [(float(s["wall_seconds"]), float(s["difference_to_finest"])) for s in done
            if float(s["difference_to_finest"]) > 0.0]
    ax.plot([t for t, _ in diff], [d for _, d in diff], "s--", color="C1", fillstyle="none",
            label="difference from the finest setting", gid="difference-to-finest")
    rtol = next((s["rtol"] for s in settings if s["rtol"]), "")
    if rtol:
        ax.axhline(float(rtol), color="C2", linestyle=":", label=f"--rtol {rtol}", gid="rtol")
    chosen = [s for s in done if s["chosen"] == "1"]
    for s in chosen:
        ax.plot([float(s["wall_seconds"])], [float(s["estimated_error"])], "o", markersize=14,
                markerfacecolor="none", markeredgecolor="C2", markeredgewidth=2,
                label=f"chosen: scale {scale_text(float(s['scale']))}", gid="chosen")
    failed = [s for s in settings if s["state"] == "failed"]
    if drawn or diff:
        ax.set_xscale("log")
        ax.set_yscale("log")
        # At least a decade on each axis, so that a labelled power of ten is always in view;
        # minor ticks stay unlabelled (their labels collide on a short range).
        times = [t for t, _, _ in drawn] + [t for t, _ in diff]
        errors = [e for _, e, _ in drawn] + [d for _, d in diff]
        for values, set_limits, axis in ((times, ax.set_xlim, ax.xaxis),
                                         (errors, ax.set_ylim, ax.yaxis)):
            low, high = min(values) / 1.5, max(values) * 1.5
            if high / low < 10.0:
                middle = math.sqrt(low * high)
                low, high = middle / math.sqrt(10.0), middle * math.sqrt(10.0)
            set_limits(low, high)
            axis.set_minor_formatter(matplotlib.ticker.NullFormatter())
    ax.set_xlabel("wall time of the run [s]")
    ax.set_ylabel("relative error, worst history column [-]")
    deck = os.path.basename(settings[0]["deck"]) if settings else ""
    title = plain(f"work precision: {deck}")
    if failed:
        title += f" ({len(failed)} setting{'s' if len(failed) > 1 else ''} failed)"
    ax.set_title(title, fontsize=10)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    return fig


def main():
    if len(sys.argv) != 3:
        print(__doc__, file=sys.stderr)
        return 3
    figure(read_settings(sys.argv[1])).savefig(sys.argv[2], format="svg",
                                               metadata={"Date": None})
    return 0


if __name__ == "__main__":
    sys.exit(main())
