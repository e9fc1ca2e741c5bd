#!/usr/bin/python3
"""Largest stable time step of the surface-diffusion scheme, by bisection.

usage: largest_stable_step.py DRIVER SCENE.prm --levels 3,4,5 --csv OUT.csv
                              [--coupled 0|1] [--steps 20] [--ratio 1.2]
                              [--start DT] [--max-dt DT]
                              [--rate S --scheme NAME] [driver options]

DRIVER is tests/surface_diffusion_validation, SCENE a Mullins scene in
reduced time (parameter_files/perturbed_circle_2d.prm). --rate S is the
mode's decay rate in that reduced time, which the driver's time fraction
is measured in (default: surface diffusion's n^2 (n^2 - 1) in 2D; volume
diffusion of an elastic cylinder: (2/3)(1 + nu) n (n^2 - 1)); --scheme
names the scheme in the CSV and the output (default: mixed or decoupled
after --coupled). For each maximum
refinement level the script runs `DRIVER mullins SCENE LEVEL STEPS` for
STEPS steps of a given dt (through --time-fraction) and calls the step
stable when the isoperimetric ratio L^2 / A (interface length L, area
A) never grows by more than 1e-3 of its start, the mode amplitude never
grows above 1.01 times its start, and the rate is a number (the run's
metrics.csv and the driver's max_amplitude_ratio and rate columns; a
failed solve counts as unstable). Surface diffusion is the gradient flow
of the length at fixed area, so L^2 / A can only fall; unlike L alone it
does not move when the scheme's area drift dilates the shape. The
amplitude alone misses grid-scale growth: one run whose length grew from
1.57 to 3.9 in two steps moved it by 0.7 %. It brackets the limit by
factors of 10 from --start (default 1e-4), then bisects in log(dt) until
the unstable / stable ratio is below --ratio. A scheme still stable at
--max-dt (default 10) is reported with that dt as its stable bound and
no unstable one. Every run is a row of OUT.csv (the driver's columns, the
scheme and a `stable` column); the last lines printed are the brackets.
Further options (--mode, --set ...) go to the driver.
"""
import argparse
import csv
import math
import os
import subprocess
import tempfile

parser = argparse.ArgumentParser(usage=__doc__, allow_abbrev=False)
parser.add_argument("driver")
parser.add_argument("scene")
parser.add_argument("--levels", default="4,5")
parser.add_argument("--csv", required=True)
parser.add_argument("--coupled", default="1")
parser.add_argument("--steps", type=int, default=20)
parser.add_argument("--ratio", type=float, default=1.2)
parser.add_argument("--start", type=float, default=1e-4)
parser.add_argument("--max-dt", type=float, default=10)
parser.add_argument("--rate", type=float)
parser.add_argument("--scheme")
options, extra = parser.parse_known_args()
levels = [int(x) for x in options.levels.split(",")]
steps, coupled = options.steps, options.coupled
mode = int(extra[extra.index("--mode") + 1]) if "--mode" in extra else 2
exact_rate = options.rate or mode * mode * (mode * mode - 1.0)  # 2D
scheme = options.scheme or ("mixed" if coupled == "1" else "decoupled")

rows, brackets = [], []  # every trial; (level, stable, unstable)


def run(level, dt):
    """One trial of STEPS steps of dt, recorded in --csv; True if stable."""
    with tempfile.TemporaryDirectory() as tmp:
        table = os.path.join(tmp, "run.csv")
        fraction = steps * dt * exact_rate
        command = [os.path.abspath(options.driver), "mullins",
                   os.path.abspath(options.scene), str(level), str(steps),
                   "--time-fraction", repr(fraction), "--coupled", coupled,
                   "--csv", table] + extra
        subprocess.run(command, cwd=tmp, stdout=subprocess.DEVNULL,
                       stderr=subprocess.DEVNULL)
        with open(table) as f:
            row = list(csv.DictReader(f))[-1]
        (output,) = os.listdir(os.path.join(tmp, "validation_output"))
        with open(os.path.join(tmp, "validation_output", output,
                               "metrics.csv")) as f:
            shape = [float(r["interface_area"]) ** 2 / float(r["solid_volume"])
                     for r in csv.DictReader(f)]
    amplitude = float(row["max_amplitude_ratio"])
    isoperimetric = max(shape) / shape[0]
    stable = (isoperimetric <= 1 + 1e-3 and amplitude <= 1.01
              and not math.isnan(float(row["rate"])))
    row.update(scheme=scheme, max_isoperimetric_ratio=isoperimetric,
               stable=int(stable))
    # Written after every trial, so that a stopped study keeps its rows.
    with open(options.csv, "a" if rows else "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(row.keys()))
        if not rows:
            writer.writeheader()
        writer.writerow(row)
    rows.append(row)
    print(f"{scheme} level {level} dt {dt:.4g}: L^2/A ratio "
          f"{isoperimetric:.4g}, "
          f"amplitude ratio {amplitude:.4g}, "
          f"{'stable' if stable else 'unstable'}", flush=True)
    return stable


for level in levels:
    lo, hi = None, None  # largest stable, smallest unstable dt
    dt = options.start
    while lo is None or hi is None:
        if run(level, dt):
            lo = dt
            if dt >= options.max_dt:
                break
            dt = min(10 * dt, options.max_dt)
        else:
            hi = dt
            dt /= 10
    while hi is not None and hi / lo > options.ratio:
        dt = math.sqrt(lo * hi)
        if run(level, dt):
            lo = dt
        else:
            hi = dt
    brackets.append((level, lo, hi))

for level, lo, hi in brackets:
    print(f"{scheme} level {level}: stable dt* {lo:.4g}, unstable "
          f"{'-' if hi is None else f'{hi:.4g}'}")
