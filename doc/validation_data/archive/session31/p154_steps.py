#!/usr/bin/env python3
"""The 154 coupled packing with the limited extension, resumed in session
31 from session 30's checkpoint: time, step and largest speed against the
step number, from session 30's progress lines
(../session30/p154_lim_progress.txt) and this session's
(p154_lim_resumed_progress.txt), and the metrics every 5 steps
(p154_lim_metrics.csv). Prints Markdown tables. Run in this folder."""
import csv
import re

steps = {}
for path in ["../session30/p154_lim_progress.txt",
             "p154_lim_resumed_progress.txt"]:
    for line in open(path):
        m = re.match(r"step\s+(\d+)\s+t =\s+(\S+) / \S+\s+dt =\s+(\S+)", line)
        if m:
            steps[int(m.group(1))] = (float(m.group(2)), float(m.group(3)))
print("| steps | t at the last (s) | mean step (s) | shortest / longest "
      "step (s) |")
print("|---|---|---|---|")
numbers = sorted(steps)
for first in range(1, numbers[-1], 10):
    last = min(first + 9, numbers[-1])
    block = [steps[k][1] for k in range(first, last + 1) if k in steps]
    print(f"| {first}-{last} | {steps[last][0]:.5f} | "
          f"{sum(block) / len(block):.2e} | {min(block):.2e} / "
          f"{max(block):.2e} |")
print("\n| step | t (s) | level-set DoFs | relative density | mean neck (um) "
      "| closed pores | volume change | largest speed (um/s) | interface "
      "cells without a xi source |")
print("|---|---|---|---|---|---|---|---|---|")
for row in csv.DictReader(open("p154_lim_metrics.csv")):
    print(f"| {row['step']} | {float(row['time']):.5f} | {row['dofs']} | "
          f"{float(row['relative_density']):.5f} | "
          f"{float(row['neck_mean']):.5f} | {row['closed_pores']} | "
          f"{float(row['volume_change']):.1e} | "
          f"{float(row['max_velocity']):.1f} | "
          f"{row['volume_diffusion_unsourced_cells']} |")
