#!/usr/bin/python3
"""The central pore of pore_cubic_coupled_3d.prm at 2 h, h and h / 2 and at
h with other steps (study packing_first_closure_cubic): relative density
of the control volume [0, R]^3 against time, the first closed pore
marked. Reads pore_cubic_<case>_metrics.csv and _pore_events.csv (the
study's runs, copied here); writes pore_cubic_density.png.

  pore_cubic_plot.py
"""
import csv
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

HERE = os.path.dirname(os.path.abspath(__file__))
CASES = [("2h", "2 h (R/h = 4)", "tab:gray", "-"),
         ("h", "h (R/h = 8, the scene)", "tab:blue", "-"),
         ("h_dt5e-4", "h, dt <= 5e-4 s", "tab:blue", "--"),
         ("h_cfl075", "h, CFL 0.75", "tab:blue", ":"),
         ("h2", "h / 2 (R/h = 16)", "tab:red", "-")]

fig, ax = plt.subplots(figsize=(7, 4.5))
for case, label, colour, style in CASES:
    rows = list(csv.DictReader(open(
        os.path.join(HERE, f"pore_cubic_{case}_metrics.csv"))))
    t = [float(r["time"]) for r in rows]
    rho = [float(r["relative_density"]) for r in rows]
    ax.plot(t, rho, color=colour, linestyle=style, label=label)
    events = list(csv.DictReader(open(
        os.path.join(HERE, f"pore_cubic_{case}_pore_events.csv"))))
    closed = [float(e["time"]) for e in events
              if e["event"] == "closed" and int(e["step"]) > 0]
    if closed:
        tc = closed[0]
        k = min(range(len(t)), key=lambda i: abs(t[i] - tc))
        ax.plot([tc], [rho[k]], "o", color=colour, markerfacecolor="none")
ax.set_xlabel("t (s)")
ax.set_ylabel("relative density of [0, R]^3")
ax.set_title("central pore of 8 tangent spheres; o: first closed pore")
ax.legend(loc="upper left", fontsize=8)
ax.grid(alpha=0.3)
fig.tight_layout()
fig.savefig(os.path.join(HERE, "pore_cubic_density.png"),
            dpi=110)
