"""Neck against time for the two-particle viscous studies
(viscous_validation hopper|spheres ... --csv FILE writes FILE.levelN.csv with
the columns time, neck, reference): one curve per level and the reference
(Hopper's exact solution, or Frenkel-Eshelby's early law for the spheres).
Usage: plot_hopper_neck.py OUT.png [--loglog] [LABEL=]FILE.level4.csv ...
(the label defaults to the level part of the file name)."""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

LABELS = {
    "t_gamma_over_eta_R": "t gamma / (eta R)",
    "neck_over_R": "neck half-width / R",
    "exact_neck_over_R": "Hopper (exact)",
    "t_gamma_over_eta_a": "t gamma / (eta a), from touching",
    "neck_over_a": "neck radius / a",
    "frenkel_eshelby": "Frenkel-Eshelby (3 t gamma / (2 eta a))^1/2",
}

files = [a for a in sys.argv[2:] if a != "--loglog"]
fig, ax = plt.subplots(figsize=(6, 4))
for argument in files:
    label, _, name = argument.rpartition("=")
    reader = csv.reader(open(name))
    columns = next(reader)
    rows = [[float(v) for v in r] for r in reader]
    t = [r[0] for r in rows]
    ax.plot(t, [r[1] for r in rows], label=label or name.rsplit(".", 2)[-2])
    reference = [r[2] for r in rows]
ax.plot(t, reference, "k--", label=LABELS[columns[2]])
if "--loglog" in sys.argv:
    ax.set_xscale("log")
    ax.set_yscale("log")
ax.set_xlabel(LABELS[columns[0]])
ax.set_ylabel(LABELS[columns[1]])
if len(files) > 4:
    # Many curves fill the axes: the legend goes to their right.
    fig.set_size_inches(9, 4)
    ax.legend(fontsize="small", loc="upper left", bbox_to_anchor=(1.02, 1))
else:
    ax.legend()
ax.grid(alpha=0.3, which="both")
fig.tight_layout()
fig.savefig(sys.argv[1], dpi=110)
