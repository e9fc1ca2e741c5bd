#!/usr/bin/python3
"""The closed row of grains approaching its equilibrium (doc/validation.md,
"The periodic row of grains").

usage: plot_grain_row.py OUT.png LABEL=SPACING.csv ...

Each SPACING.csv is written by `check_grains.py spacing ... --csv` (columns
time, centre_spacing, exact_centre_spacing); OUT.png shows the centre
spacing over the exact equilibrium's against time, one line per file.
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

if len(sys.argv) < 3:
    sys.exit(__doc__)
fig, ax = plt.subplots(figsize=(6, 4))
for item in sys.argv[2:]:
    label, path = item.rsplit("=", 1)
    with open(path) as f:
        rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]
    ax.plot([r["time"] for r in rows],
            [r["centre_spacing"] / r["exact_centre_spacing"] for r in rows],
            label=label)
ax.axhline(1, color="k", lw=0.8)
ax.set_xlabel("t")
ax.set_ylabel("centre spacing / exact equilibrium's")
ax.grid(True, alpha=0.3)
ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(sys.argv[1], dpi=110)
