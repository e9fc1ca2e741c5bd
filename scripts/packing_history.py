#!/usr/bin/python3
"""History of a packing run: necks, density, shrinkage, pores, volume.

usage: packing_history.py RUN_DIR PARTICLES.csv --csv OUT.csv --png OUT.png
                          [--title TEXT]

RUN_DIR is a levelsinter output directory (metrics.csv, necks.csv);
PARTICLES.csv the scene's particle file (x, y, z, r rows; '#' lines are
comments), which gives each pair's R = 2 r_i r_j / (r_i + r_j). Per
metrics step the table has the neck x/R over the pairs with a neck (min,
mean, median, max, the fraction at or above 0.5), the contacts, the
relative density, the size ratios (shrinkage = 1 - ratio), the closed
pores, the sub-cell pockets and the volume change; the plot shows them
against time in four panels. Printed: the first step at which the mean
and the median x/R reach 0.5, if they do, and the first closed pore.
"""
import csv
import statistics
import sys
from collections import defaultdict

import matplotlib

import validation_data

matplotlib.use("Agg")
import matplotlib.pyplot as plt

args = sys.argv[1:]
options = {}
for name in ("--csv", "--png", "--title"):
    if name in args:
        i = args.index(name)
        options[name] = args[i + 1]
        del args[i:i + 2]
if len(args) != 2 or "--csv" not in options or "--png" not in options:
    sys.exit(__doc__)
run, particle_file = args

radii = []
for line in open(particle_file):
    line = line.strip()
    if not line or line.startswith("#"):
        continue
    values = line.split(",")
    try:
        radii.append(float(values[-1]))
    except ValueError:
        continue  # a header line

necks = defaultdict(list)
for row in csv.DictReader(open(f"{run}/necks.csv")):
    i, j = int(row["particle_i"]), int(row["particle_j"])
    radius = float(row["neck_radius"])
    if radius > 0:
        R = 2 * radii[i] * radii[j] / (radii[i] + radii[j])
        necks[int(row["step"])].append(radius / R)

metrics = list(csv.DictReader(open(f"{run}/metrics.csv")))
axes = [a for a in "xyz" if f"size_ratio_{a}" in metrics[0]]
columns = ["step", "time", "contacts", "neck_min_over_R", "neck_mean_over_R",
           "neck_median_over_R", "neck_max_over_R", "fraction_at_half",
           "relative_density"] + [f"size_ratio_{a}" for a in axes] + [
           "closed_pores", "sub_cell_pockets", "volume_change", "wall_time"]
table = []
for m in metrics:
    step = int(m["step"])
    x = sorted(necks.get(step, []))
    nan = float("nan")
    row = {"step": step, "time": float(m["time"]), "contacts": len(x),
           "neck_min_over_R": x[0] if x else nan,
           "neck_mean_over_R": statistics.fmean(x) if x else nan,
           "neck_median_over_R": statistics.median(x) if x else nan,
           "neck_max_over_R": x[-1] if x else nan,
           "fraction_at_half": sum(v >= 0.5 for v in x) / len(x) if x else nan}
    for c in columns[8:]:
        row[c] = float(m.get(c, "nan"))
    table.append(row)

validation_data.refuse_shorter(options["--csv"], table)
with open(options["--csv"], "w", newline="") as f:
    writer = csv.DictWriter(f, fieldnames=columns)
    writer.writeheader()
    for row in table:
        writer.writerow({k: (f"{v:.6g}" if isinstance(v, float) else v)
                         for k, v in row.items()})

for key in ("neck_mean_over_R", "neck_median_over_R"):
    reached = [r for r in table if r[key] >= 0.5]
    print(f"{key} >= 0.5: " + (f"step {reached[0]['step']}, t = "
                               f"{reached[0]['time']:.4g}" if reached else
                               f"not reached (last {table[-1][key]:.3f} at "
                               f"step {table[-1]['step']})"))
closed = [r for r in table if r["closed_pores"] > 0]
print("first closed pore: " + (f"step {closed[0]['step']}, t = "
                               f"{closed[0]['time']:.4g}" if closed else
                               "none"))
print(f"volume change at the end: {table[-1]['volume_change']:.3g}")

t = [r["time"] for r in table]
figure, panels = plt.subplots(2, 2, figsize=(10, 7), sharex=True)
ax = panels[0][0]
for key, label in (("neck_max_over_R", "max"), ("neck_median_over_R",
                   "median"), ("neck_mean_over_R", "mean"),
                   ("neck_min_over_R", "min")):
    ax.plot(t, [r[key] for r in table], label=label)
ax.axhline(0.5, color="grey", linestyle=":")
ax.set_ylabel("neck x / R over the contacts")
ax.legend()
ax = panels[0][1]
ax.plot(t, [r["relative_density"] for r in table])
ax.set_ylabel("relative density (control volume)")
ax = panels[1][0]
for a in axes:
    ax.plot(t, [r[f"size_ratio_{a}"] for r in table], label=a)
ax.set_ylabel("size ratio L / L0")
ax.legend()
ax.set_xlabel("time")
ax = panels[1][1]
ax.plot(t, [r["closed_pores"] for r in table], label="closed pores")
ax.set_ylabel("closed pores")
twin = ax.twinx()
twin.plot(t, [100 * r["volume_change"] for r in table], color="C3",
          label="volume change")
twin.set_ylabel("volume change (%)", color="C3")
ax.set_xlabel("time")
if "--title" in options:
    figure.suptitle(options["--title"])
figure.tight_layout()
figure.savefig(options["--png"], dpi=100)
