#!/bin/bash
# The elastic set-up's parts per rank (throw-away build, instr/apply.py on main 057d5dd), 27 spheres, 1 step, 1 and 2 ranks.
cd /work/runs/s25/instr
M=/work/main
export LD_LIBRARY_PATH=/work/runs/s25/bin_instr
for np in 1 2; do
mpirun --allow-run-as-root -np $np -x LD_LIBRARY_PATH /work/runs/s25/bin_instr/levelsinter --overwrite \
  --set 'Domain/Upper corner=0.9,0.9,0.9' --set 'Domain/Subdivisions=3,3,3' \
  --set "Geometry/Particle file=$M/parameter_files/packing_27_like_154_3d.csv" \
  --set 'Time/Maximum steps=1' --set 'Output/Field formats=none' --set 'Output/Metrics interval=100' \
  --set "Output/Directory=/work/runs/s25/instr/np$np" \
  $M/parameter_files/packing_154_coupled_3d.prm > np$np.log 2>&1
done
