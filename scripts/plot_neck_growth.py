#!/usr/bin/python3
"""Neck growth x/R against reduced time t* in log-log scales.

usage: plot_neck_growth.py OUT.png [--law A,n ...] [--xlabel TEXT]
                           LABEL=FILE.csv [...]

Each CSV is written by `surface_diffusion_validation neck ... --csv`
(columns t_star, neck_over_R; R is the equivalent radius 2 R1 R2/(R1+R2)).
--law A,n adds the power law x/R = A t*^(1/n) as a dashed line, e.g. the
paper's fit 1.3,7 (Fig. 26). --xlabel names the reduced time when it is
not C_s t / R^4 (the driver uses C_v gamma t / R^3 with volume diffusion).
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

args = sys.argv[1:]
laws = []
while "--law" in args:
    i = args.index("--law")
    laws.append([float(v) for v in args[i + 1].split(",")])
    del args[i : i + 2]
xlabel = "t* = C_s t / R^4"
if "--xlabel" in args:
    i = args.index("--xlabel")
    xlabel = args[i + 1]
    del args[i : i + 2]
if len(args) < 2:
    sys.exit(__doc__)

fig, ax = plt.subplots(figsize=(6.5, 4.5))
t_all = []
for item in args[1:]:
    label, path = item.rsplit("=", 1)
    rows = [r for r in csv.DictReader(open(path)) if float(r["t_star"]) > 0]
    t = [float(r["t_star"]) for r in rows]
    t_all += t
    ax.loglog(t, [float(r["neck_over_R"]) for r in rows], "-", label=label)
for a, n in laws:
    t = [min(t_all), max(t_all)]
    ax.loglog(t, [a * v ** (1 / n) for v in t], "k--", lw=1,
              label=f"x/R = {a:g} t*^(1/{n:g})")
ax.set_xlabel(xlabel)
ax.set_ylabel("x / R")
ax.grid(True, which="both", alpha=0.3)
ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(args[0], dpi=120)
