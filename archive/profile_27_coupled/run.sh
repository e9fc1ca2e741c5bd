#!/bin/bash
# The profile of doc/performance.md, "Where a coupled packing step goes, by
# function": 27 spheres made like the 154, the coupled 154 scene, 1 rank,
# set-up and 3 steps under perf's sampling clock. Run from the repository
# root with a Release build in build/: writes perf.data, run.log and
# perf_symbols.txt into this folder.
set -e
here=$(dirname "$0")
perf record -e cpu-clock -F 250 -o "$here/perf.data" ./build/levelsinter \
  --overwrite --set "Output/Directory=$here/run" \
  --set "Domain/Upper corner=0.9,0.9,0.9" --set "Domain/Subdivisions=3,3,3" \
  --set "Geometry/Particle file=$PWD/parameter_files/packing_27_like_154_3d.csv" \
  --set "Time/Maximum steps=3" --set "Output/Field formats=none" \
  --set "Output/Progress interval=1" \
  parameter_files/packing_154_coupled_3d.prm | grep -v '^warning' > "$here/run.log"
perf report -i "$here/perf.data" --stdio --sort symbol | grep -v '^$' |
  sed 's/ \{3,\}/  /g' | head -80 > "$here/perf_symbols.txt"
rm -rf "$here/run" "$here/perf.data"
