#!/usr/bin/env python3
"""The volume per grain of the 27-grain packing, stage by stage (doc/
validation.md, "Volume per grain"): reads the metrics.csv of runs of
parameter_files/grains_packing_27_3d.prm and writes one CSV row per run and
metrics row (time, grain_volume_change_max, volume_change,
grain_relative_density).

  grain_volume_stages.py OUT.csv MEASURE:NAME:RUN_DIRECTORY...

MEASURE names how the run's levelsinter measured the grain volumes (owner:
each quadrature point to the grain whose power cell holds it, before
3c758f8; ramp: grain_geometry::grain_volumes). The runs, each with
--set "Output/Field interval=0" and, but for the last two, --set
"Time/End time=1.2":
  all        the scene as it is
  no_gb      --set "Grain boundaries/Coefficient=1e-14" (rigid grains at rest)
  no_vc      --set "Volume correction/Enabled=false"
  no_gb_vc   both
  still      --set "Grain boundaries/Coefficient=1e-14"
             --set "Surface diffusion/Coefficient=1e-14" (nothing moves:
             reinitialisation, adaptation and volume correction only)
  conserve_t3, plain_t3: to t = 3, --set "Grain boundaries/Conserve grain
             volumes=true" or false.
"""
import csv
import sys

out, runs = sys.argv[1], sys.argv[2:]
with open(out, "w", newline="") as f:
    writer = csv.writer(f)
    writer.writerow(["measure", "run", "time", "grain_volume_change_max",
                     "volume_change", "grain_relative_density"])
    for spec in runs:
        measure, name, directory = spec.split(":", 2)
        with open(directory + "/metrics.csv") as m:
            for row in csv.DictReader(m):
                writer.writerow([measure, name, row["time"],
                                 row["grain_volume_change_max"],
                                 row["volume_change"],
                                 row["grain_relative_density"]])
