#!/usr/bin/python3
"""Merge the rows of performance_study runs, plot the cost per step against
the particle count and project it (doc/performance.md).

usage: plot_performance.py --csv OUT.csv --png OUT.png RUN.csv [RUN.csv ...]

Input files that do not exist (runs not made) are skipped. The 2-rank
runs give the curve: CPU and wall seconds per step against N, and the
projection linear in the DoFs from the largest run. Printed: the
least-squares power law c N^b of the CPU time,
the 1 -> 2 rank speed-up where a particle count has both, and the
projection of the CPU time to the paper's 550 steps and to 1 000 and
10 000 particles (the same DoFs per particle and steps per neck growth).
"""
import csv
import math
import os
import sys

import matplotlib

import validation_data

matplotlib.use("Agg")
import matplotlib.pyplot as plt

args = sys.argv[1:]
out_csv = args[args.index("--csv") + 1]
out_png = args[args.index("--png") + 1]
inputs = [a for i, a in enumerate(args)
          if a not in ("--csv", "--png") and args[i - 1] not in ("--csv", "--png")]

rows = []
for path in inputs:
    # A run that was not made (a long one skipped) is reported, not fatal.
    if not os.path.exists(path):
        print(f"not run: {path}")
        continue
    rows += list(csv.DictReader(open(path)))
columns = list(rows[0].keys())
rows.sort(key=lambda r: (float(r["particles"]), float(r["ranks"])))
validation_data.refuse_shorter(out_csv, rows)
with open(out_csv, "w", newline="") as f:
    writer = csv.DictWriter(f, fieldnames=columns)
    writer.writeheader()
    writer.writerows(rows)

two = [r for r in rows if float(r["ranks"]) == 2]
n = [float(r["particles"]) for r in two]
cpu = [float(r["cpu_per_step"]) for r in two]
wall = [float(r["wall_per_step"]) for r in two]

# Least squares of log cpu = log c + b log N.
lx = [math.log(x) for x in n]
ly = [math.log(y) for y in cpu]
m = len(lx)
b = (m * sum(x * y for x, y in zip(lx, ly)) - sum(lx) * sum(ly)) / (
    m * sum(x * x for x in lx) - sum(lx) ** 2)
c = math.exp((sum(ly) - b * sum(lx)) / m)
print(f"CPU per step (2 ranks, summed over both) = {c:.4g} N^{b:.3f}")
for count in sorted(set(float(r["particles"]) for r in rows)):
    runs = {float(r["ranks"]): r for r in rows
            if float(r["particles"]) == count}
    if 1 in runs and 2 in runs:
        speedup = (float(runs[1]["wall_per_step"]) /
                   float(runs[2]["wall_per_step"]))
        cpu_ratio = (float(runs[2]["cpu_per_step"]) /
                     float(runs[1]["cpu_per_step"]))
        print(f"N = {count:.0f}: wall speed-up 1 -> 2 ranks {speedup:.2f}, "
              f"CPU(2 ranks) / CPU(1 rank) {cpu_ratio:.2f}, load "
              f"{runs[1]['load']} / {runs[2]['load']}")
for count in (154, 1000, 10000):
    per_step = c * count ** b
    print(f"N = {count}: {per_step:.4g} CPU s per step, 550 steps "
          f"{550 * per_step / 3600:.4g} CPU h (power law)")
# Linear in the DoFs (the solvers' work per DoF and step held fixed): the
# CPU per DoF and step and the DoFs per particle of the largest run, and
# the CPU per DoF and step of every run for comparison.
for r in rows:
    print(f"N = {float(r['particles']):.0f}, {float(r['ranks']):.0f} rank(s): "
          f"{float(r['cpu_per_step']) / float(r['dofs']):.3g} CPU s per DoF "
          f"and step, {float(r['dofs_per_particle']):.0f} DoFs per particle")
largest = two[-1]
per_dof = float(largest["cpu_per_step"]) / float(largest["dofs"])
per_particle = float(largest["dofs_per_particle"])
for count in (154, 1000, 10000):
    per_step = per_dof * per_particle * count
    print(f"N = {count}: {per_particle * count:.3g} DoFs, {per_step:.4g} "
          f"CPU s per step, 550 steps {550 * per_step / 3600:.4g} CPU h "
          f"(linear in the DoFs of N = {float(largest['particles']):.0f})")

fig, ax = plt.subplots(figsize=(6.5, 4.5))
ax.loglog(n, cpu, "o", label="CPU s per step (both ranks)")
ax.loglog(n, wall, "s", label="wall s per step")
grid = [8 * (10000 / 8) ** (k / 50) for k in range(51)]
ax.loglog(grid, [per_dof * per_particle * x for x in grid], "-", color="C0",
          label=f"CPU linear in the DoFs of N = "
          f"{float(largest['particles']):.0f}")
ax.set_xlabel("particles N (h_min = 0.0094 um, 2 MPI ranks)")
ax.set_ylabel("seconds per step")
ax.grid(True, which="both", alpha=0.3)
ax.legend()
fig.tight_layout()
fig.savefig(out_png, dpi=120)
