#!/usr/bin/python3
"""History of runs through changes of topology: necks, closed pores, area or
volume, tr c, cost (doc/validation.md, "Viscoelastic melts past topology
change and in a 3D packing").

usage: topology_history.py --csv OUT.csv [--times T1,T2,...]
                           [--min NAME=VALUE] [--max NAME=VALUE]
                           LEVEL=RUN_DIR [LEVEL=RUN_DIR ...]

RUN_DIR is a levelsinter output directory (metrics.csv, pore_events.csv);
RUN_DIR.log, if present, is the run's standard output (tests/logged_run
.cmake writes it): the rejected steps ("... failed; retrying") and the
time per phase (the timer table at the end) come from there. For each run
OUT.csv.levelLEVEL.csv gets the history, one row per metrics step: time,
dt, neck_radius (the smallest neck over the pairs), neck_max, closed
pores and their area (2D) or volume (3D) in the computed box, the open
porosity (of the control volume), the solid's relative change, the largest tr c and tr c at the neck (NaN where the
scene has none). OUT.csv gets one row per run: steps, rejected steps,
wall time, the smallest neck, the closed pores' size and the open
porosity at the times of --times (interpolated), the closed pores' initial size, when they fell
below 10 % and 1 % of it (pore_below_F_time), when the first pore closed
(`closed` event after t = 0; NaN if none) and when the last one vanished
(`vanished` with no closed pore left after it; NaN if one is left or there
was none), the largest |relative solid change| and the last, the largest
tr c anywhere and at the neck, the mean Stokes iterations and the wall
time per step of each timer phase (phase_NAME). --min/--max NAME=VALUE
check a column of the last run's row (exit code 1 if one fails; a NaN
fails).
"""
import csv
import math
import os
import re
import sys

import validation_data


def arguments(argv):
    options = {"--csv": None, "--times": "0.01,0.05,0.1,0.2,0.5,1"}
    limits, runs = [], []
    i = 0
    while i < len(argv):
        if argv[i] in options:
            options[argv[i]] = argv[i + 1]
            i += 2
        elif argv[i] in ("--min", "--max"):
            name, value = argv[i + 1].split("=")
            limits.append((argv[i], name, float(value)))
            i += 2
        elif "=" in argv[i]:
            level, directory = argv[i].split("=", 1)
            runs.append((level, directory))
            i += 1
        else:
            sys.exit(__doc__)
    if options["--csv"] is None or not runs:
        sys.exit(__doc__)
    times = [float(t) for t in options["--times"].split(",")]
    return options["--csv"], times, limits, runs


def column(rows, name):
    nan = float("nan")
    return [float(r[name]) if name in r and r[name] != "" else nan
            for r in rows]


def value_at(t, y, time):
    """y at time, linear between the rows around it; NaN outside."""
    for i in range(1, len(t)):
        if t[i - 1] < time <= t[i]:
            s = (time - t[i - 1]) / (t[i] - t[i - 1])
            return (1 - s) * y[i - 1] + s * y[i]
    return float("nan")


def first_below(t, y, level):
    """The first time y falls below level (linear between rows); NaN if
    it never does or starts there."""
    for i in range(1, len(t)):
        if y[i - 1] >= level > y[i]:
            s = (y[i - 1] - level) / (y[i - 1] - y[i])
            return t[i - 1] + s * (t[i] - t[i - 1])
    return float("nan")


def nan_max(values):
    finite = [v for v in values if not math.isnan(v)]
    return max(finite) if finite else float("nan")


def log_measures(path):
    """Rejected steps and the wall time of each timer phase from the log."""
    if not os.path.exists(path):
        return float("nan"), {}
    rejected, phases = 0, {}
    for line in open(path):
        if "failed; retrying" in line:
            rejected += 1
        fields = [f.strip() for f in line.split("|")]
        # | name | calls | min time  rank | avg time | max time  rank |
        if len(fields) == 7 and re.fullmatch(r"\d+", fields[2]):
            average = fields[4]
            if average.endswith("s"):
                name = re.sub(r"[^A-Za-z0-9]+", "_", fields[1]).strip("_")
                phases[name] = float(average[:-1])
    return rejected, phases


def history(level, directory, csv_name, times):
    rows = list(csv.DictReader(open(os.path.join(directory, "metrics.csv"))))
    t = column(rows, "time")
    # The packing analysis' smallest neck skips pairs without one (pairs
    # across a symmetry plane from each other's images); neck_radius,
    # the smallest over all listed pairs, counts them as 0.
    neck = "neck_min" if "neck_min" in rows[0] else "neck_radius"
    series = {
        "time": t,
        "dt": column(rows, "dt"),
        "neck_radius": column(rows, neck),
        "neck_max": column(rows, "neck_max"),
        "closed_pores": column(rows, "closed_pores"),
        "closed_pore_size": column(rows, "closed_pore_volume"),
        "open_porosity": column(rows, "open_porosity"),
        "volume_change": column(rows, "volume_change"),
        "max_trace_c": column(rows, "viscoelastic_max_trace_c"),
        "neck_trace_c": column(rows, "neck_viscoelastic_trace_c"),
    }
    validation_data.refuse_shorter(f"{csv_name}.level{level}.csv", len(t))
    with open(f"{csv_name}.level{level}.csv", "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(series.keys())
        for i in range(len(t)):
            writer.writerow([f"{series[k][i]:.8g}" for k in series])

    events = list(csv.DictReader(open(os.path.join(directory,
                                                   "pore_events.csv"))))
    closed = [float(e["time"]) for e in events
              if e["event"] == "closed" and float(e["time"]) > 0]
    vanished = [float(e["time"]) for e in events if e["event"] == "vanished"]
    pores = series["closed_pores"]
    nan = float("nan")
    summary = {"level": level, "steps": int(float(rows[-1]["step"])),
               "end_time": t[-1]}
    summary["rejected"], phases = log_measures(directory + ".log")
    summary["wall_time"] = float(rows[-1]["wall_time"])
    for time in times:
        summary[f"neck_t{time:g}"] = value_at(t, series["neck_radius"], time)
    summary["initial_closed_pore_size"] = series["closed_pore_size"][0]
    for time in times:
        summary[f"pore_t{time:g}"] = value_at(t, series["closed_pore_size"],
                                              time)
    for time in times:
        summary[f"open_porosity_t{time:g}"] = value_at(
            t, series["open_porosity"], time)
    # The closure time by a threshold fixed in size: the first time the
    # closed pores are below a fraction of their initial size (vanished
    # means below one finest cell, a threshold that moves with h).
    size = series["closed_pore_size"]
    for fraction in (0.1, 0.01):
        summary[f"pore_below_{fraction:g}_time"] = first_below(
            t, size, fraction * size[0])
    summary["first_closed_time"] = closed[0] if closed else nan
    summary["vanished_time"] = (vanished[-1] if vanished and pores[-1] == 0
                                else nan)
    summary["max_abs_volume_change"] = nan_max(
        [abs(v) for v in series["volume_change"]])
    summary["final_volume_change"] = series["volume_change"][-1]
    summary["max_trace_c"] = nan_max(series["max_trace_c"])
    summary["max_neck_trace_c"] = nan_max(series["neck_trace_c"])
    its = column(rows[1:], "stokes_iterations")
    summary["mean_stokes_its"] = sum(its) / len(its) if its else nan
    steps = max(summary["steps"], 1)
    for name, seconds in phases.items():
        summary[f"phase_{name}"] = seconds / steps
    return summary


def main():
    csv_name, times, limits, runs = arguments(sys.argv[1:])
    table = [history(level, d, csv_name, times) for level, d in runs]
    columns = []
    for row in table:
        columns += [c for c in row if c not in columns]
    validation_data.refuse_shorter(csv_name, table)
    with open(csv_name, "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(columns)
        for row in table:
            writer.writerow([f"{row[c]:.6g}" if isinstance(row.get(c), float)
                             else row.get(c, "nan") for c in columns])
    for row in table:
        print(", ".join(f"{c} = {row[c]:.6g}" if isinstance(row[c], float)
                        else f"{c} = {row[c]}" for c in row))
    failures = 0
    for kind, name, limit in limits:
        value = float(table[-1].get(name, float("nan")))
        passed = value >= limit if kind == "--min" else value <= limit
        print(f"{'PASS' if passed else 'FAIL'}: {name} = {value:.6g} "
              f"({'>=' if kind == '--min' else '<='} {limit:g})")
        failures += not passed
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
