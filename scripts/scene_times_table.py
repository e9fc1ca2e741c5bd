#!/usr/bin/env python3
"""Fill the time columns of the user guide's scene table from the data.

    scene_times_table.py ROOT [--check]

Reads ROOT/doc/validation_data/scene_times.csv (scripts/measure_scenes.py)
and rewrites, in the table of ROOT/doc/user_guide.md whose header starts
with "| scene | what it shows |", the columns "1 core" and "2 cores" of each
scene the CSV has: "12 s (4.3 s CPU)" for a run measured to its end,
"~3.3 min (~70 s CPU), projected from 13 steps" for one projected from its
first steps, "not measured: ..." otherwise. With --check nothing is
written; the exit code is 1 if the table and the CSV disagree (the test
scene_times_table), so that a table cannot cite times no file holds.
"""
import csv
import pathlib
import sys

HEADER = "| scene | what it shows |"


def duration(seconds):
    if seconds < 90:
        return f"{seconds:.2g} s" if seconds < 10 else f"{seconds:.0f} s"
    if seconds < 90 * 60:
        return f"{seconds / 60:.1f} min"
    return f"{seconds / 3600:.1f} h"


def cell(row):
    if row is None:
        return "-"
    status = row["status"]
    if status == "finished":
        return (f"{duration(float(row['total_wall_s']))} "
                f"({duration(float(row['total_cpu_s']))} CPU)")
    if status.startswith("projected"):
        return (f"~{duration(float(row['total_wall_s']))} "
                f"(~{duration(float(row['total_cpu_s']))} CPU), {status}")
    return (f"not measured: {status} ({duration(float(row['cpu_s']))} CPU "
            f"before the stop)")


def main():
    args = sys.argv[1:]
    check = "--check" in args
    args = [a for a in args if a != "--check"]
    if len(args) != 1:
        sys.exit(__doc__)
    root = pathlib.Path(args[0])
    rows = {}
    with open(root / "doc/validation_data/scene_times.csv", newline="") as f:
        for row in csv.DictReader(f):
            rows[(row["scene"], int(row["ranks"]))] = row
    guide = root / "doc/user_guide.md"
    lines = guide.read_text().split("\n")
    start = next(i for i, line in enumerate(lines) if line.startswith(HEADER))
    out = list(lines)
    for i in range(start + 2, len(lines)):
        if not lines[i].startswith("|"):
            break
        fields = lines[i].split(" | ")
        scene = fields[0].strip("| `").split("`")[0]
        if not any(key[0] == scene for key in rows):
            continue
        fields[2] = cell(rows.get((scene, 1)))
        fields[3] = cell(rows.get((scene, 2))) + " |"
        out[i] = " | ".join(fields)
    if out == lines:
        return
    if check:
        for old, new in zip(lines, out):
            if old != new:
                print(f"table:    {old}\nscene_times.csv: {new}")
        sys.exit("scene_times_table.py: error: the scene table of "
                 "doc/user_guide.md and doc/validation_data/scene_times.csv "
                 "disagree; run scripts/scene_times_table.py ROOT")
    guide.write_text("\n".join(out))


if __name__ == "__main__":
    main()
