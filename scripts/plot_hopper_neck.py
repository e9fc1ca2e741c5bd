"""Neck half-width against time for the Hopper study (viscous_validation
hopper ... --csv FILE writes FILE.levelN.csv): one curve per level and the
exact solution. Usage: plot_hopper_neck.py OUT.png [LABEL=]FILE.level4.csv ...
(the label defaults to the level part of the file name)."""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

fig, ax = plt.subplots(figsize=(6, 4))
for argument in sys.argv[2:]:
    label, _, name = argument.rpartition("=")
    rows = list(csv.DictReader(open(name)))
    t = [float(r["t_gamma_over_eta_R"]) for r in rows]
    ax.plot(t, [float(r["neck_over_R"]) for r in rows], "o-", markersize=3,
            label=label or name.rsplit(".", 2)[-2])
    exact = [float(r["exact_neck_over_R"]) for r in rows]
ax.plot(t, exact, "k--", label="Hopper (exact)")
ax.set_xlabel("t gamma / (eta R)")
ax.set_ylabel("neck half-width / R")
ax.legend()
ax.grid(alpha=0.3)
fig.tight_layout()
fig.savefig(sys.argv[1], dpi=110)
