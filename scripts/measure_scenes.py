#!/usr/bin/env python3
"""Measure how long each shipped scene takes, on 1 and 2 MPI ranks.

    measure_scenes.py LEVELSINTER --csv OUT.csv [SCENE.prm ...]
                      [--skip NAME.prm ...] [--ranks 1 2] [--budget 60]
                      [--max-budget 300] [--work DIR]

Runs `mpirun -np N LEVELSINTER SCENE` (the scene as shipped, its fields
included, progress every step) into WORK/SCENE_npN, its output in
WORK/SCENE_npN.log. A run that ends within
--budget seconds is measured to its end; a longer one is stopped with
SIGUSR1 once the progress line has an ETA (at most --max-budget seconds)
and projected to its end time: the wall time of the last progress line
plus its ETA, "projected from N steps" (a run whose ETA says it ends
within half a budget more is let finish). CPU time is that of the ranks
(user + system, summed over the ranks, sampled every 0.5 s from /proc),
measured to the stop; a projected run's CPU is scaled like its wall
time. The load average at
the start is kept: on a shared machine the wall time grows with it, the
CPU time hardly. One CSV row per scene and rank count, written to OUT.csv
as it goes (all parameter_files/*.prm but the --skip ones unless SCENEs
are given); the rows OUT.csv holds for scenes or rank counts not measured
this time are kept.
"""
import argparse
import csv
import datetime
import os
import pathlib
import re
import signal
import subprocess
import threading
import time

PROGRESS = re.compile(r"^step +(\d+) +t = +(\S+) / (\S+) .* wall (\S+ \S+)"
                      r" +ETA (-|\S+ \S+)")
DONE = re.compile(r"^done: (\d+) steps to t = (\S+) in (\S+) s")
COLUMNS = ["scene", "ranks", "status", "steps", "time_reached", "end_time",
           "wall_s", "cpu_s", "total_wall_s", "total_cpu_s", "load_1min",
           "date"]


def seconds(text):
    value, unit = text.split()
    return float(value) * {"s": 1, "min": 60, "h": 3600}[unit]


def ranks_cpu(parent, seen):
    """Record in seen the CPU seconds (user + system) so far of each
    process whose parent is parent (mpirun's ranks: the ranks are not
    waited for through mpirun, so the rusage of children misses them)."""
    tick = os.sysconf("SC_CLK_TCK")
    for stat in pathlib.Path("/proc").glob("[0-9]*/stat"):
        try:
            fields = stat.read_text().rsplit(")", 1)[1].split()
        except OSError:
            continue
        if int(fields[1]) == parent:
            seen[stat.parent.name] = (int(fields[11]) + int(fields[12])) / tick


def measure(levelsinter, scene, ranks, args):
    mpirun = ["mpirun", "--oversubscribe", "-np", str(ranks)]
    if os.geteuid() == 0:
        mpirun.insert(1, "--allow-run-as-root")
    out = pathlib.Path(args.work) / f"{scene.stem}_np{ranks}"
    command = mpirun + [levelsinter, "--overwrite",
                        "--set", f"Output/Directory={out}",
                        "--set", "Output/Progress interval=1", str(scene)]
    load = os.getloadavg()[0]
    start = time.monotonic()
    process = subprocess.Popen(command, stdout=subprocess.PIPE,
                               stderr=subprocess.STDOUT, text=True)
    lines = []
    reader = threading.Thread(
        target=lambda: lines.extend(iter(process.stdout.readline, "")))
    reader.start()
    stopped = False
    cpu_seen = {}
    while process.poll() is None:
        ranks_cpu(process.pid, cpu_seen)
        time.sleep(0.5)
        elapsed = time.monotonic() - start
        etas = [seconds(m.group(5)) for m in map(PROGRESS.match, lines[-3:])
                if m and m.group(5) != "-"]
        # A run whose ETA says it ends within half the budget more is let
        # finish.
        if not stopped and ((elapsed > args.budget and etas and
                             elapsed + etas[-1] > 1.5 * args.budget)
                            or elapsed > args.max_budget):
            # SIGUSR1: mpirun passes it on and every rank stops cleanly
            # after its step (SIGTERM makes mpirun end the ranks at once).
            process.send_signal(signal.SIGUSR1)
            stopped = True
    reader.join()
    cpu = sum(cpu_seen.values())
    pathlib.Path(f"{out}.log").write_text("".join(lines))
    row = {"scene": scene.name, "ranks": ranks, "cpu_s": round(cpu, 1),
           "load_1min": round(load, 1),
           "date": datetime.datetime.now().isoformat(timespec="minutes")}
    progress = [m for m in map(PROGRESS.match, lines) if m]
    done = [m for m in map(DONE.match, lines) if m]
    if done:
        wall = float(done[-1].group(3))
        row.update(status="finished", steps=int(done[-1].group(1)),
                   time_reached=float(done[-1].group(2)),
                   end_time=progress[-1].group(3) if progress else "",
                   wall_s=round(wall, 1), total_wall_s=round(wall, 1),
                   total_cpu_s=round(cpu, 1))
        return row
    # The last progress line with an ETA before the stop (the step the
    # signal ended, if it printed one, reports 0).
    estimated = [m for m in progress
                 if m.group(5) != "-" and seconds(m.group(5)) > 0]
    if not estimated:
        row.update(status="failed" if not stopped else "no estimate",
                   steps=int(progress[-1].group(1)) if progress else 0)
        print("".join(lines[-20:]))
        return row
    last = estimated[-1]
    wall = seconds(last.group(4))
    total = wall + seconds(last.group(5))
    row.update(status=f"projected from {last.group(1)} steps",
               steps=int(last.group(1)), time_reached=float(last.group(2)),
               end_time=float(last.group(3)), wall_s=round(wall, 1),
               total_wall_s=round(total, 1),
               total_cpu_s=round(cpu * total / max(wall, 1e-9), 1))
    return row


def main():
    parser = argparse.ArgumentParser(usage=__doc__)
    parser.add_argument("levelsinter")
    parser.add_argument("--csv", required=True)
    parser.add_argument("scenes", nargs="*")
    parser.add_argument("--skip", nargs="+", default=[])
    parser.add_argument("--ranks", nargs="+", type=int, default=[1, 2])
    parser.add_argument("--budget", type=float, default=60)
    parser.add_argument("--max-budget", type=float, default=300)
    parser.add_argument("--work", default="measure_scenes")
    # Scenes may follow the options (the usage line's order).
    args = parser.parse_intermixed_args()
    pathlib.Path(args.work).mkdir(parents=True, exist_ok=True)
    root = pathlib.Path(__file__).resolve().parent.parent
    scenes = ([pathlib.Path(s) for s in args.scenes] if args.scenes else
              sorted(p for p in (root / "parameter_files").glob("*.prm")
                     if p.name not in args.skip))
    # The rows of scenes and rank counts not measured this time are kept,
    # so that measuring a few scenes again does not drop the others.
    table = {}
    if pathlib.Path(args.csv).is_file():
        with open(args.csv, newline="") as f:
            for row in csv.DictReader(f):
                table[(row["scene"], int(row["ranks"]))] = row
    for scene in scenes:
        for ranks in args.ranks:
            row = measure(str(pathlib.Path(args.levelsinter).resolve()),
                          scene.resolve(), ranks, args)
            table[(scene.name, ranks)] = row
            write_table(args.csv, table)
            print(", ".join(f"{k} {row.get(k, '')}" for k in COLUMNS),
                  flush=True)


def write_table(path, table):
    """Write the rows of table (keyed by scene and ranks) sorted, through
    a temporary file renamed into place."""
    partial = pathlib.Path(str(path) + ".partial")
    with open(partial, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=COLUMNS)
        writer.writeheader()
        for key in sorted(table):
            writer.writerow({k: table[key].get(k, "") for k in COLUMNS})
    partial.replace(path)


if __name__ == "__main__":
    main()
