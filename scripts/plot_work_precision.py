#!/usr/bin/python3
"""Work-precision plot: error against CPU time, one line per study.

usage: plot_work_precision.py OUT.png [--columns A,B] [--group COLUMN]
                              LABEL=FILE.csv [LABEL=FILE.csv ...]

Each CSV is a study table with a cpu_time column, e.g. written by
`levelsinter_validation transport ... --csv` (columns level, h, cpu_time,
volume_error, shape_error, ...) or `surface_diffusion_validation mullins
... --csv` (h, steps, cpu_time, rate_error, volume_change, ...). One panel
per column of --columns (default volume_error,shape_error), the magnitude
of the column against the CPU time of the run (summed over the ranks;
unlike the wall time it does not depend on other jobs sharing the
machine). Points are labelled with the finest cell size, and with the
number of steps where the table has them. --group h draws one line per
value of that column (e.g. one line per mesh over the time steps).
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

LABELS = {
    "volume_error": "relative volume (area) error",
    "shape_error": "shape error (mean distance)",
    "rate_error": "|relative decay-rate error|",
    "volume_change": "|relative area change|",
    "max_neck_error": "max relative neck-radius error",
    "final_neck_error": "final relative neck-radius error",
    "area_drift": "|solid-area drift|",
}

args = sys.argv[1:]
columns, group = ["volume_error", "shape_error"], None
if "--columns" in args:
    i = args.index("--columns")
    columns = args[i + 1].split(",")
    del args[i : i + 2]
if "--group" in args:
    i = args.index("--group")
    group = args[i + 1]
    del args[i : i + 2]
if len(args) < 2:
    sys.exit(__doc__)


def point_label(row):
    text = f"1/{round(1 / float(row['h']))}"
    if "steps" in row:
        text += f", {round(float(row['steps']))}"
    return text


fig, axes = plt.subplots(1, len(columns), figsize=(5.5 * len(columns), 4.5),
                         squeeze=False)
for item in args[1:]:
    label, path = item.rsplit("=", 1)
    with open(path) as f:
        rows = list(csv.DictReader(f))
    groups = {}
    for r in rows:
        groups.setdefault(r[group] if group else None, []).append(r)
    for key, members in groups.items():
        name = label if key is None else f"{label}, {group} = {point_label({'h': key}) if group == 'h' else key}"
        cpu = [float(r["cpu_time"]) for r in members]
        for ax, column in zip(axes[0], columns):
            values = [abs(float(r[column])) for r in members]
            ax.loglog(cpu, values, "o-", label=name)
            for t, v, r in zip(cpu, values, members):
                ax.annotate(point_label(r), (t, v), fontsize=7,
                            textcoords="offset points", xytext=(3, 3))
for ax, column in zip(axes[0], columns):
    ax.set_ylabel(LABELS.get(column, column))
    ax.set_xlabel("CPU time (s)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(args[0], dpi=120)
