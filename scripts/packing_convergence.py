#!/usr/bin/env python3
"""How far a packing's results move with the resolution and the step.

    packing_convergence.py LEVELSINTER SCENE.prm --work DIR --csv OUT.csv
        --end-time T --times t1,t2,... --case NAME[:ENTRY=VALUE;...] ...
        [--reference NAME] [--ranks N] [--set ENTRY=VALUE ...]
        [--checkpoint-interval K] [--analyse-only]

Runs SCENE once per --case (its entries on top of the --set ones, e.g.
"cfl1:Time/CFL number=1" or "h2:Mesh refinement/Maximum level=6") to
Time/End time = T into DIR/NAME, with a checkpoint every K steps (default
5). A case whose run holds a checkpoint is resumed (a study longer than a
session goes on where it stopped); one whose metrics.csv reaches T is not
run again. Then, per case, at each of the times (linear interpolation
between metrics rows): relative density, mean neck radius, open and closed
porosity, closed pores, and the volume change; the time of the first
closed pore (pore_events.csv; a pocket of a few cells counts), the time
the control volume's closed porosity first exceeds its open porosity (most
of its pore space cut off), the steps and the wall time. Each value is
also given relative to the --reference case (default: the last), the
difference in density and porosity in absolute terms, the neck and the
closure time relative. One CSV row per case and time; the table printed.
"""
import argparse
import csv
import os
import pathlib
import subprocess
import sys

QUANTITIES = ["relative_density", "neck_mean", "open_porosity",
              "closed_porosity", "closed_pores", "volume_change"]
# Compared as differences (fractions of the box) or relative to the
# reference's value.
ABSOLUTE = {"relative_density", "open_porosity", "closed_porosity",
            "closed_pores", "volume_change"}


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def reached(directory, end_time):
    metrics = pathlib.Path(directory, "metrics.csv")
    if not metrics.is_file():
        return False
    rows = read_csv(metrics)
    return bool(rows) and float(rows[-1]["time"]) >= end_time * (1 - 1e-9)


def run_case(args, name, entries):
    directory = pathlib.Path(args.work, name).resolve()
    if reached(directory, args.end_time):
        return
    overrides = list(args.set) + entries + [
        f"Time/End time={args.end_time}",
        f"Output/Directory={directory}",
        f"Output/Checkpoint interval={args.checkpoint_interval}",
        "Output/Field formats=none"]
    command = ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np",
               str(args.ranks), args.levelsinter]
    if pathlib.Path(directory, "checkpoints").is_dir():
        command += ["--resume", str(directory)]
        # A resumed run takes its scene from the checkpoint; only the end
        # time may move.
        overrides = [f"Time/End time={args.end_time}"]
    else:
        command += ["--overwrite", str(pathlib.Path(args.scene).resolve())]
    for entry in overrides:
        command += ["--set", entry]
    print(" ".join(command), flush=True)
    with open(directory.with_suffix(".log"), "a") as log:
        code = subprocess.call(command, stdout=log, stderr=subprocess.STDOUT)
    if code != 0:
        sys.exit(f"packing_convergence.py: error: case {name} stopped with "
                 f"exit code {code} (log: {directory.with_suffix('.log')})")


def at(rows, column, t):
    """Column at time t, linear between the metrics rows around it."""
    times = [float(r["time"]) for r in rows]
    if not times or t > times[-1] * (1 + 1e-9):
        return float("nan")
    for k in range(1, len(times)):
        if times[k] >= t:
            t0, t1 = times[k - 1], times[k]
            y0, y1 = float(rows[k - 1][column]), float(rows[k][column])
            w = (t - t0) / (t1 - t0) if t1 > t0 else 1
            return y0 + w * (y1 - y0)
    return float(rows[0][column])


def first_closure(directory):
    events = pathlib.Path(directory, "pore_events.csv")
    if not events.is_file():
        return float("nan")
    for row in read_csv(events):
        if row["event"] == "closed" and int(row["step"]) > 0:
            return float(row["time"])
    return float("nan")


def mostly_closed(rows):
    """First time at which the control volume's closed porosity exceeds its
    open porosity (NaN if it never happens in the run)."""
    for row in rows:
        if float(row["closed_porosity"]) > float(row["open_porosity"]):
            return float(row["time"])
    return float("nan")


def analyse(args, cases):
    results = {}
    for name, _ in cases:
        directory = pathlib.Path(args.work, name)
        rows = read_csv(directory / "metrics.csv")
        results[name] = {
            "rows": rows,
            "closure": first_closure(directory),
            "mostly_closed": mostly_closed(rows),
            "steps": int(rows[-1]["step"]),
            "wall": float(rows[-1]["wall_time"])}
    reference = results[args.reference or cases[-1][0]]
    columns = ["case", "time", "steps", "wall_time", "first_closure",
               "first_closure_rel", "mostly_closed", "mostly_closed_rel"]
    for q in QUANTITIES:
        columns += [q, q + ("_diff" if q in ABSOLUTE else "_rel")]
    table = []
    for name, _ in cases:
        r = results[name]
        closure_rel = r["closure"] / reference["closure"] - 1
        for t in args.times:
            row = {"case": name, "time": t, "steps": r["steps"],
                   "wall_time": r["wall"], "first_closure": r["closure"],
                   "first_closure_rel": closure_rel,
                   "mostly_closed": r["mostly_closed"],
                   "mostly_closed_rel":
                       r["mostly_closed"] / reference["mostly_closed"] - 1}
            for q in QUANTITIES:
                value = at(r["rows"], q, t)
                ref = at(reference["rows"], q, t)
                row[q] = value
                row[q + ("_diff" if q in ABSOLUTE else "_rel")] = (
                    value - ref if q in ABSOLUTE else value / ref - 1)
            table.append(row)
    with open(args.csv, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=columns)
        writer.writeheader()
        writer.writerows(table)
    for row in table:
        print(", ".join(f"{k} {row[k]:.6g}" if isinstance(row[k], float)
                        else f"{k} {row[k]}" for k in columns))


def main():
    parser = argparse.ArgumentParser(usage=__doc__)
    parser.add_argument("levelsinter")
    parser.add_argument("scene")
    parser.add_argument("--work", required=True)
    parser.add_argument("--csv", required=True)
    parser.add_argument("--end-time", type=float, required=True)
    parser.add_argument("--times", required=True)
    parser.add_argument("--case", action="append", required=True)
    parser.add_argument("--reference")
    parser.add_argument("--ranks", type=int, default=2)
    parser.add_argument("--set", action="append", default=[])
    parser.add_argument("--checkpoint-interval", type=int, default=5)
    parser.add_argument("--analyse-only", action="store_true")
    args = parser.parse_args()
    args.times = [float(t) for t in args.times.split(",")]
    cases = []
    for case in args.case:
        name, _, entries = case.partition(":")
        cases.append((name, [e for e in entries.split(";") if e]))
    os.makedirs(args.work, exist_ok=True)
    if not args.analyse_only:
        for name, entries in cases:
            run_case(args, name, entries)
    analyse(args, cases)


if __name__ == "__main__":
    main()
