#!/bin/bash
# 8 spheres made like the 154 (the CI guard's scene), every setting of the
# coupled 154 scene, to t = 0.005 s, 1 rank. usage: run8.sh NAME [--set ...]
cd /work/runs/s23
name=$1; shift
/usr/bin/time -v ${BIN:-./levelsinter} --overwrite --set "Domain/Upper corner=0.6,0.6,0.6" \
  --set "Domain/Subdivisions=2,2,2" \
  --set "Geometry/Particle file=/work/main/parameter_files/packing_8_like_154_3d.csv" \
  --set "Time/End time=0.005" --set "Output/Metrics interval=1" \
  --set "Output/Field formats=none" --set "Output/Directory=/work/runs/s23/$name" \
  "$@" /work/main/parameter_files/packing_154_coupled_3d.prm > $name.log 2> $name.time
echo "exit $?" >> $name.log
