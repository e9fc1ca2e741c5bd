#!/bin/bash
# 27 spheres like the 154 (the 154 scene's settings in a 0.9 um box), 1 rank; BIN, STEPS, OUT, EXTRA from the environment.
cd /work/runs/s27
M=/work/main
BIN=${BIN:-/work/main/build}
export LD_LIBRARY_PATH=$BIN LS_MODES
/usr/bin/time -v -o ${OUT}.time $BIN/levelsinter --overwrite \
  --set 'Domain/Upper corner=0.9,0.9,0.9' --set 'Domain/Subdivisions=3,3,3' \
  --set "Geometry/Particle file=$M/parameter_files/packing_27_like_154_3d.csv" \
  --set "Time/Maximum steps=${STEPS:-3}" --set 'Output/Field formats=none' --set 'Output/Metrics interval=1' \
  --set "Output/Directory=/work/runs/s27/$OUT" $EXTRA \
  $M/parameter_files/packing_154_coupled_3d.prm > ${OUT}.log 2>&1
echo "exit $?" >> ${OUT}.log
