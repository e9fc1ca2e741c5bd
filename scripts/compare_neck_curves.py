#!/usr/bin/python3
"""Neck curves x/R(t*) of several runs compared at fixed t*, and fitted.

usage: compare_neck_curves.py --t-star T1,T2,... [--window LO,HI]
                              [--time t] [--last-largest]
                              LABEL=FILE.csv [...]

Each CSV is written by `surface_diffusion_validation neck ... --csv`
(columns t, t_star, neck_over_R). Prints, per run, x/R at each T (linear
interpolation in log x against log t*; '-' outside the run), the relative
difference to the previous run at each T, and the least-squares fit
x/R = A t*^(1/n) over the samples with LO <= x/R <= HI (default 0.05,
0.3: the Nichols-Mullins window). Samples with x = 0 (a neck that
closed) are left out. --time t reads the scene's time t instead of t*
(runs whose t* differ: surface, volume and coupled diffusion).
--last-largest: exit code 1 unless the last run's x/R exceeds every
other run's at every T (coupled diffusion against each mechanism alone).
"""
import csv
import math
import sys

args = sys.argv[1:]


def option(name, default):
    if name in args:
        i = args.index(name)
        value = args[i + 1]
        del args[i : i + 2]
        return [float(v) for v in value.split(",")]
    return default


t_stars = option("--t-star", None)
lo, hi = option("--window", [0.05, 0.3])
time = "t_star"
if "--time" in args:
    i = args.index("--time")
    time = args[i + 1]
    del args[i : i + 2]
last_largest = "--last-largest" in args
if last_largest:
    args.remove("--last-largest")
if t_stars is None or not args:
    sys.exit(__doc__)


def at(t, x, t_star):
    for i in range(1, len(t)):
        if t[i - 1] <= t_star <= t[i]:
            s = (math.log(t_star) - math.log(t[i - 1])) / (
                math.log(t[i]) - math.log(t[i - 1]))
            return math.exp((1 - s) * math.log(x[i - 1]) + s * math.log(x[i]))
    return None


def fit(t, x):
    pts = [(math.log(a), math.log(b)) for a, b in zip(t, x) if lo <= b <= hi]
    if len(pts) < 2:
        return None
    m = len(pts)
    mx = sum(p[0] for p in pts) / m
    my = sum(p[1] for p in pts) / m
    slope = sum((p[0] - mx) * (p[1] - my) for p in pts) / sum(
        (p[0] - mx) ** 2 for p in pts)
    return math.exp(my - slope * mx), 1 / slope, m, min(
        math.exp(p[1]) for p in pts), max(math.exp(p[1]) for p in pts)


def show(v, digits):
    return "-" if v is None else f"{v:.{digits}g}"


print(("t*" if time == "t_star" else time) + ": " +
      " / ".join(f"{v:g}" for v in t_stars))
previous = None
runs = []
for item in args:
    label, path = item.rsplit("=", 1)
    # t* = 0 and a closed neck (x = 0) have no logarithm.
    rows = [r for r in csv.DictReader(open(path))
            if float(r[time]) > 0 and float(r["neck_over_R"]) > 0]
    t = [float(r[time]) for r in rows]
    x = [float(r["neck_over_R"]) for r in rows]
    values = [at(t, x, v) for v in t_stars]
    line = f"{label}: x/R " + " / ".join(show(v, 3) for v in values)
    if previous is not None:
        diffs = [None if a is None or b is None else 100 * (a - b) / b
                 for a, b in zip(values, previous)]
        line += "; vs previous (%) " + " / ".join(show(d, 2) for d in diffs)
    f = fit(t, x)
    if f is not None:
        line += (f"; fit {lo:g} <= x/R <= {hi:g}: A = {f[0]:.3g}, "
                 f"n = {f[1]:.3g} ({f[2]} samples, x/R {f[3]:.3g}-{f[4]:.3g})")
    print(line)
    previous = values
    runs.append((label, values))

if last_largest:
    label, last = runs[-1]
    failed = [(other, t_stars[i])
              for other, values in runs[:-1]
              for i, v in enumerate(values)
              if last[i] is None or v is None or not last[i] > v]
    for other, t_star in failed:
        print(f"FAILED: {label} is not above {other} at {t_star:g}")
    if failed:
        sys.exit(1)
    print(f"{label} is above every other run at every time")
