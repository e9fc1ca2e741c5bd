#!/usr/bin/python3
"""Plot metrics.csv columns of one or several levelsinter runs to a PNG.

Each RUN is an output directory (holding metrics.csv) or a metrics.csv
itself; its curves are labelled with the run directory. Every column given
with --y gets its own panel, sharing the x axis (--x, default time). Give
the runs before --y.

examples:
  plot_metrics.py output/two_cylinders_2d --y neck_radius -o neck.png
  plot_metrics.py run_a run_b --y solid_volume interface_area --logy -o a.png
  plot_metrics.py run_a --columns        # list the columns and stop
"""
import argparse
import csv
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def read_metrics(run):
    path = pathlib.Path(run)
    if path.is_dir():
        path = path / "metrics.csv"
    if not path.is_file():
        sys.exit(f"plot_metrics.py: error: '{path}' does not exist")
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        sys.exit(f"plot_metrics.py: error: '{path}' has no rows")
    label = str(path.parent) if path.name == "metrics.csv" else str(path)
    return label, rows


def column(rows, name, label):
    if name not in rows[0]:
        sys.exit(f"plot_metrics.py: error: {label} has no column '{name}' "
                 f"(it has: {', '.join(rows[0])})")
    return [float(r[name]) for r in rows]


def main():
    description, examples = __doc__.split("examples:")
    parser = argparse.ArgumentParser(
        description=description, epilog="examples:" + examples,
        formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("runs", nargs="+", metavar="RUN",
                        help="output directory or metrics.csv")
    parser.add_argument("--x", default="time",
                        help="column on the x axis (default: time)")
    parser.add_argument("--y", nargs="+", default=["solid_volume"],
                        metavar="COLUMN",
                        help="columns to plot, one panel each "
                             "(default: solid_volume)")
    parser.add_argument("-o", "--output", default="metrics.png",
                        help="PNG file to write (default: metrics.png)")
    parser.add_argument("--logx", action="store_true", help="log x axis")
    parser.add_argument("--logy", action="store_true", help="log y axes")
    parser.add_argument("--columns", action="store_true",
                        help="print each run's columns and stop")
    args = parser.parse_args()

    runs = [read_metrics(run) for run in args.runs]
    if args.columns:
        for label, rows in runs:
            print(f"{label}: {', '.join(rows[0])}")
        return

    fig, axes = plt.subplots(len(args.y), 1, sharex=True, squeeze=False,
                             figsize=(6.5, 2.2 + 2.3 * len(args.y)))
    for ax, name in zip(axes[:, 0], args.y):
        for label, rows in runs:
            ax.plot(column(rows, args.x, label), column(rows, name, label),
                    "-", marker="." if len(rows) < 60 else None, label=label)
        ax.set_ylabel(name)
        ax.set_xscale("log" if args.logx else "linear")
        if args.logy:
            ax.set_yscale("log")
        else:  # values, not an offset + small ticks
            ax.ticklabel_format(axis="y", useOffset=False)
        ax.grid(True, which="both", alpha=0.3)
    axes[0, 0].legend(fontsize=8)
    axes[-1, 0].set_xlabel(args.x)
    fig.tight_layout()
    fig.savefig(args.output, dpi=120)
    print(f"wrote {args.output}")


if __name__ == "__main__":
    main()
