#!/usr/bin/python3
"""Work-precision plot: error against wall time, one line per study.

usage: plot_work_precision.py OUT.png LABEL=FILE.csv [LABEL=FILE.csv ...]

Each CSV is a table written by `levelsinter_validation transport ... --csv`
(columns level, h, cpu_time, volume_error, shape_error, ...). The left
panel shows the relative volume (area) error, the right one the shape error
(mean distance of the interface from the exact one), both against the CPU
time of the run (summed over the ranks; unlike the wall time it does not
depend on other jobs sharing the machine), with the finest cell size
written next to each point.
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

if len(sys.argv) < 3:
    sys.exit(__doc__)

fig, axes = plt.subplots(1, 2, figsize=(11, 4.5))
for item in sys.argv[2:]:
    label, path = item.rsplit("=", 1)
    with open(path) as f:
        rows = list(csv.DictReader(f))
    wall = [float(r["cpu_time"]) for r in rows]
    for ax, column in zip(axes, ["volume_error", "shape_error"]):
        values = [float(r[column]) for r in rows]
        ax.loglog(wall, values, "o-", label=label)
        for t, v, r in zip(wall, values, rows):
            ax.annotate(f"1/{round(1 / float(r['h']))}", (t, v), fontsize=7,
                        textcoords="offset points", xytext=(3, 3))
axes[0].set_ylabel("relative volume (area) error")
axes[1].set_ylabel("shape error (mean distance)")
for ax in axes:
    ax.set_xlabel("CPU time (s)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(sys.argv[1], dpi=120)
