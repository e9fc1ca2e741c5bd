#!/bin/bash
# Before (bin_w1 = 057d5dd) and after (the ghost-penalty faces' entries inserted directly, on the merged main),
# 27 spheres, 2 steps, 1 and 2 ranks.
cd /work/runs/s25
M=/work/main
for np in ${NPS:-1 2}; do
for v in ${VS:-bin_w1 bin_face}; do
export LD_LIBRARY_PATH=/work/runs/s25/$v
mpirun --allow-run-as-root -np $np -x LD_LIBRARY_PATH $v/levelsinter --overwrite \
  --set 'Domain/Upper corner=0.9,0.9,0.9' --set 'Domain/Subdivisions=3,3,3' \
  --set "Geometry/Particle file=$M/parameter_files/packing_27_like_154_3d.csv" \
  --set 'Time/Maximum steps=2' --set 'Output/Field formats=none' --set 'Output/Metrics interval=1' \
  --set "Output/Directory=/work/runs/s25/abface_${v}_np$np" \
  $M/parameter_files/packing_154_coupled_3d.prm > abface_${v}_np$np.log 2>&1
done; done
