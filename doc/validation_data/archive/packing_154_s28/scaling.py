#!/usr/bin/python3
"""Per call: the 1-rank run's CPU (its core shared with other jobs, so CPU,
not wall) against the 2-rank run's wall on idle cores (session 27)."""
import csv, sys
one = {r["section"]: r for r in csv.DictReader(open(sys.argv[1]))}
two = {r["section"]: r for r in csv.DictReader(open(sys.argv[2]))}
print("| section | 1 rank: calls, CPU s per call | 2 ranks: calls, wall s per call | speed-up |")
print("|---|---|---|---|")
for s in two:
    if s not in one or float(two[s]["wall_seconds"]) < 1: continue
    c1, t1 = int(one[s]["calls"]), float(one[s]["cpu_seconds"])
    c2, t2 = int(two[s]["calls"]), float(two[s]["wall_seconds"])
    print(f"| {s} | {c1}, {t1/c1:.1f} | {c2}, {t2/c2:.1f} | {(t1/c1)/(t2/c2):.2f} |")
