"""The fit section of `clinch report --fit`: for each measured column of each data file of a fit,
the measured points with the model's curve at the deck's own values (before) and at the fitted
values (after), from the <job>.fit-curves.csv that `clinch fit` writes (src/fit/fit_tables.hpp).
"""
import csv

from matplotlib.figure import Figure

from work_precision_plot import plain

HEADER = ["data", "column", "abscissa", "x", "measured", "initial", "fitted"]


def read_curves(path):
    """{(data file, column): (abscissa, rows)} in the file's order; ValueError when the file is
    not a fit-curves table."""
    with open(path, newline="", encoding="utf-8", errors="replace") as f:
        reader = csv.reader(f)
        if next(reader, None) != HEADER:
            raise ValueError(f"{path}:1: not a <job>.fit-curves.csv of `clinch fit`")
        curves = {}
        for row in reader:
            data, column, abscissa = row[0], row[1], row[2]
            values = [float(v) if v else None for v in row[3:]]
            curves.setdefault((data, column), (abscissa, []))[1].append(values)
    return curves


def figure(abscissa, column, rows):
    fig = Figure(figsize=(5.0, 3.4))
    ax = fig.add_subplot()
    x = [r[0] for r in rows]
    ax.plot(x, [r[1] for r in rows], "o", ms=3, color="black", label="measured")
    for index, label, style in ((2, "before (deck's values)", "--"), (3, "after (fitted)", "-")):
        points = [(xi, r[index]) for xi, r in zip(x, rows) if r[index] is not None]
        if points:
            ax.plot([p[0] for p in points], [p[1] for p in points], style, label=label)
    ax.set_xlabel(plain(abscissa))
    ax.set_ylabel(plain(column))
    ax.legend(fontsize="small")
    ax.grid(True, alpha=0.3)
    fig.tight_layout()
    return fig
