#!/usr/bin/python3
"""Plot the Stokes neck speed on Hopper's exact shape against the finest
cell size, one line per initial neck
(doc/validation_data/archive/hopper_neck_speed.csv).

usage: plot_neck_speed.py hopper_neck_speed.csv OUT.png
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

rows = list(csv.DictReader(open(sys.argv[1])))
fig, ax = plt.subplots(figsize=(6, 4.5))
for y in sorted({r["y0_over_R"] for r in rows}, key=float):
    sel = [r for r in rows if r["y0_over_R"] == y]
    h = [float(r["h_min_over_R"]) for r in sel]
    ratio = [1 + float(r["initial_neck_speed_error"]) for r in sel]
    line, = ax.semilogx(h, ratio, "o-", label=f"y_n = {y} R")
    # The neck meniscus radius y_n^2 / (2R): the cell size below which the
    # capillary pull at the neck is resolved.
    ax.axvline(float(y) ** 2 / 2, color=line.get_color(), ls=":", lw=1)
ax.axhline(1, color="k", lw=0.8)
ax.invert_xaxis()
ax.set_xlabel("finest cell h_min / R (dotted: meniscus radius y_n^2 / 2R)")
ax.set_ylabel("neck speed / Hopper's dy_n/dt")
ax.set_title("Stokes solution on Hopper's exact shape, R/h = 20 + k levels")
ax.legend()
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=120)
