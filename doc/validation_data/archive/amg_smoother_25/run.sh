#!/bin/bash
# AMG settings of the elastic solve (a throw-away build reading LS_AMG_TRIAL: W/V cycle, sweeps, t = threshold 0.01),
# 27 spheres like the 154, 2 steps, 1 rank, build = main 36a5d51 + that variable.
cd /work/runs/s25
M=/work/main
export LD_LIBRARY_PATH=/work/runs/s25/bin_amg
for c in ${CONFIGS:-W2 V2 V1 W1 V2t}; do
LS_AMG_TRIAL=$c /usr/bin/time -v bin_amg/levelsinter --overwrite \
  --set 'Domain/Upper corner=0.9,0.9,0.9' --set 'Domain/Subdivisions=3,3,3' \
  --set "Geometry/Particle file=$M/parameter_files/packing_27_like_154_3d.csv" \
  --set 'Time/Maximum steps=2' --set 'Output/Field formats=none' --set 'Output/Metrics interval=1' \
  --set "Output/Directory=/work/runs/s25/amg27_$c" \
  $M/parameter_files/packing_154_coupled_3d.prm > amg27_$c.log 2> amg27_$c.time
done
