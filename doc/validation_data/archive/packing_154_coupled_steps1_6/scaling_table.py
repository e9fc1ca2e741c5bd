#!/usr/bin/python3
# scal.py ONE_RANK_timing.csv TWO_RANK_timing.csv: wall per phase and the speed-up
import csv, sys
a={r['section']:r for r in csv.DictReader(open(sys.argv[1]))}
b={r['section']:r for r in csv.DictReader(open(sys.argv[2]))}
print('| phase | calls | 1 rank (wall) | 2 ranks (wall) | speed-up |')
print('|---|---|---|---|---|')
for k in a:
    if k in b and float(b[k]['wall_seconds'])>1:
        x=float(a[k]['wall_seconds']); y=float(b[k]['wall_seconds'])
        print('| %s | %s | %.1f s | %.1f s | %.2fx |'%(k,a[k]['calls'],x,y,x/y))
