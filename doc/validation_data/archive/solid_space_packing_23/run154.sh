#!/bin/bash
# The coupled 154-particle scene with the solid-only elastic problem and the
# recovered gradient (session 23), 2 ranks, checkpoints every 10 steps.
cd /work/runs/s23
/usr/bin/time -v mpirun --allow-run-as-root -np 2 ./levelsinter_154 --overwrite \
  --set "Viscous flow/Pressure space=solid" \
  --set "Volume diffusion/Pressure gradient=recovered" \
  --set "Output/Field formats=none" --set "Output/Checkpoint interval=10" \
  --set "Output/Directory=/work/runs/s23/c154_solid_rec" \
  --set "Geometry/Particle file=/work/main/parameter_files/packing_154_3d.csv" \
  "$@" /work/main/parameter_files/packing_154_coupled_3d.prm > c154_solid_rec.log 2> c154_solid_rec.time
echo "exit $?" >> c154_solid_rec.log
