#!/usr/bin/python3
"""Neck, closed-pore size and tr c against time for runs through changes
of topology: the histories FILE.levelN.csv of scripts/topology_history.py,
one curve per file, in three panels (the pore panel only shows runs that
had a closed pore; tr c solid at the neck where the run measures it,
dotted the largest anywhere).

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

figure, (neck_ax, pore_ax, trace_ax) = plt.subplots(1, 3, figsize=(15, 4.2))
colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
for k, entry in enumerate(args[1:]):
    label, path = entry.split("=", 1)
    rows = list(csv.DictReader(open(path)))
    t = [float(r["time"]) for r in rows]

    def series(name):
        return [float(r[name]) for r in rows]

    colour = colours[k % len(colours)]
    neck_ax.plot(t, series("neck_radius"), color=colour, label=label)
    size = series("open_porosity" if open_porosity else "closed_pore_size")
    if any(s > 0 for s in size):
        pore_ax.plot(t, size, color=colour, label=label)
    at_neck = series("neck_trace_c")
    if any(not math.isnan(v) for v in at_neck):
        trace_ax.plot(t, at_neck, color=colour, label=f"{label}, at the neck")
    largest = series("max_trace_c")
    if any(not math.isnan(v) for v in largest):
        trace_ax.plot(t, largest, color=colour, linestyle=":",
                      label=f"{label}, largest")

neck_ax.set_ylabel("smallest neck (half-width / radius)")
pore_ax.set_ylabel("open porosity" if open_porosity else
                   f"closed pores: {options['--size']} in the computed box")
trace_ax.set_ylabel("tr c")
trace_ax.set_yscale("log")
for ax in (neck_ax, pore_ax, trace_ax):
    ax.set_xlabel("t gamma / (eta_0 R)")
    ax.grid(True, alpha=0.3)
    if ax.get_legend_handles_labels()[0]:
        ax.legend(fontsize=7)
if options["--title"]:
    figure.suptitle(options["--title"])
figure.tight_layout()
figure.savefig(out, dpi=100)
