#!/bin/bash
# Before (s24/bin2 = main fb8b951 for this scene) and after (cut-cell rules), 27 spheres, 3 steps, 1 rank.
cd /work/runs/s25
M=/work/main
for v in /work/runs/s24/bin2 /work/runs/s25/bin_new; do
n=$(basename $v)
export LD_LIBRARY_PATH=$v
/usr/bin/time -v $v/levelsinter --overwrite \
  --set 'Domain/Upper corner=0.9,0.9,0.9' --set 'Domain/Subdivisions=3,3,3' \
  --set "Geometry/Particle file=$M/parameter_files/packing_27_like_154_3d.csv" \
  --set 'Time/Maximum steps=3' --set 'Output/Field formats=none' --set 'Output/Metrics interval=1' \
  --set "Output/Directory=/work/runs/s25/ab27_$n" \
  $M/parameter_files/packing_154_coupled_3d.prm > ab27_$n.log 2> ab27_$n.time
done
