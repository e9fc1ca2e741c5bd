#!/bin/bash
# Resolution study on 8 spheres made like the 154 (issue 26), 1 rank, frozen build study19 (7890ab4)
# usage: run8.sh WORKDIR CSV CASE-SPEC...
export LD_LIBRARY_PATH=/work/perf/study19
work=$1; csv=$2; shift 2
cases=()
for c in "$@"; do cases+=(--case "$c"); done
/usr/bin/python3 /work/main/scripts/packing_convergence.py /work/perf/study19/levelsinter \
  /work/main/parameter_files/packing_154_coupled_3d.prm \
  --work $work --csv $csv \
  --end-time 0.005 --times 0.001,0.0025,0.005 \
  --set "Domain/Upper corner=0.6,0.6,0.6" --set "Domain/Subdivisions=2,2,2" --set "Output/Metrics interval=1" \
  --set "Geometry/Particle file=/work/main/parameter_files/packing_8_like_154_3d.csv" \
  "${cases[@]}" --reference ${REF:-reference} --ranks 1
