#!/bin/bash
# A/B: $1 and $2 binaries (dirs under /work/runs/s26), 27 spheres, STEPS steps, 1 rank, one after the other.
cd /work/runs/s26
for b in $1 $2; do OUT=ab_${b}_$3 BIN=/work/runs/s26/$b STEPS=${STEPS:-2} ./p27.sh; done
