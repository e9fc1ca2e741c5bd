#!/usr/bin/python3
"""Plot the mean outer FGMRES count per Stokes solve against R/h, one line per
study CSV (the `mean_stokes_its` column of levelsinter_viscous_validation's
hopper or spheres table; R/h from the column `h` and the particle radius).

usage: plot_solver_iterations.py OUT.png RADIUS LABEL=FILE.csv [LABEL=FILE.csv ...]
(a LABEL "X, before" is drawn dashed in the colour of the LABEL "X")
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

out, radius = sys.argv[1], float(sys.argv[2])
fig, ax = plt.subplots(figsize=(6.5, 4.5))
colours = {}
for spec in sys.argv[3:]:
    label, path = spec.split("=", 1)
    rows = list(csv.DictReader(open(path)))
    r_over_h = [radius / float(r["h"]) for r in rows]
    its = [float(r["mean_stokes_its"]) for r in rows]
    # "X, before" is drawn dashed in the colour of "X".
    key = label.split(",")[0]
    colour = colours.setdefault(key, f"C{len(colours)}")
    style = "o--" if key != label else "o-"
    ax.semilogx(r_over_h, its, style, color=colour, label=label)
ax.set_xlabel("R / h (finest cells)")
ax.set_ylabel("mean FGMRES iterations per Stokes solve")
ax.set_ylim(bottom=0)
ax.grid(True, which="both", lw=0.3)
ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(out, dpi=120)
