#!/bin/bash
# the coupled 154 scene, 1 step, continuous (new quadrature) or solid space
cd /work/runs/c154
space=$1
cp /work/main/build/levelsinter ./levelsinter_$space
/usr/bin/time -v mpirun --allow-run-as-root -np 2 ./levelsinter_$space --overwrite --set "Time/Maximum steps=1" --set "Output/Field formats=none" --set "Output/Metrics interval=1" --set "Viscous flow/Pressure space=$space" --set "Output/Directory=/work/runs/c154/$space" --set "Geometry/Particle file=/work/main/parameter_files/packing_154_3d.csv" /work/main/parameter_files/packing_154_coupled_3d.prm > $space.log 2> $space.time
