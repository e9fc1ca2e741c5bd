#!/bin/bash
# The resolution runs on 8 spheres made like the 154 (issue 26, session 19),
# 1 rank, frozen build of 7890ab4 in /work/perf/study19:
#   run.sh coupled|surface_diffusion WORKDIR CSV CASE-SPEC...
# coupled: to t = 0.005 s (the cases h2 and curv1 were stopped after 3-4
# steps); surface_diffusion: to t = 0.033 s. REF names the reference case.
export LD_LIBRARY_PATH=/work/perf/study19
scene=$1; work=$2; csv=$3; shift 3
if [ "$scene" = coupled ]; then times="--end-time 0.005 --times 0.001,0.0025,0.005"
else times="--end-time 0.033 --times 0.005,0.01,0.02,0.033"; fi
cases=()
for c in "$@"; do cases+=(--case "$c"); done
/usr/bin/python3 /work/main/scripts/packing_convergence.py /work/perf/study19/levelsinter \
  /work/main/parameter_files/packing_154_${scene}_3d.prm --work $work --csv $csv $times \
  --set "Domain/Upper corner=0.6,0.6,0.6" --set "Domain/Subdivisions=2,2,2" --set "Output/Metrics interval=1" \
  --set "Geometry/Particle file=/work/main/parameter_files/packing_8_like_154_3d.csv" \
  "${cases[@]}" --reference ${REF:-reference} --ranks 1
