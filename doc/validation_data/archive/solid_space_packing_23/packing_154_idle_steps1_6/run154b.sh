#!/bin/bash
# The coupled 154-particle scene as shipped in session 23 (solid space,
# recovered xi), 2 ranks on idle cores, 6 steps: the cost per phase.
cd /work/runs/s23
/usr/bin/time -v mpirun --allow-run-as-root -np 2 ./levelsinter_154b --overwrite \
  --set "Time/Maximum steps=6" --set "Output/Field formats=none" \
  --set "Output/Directory=/work/runs/s23/c154b" \
  --set "Geometry/Particle file=/work/main/parameter_files/packing_154_3d.csv" \
  /work/main/parameter_files/packing_154_coupled_3d.prm > c154b.log 2> c154b.time
echo "exit $?" >> c154b.log
