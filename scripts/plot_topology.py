#!/usr/bin/python3
"""Neck, closed-pore size and tr c against time for runs through changes
of topology: the histories FILE.levelN.csv of scripts/topology_history.py,
one curve per file, in three panels (the pore panel only shows runs that
had a closed pore, and is left out if none had; tr c solid at the neck
where the run measures it, dotted the largest anywhere).

usage: plot_topology.py OUT.png [--title TEXT] [--size area|volume]
                        [--open-porosity]
                        LABEL=FILE.levelN.csv [LABEL=FILE.levelN.csv ...]

--open-porosity: the middle panel shows the open porosity instead (a
packing whose pore space stays open).
"""
import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

args = sys.argv[1:]
open_porosity = "--open-porosity" in args
if open_porosity:
    args.remove("--open-porosity")
options = {"--title": None, "--size": "area"}
for name in options:
    if name in args:
        i = args.index(name)
        options[name] = args[i + 1]
        del args[i:i + 2]
if len(args) < 2 or any("=" not in a for a in args[1:]):
    sys.exit(__doc__)
out = args[0]

runs = []
for entry in args[1:]:
    label, path = entry.split("=", 1)
    rows = list(csv.DictReader(open(path)))
    runs.append((label, {name: [float(r[name]) for r in rows]
                         for name in rows[0]}))
pore_name = "open_porosity" if open_porosity else "closed_pore_size"
# Without any pore (a pair) the middle panel is left out.
with_pores = any(any(v > 0 for v in run[pore_name]) for _, run in runs)
figure, axes = plt.subplots(1, 3 if with_pores else 2,
                            figsize=(15 if with_pores else 10, 4.2))
neck_ax, trace_ax = axes[0], axes[-1]
pore_ax = axes[1] if with_pores else None
colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
for k, (label, run) in enumerate(runs):
    colour = colours[k % len(colours)]
    t = run["time"]
    neck_ax.plot(t, run["neck_radius"], color=colour, label=label)
    if with_pores and any(v > 0 for v in run[pore_name]):
        pore_ax.plot(t, run[pore_name], color=colour, label=label)
    if any(not math.isnan(v) for v in run["neck_trace_c"]):
        trace_ax.plot(t, run["neck_trace_c"], color=colour,
                      label=f"{label}, at the neck")
    if any(not math.isnan(v) for v in run["max_trace_c"]):
        trace_ax.plot(t, run["max_trace_c"], color=colour, linestyle=":",
                      label=f"{label}, largest")

neck_ax.set_ylabel("smallest neck (half-width / radius)")
if with_pores:
    pore_ax.set_ylabel("open porosity" if open_porosity else
                       f"closed pores: {options['--size']} in the computed "
                       "box")
trace_ax.set_ylabel("tr c")
trace_ax.set_yscale("log")
for ax in axes:
    ax.set_xlabel("t gamma / (eta_0 R)")
    ax.grid(True, alpha=0.3)
    if ax.get_legend_handles_labels()[0]:
        ax.legend(fontsize=7)
if options["--title"]:
    figure.suptitle(options["--title"])
figure.tight_layout()
figure.savefig(out, dpi=100)
