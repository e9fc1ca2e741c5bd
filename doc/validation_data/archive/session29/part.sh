#!/bin/bash
# Partition statistics of the 154 coupled scene: W = weights, NAME = output.
cd /work/runs/s29
LS_WEIGHTS=$W nice -n 5 mpirun --oversubscribe --allow-run-as-root -np ${NP:-2} /work/main/build/levelsinter --overwrite /work/main/parameter_files/packing_154_coupled_3d.prm \
  --set "Time/Maximum steps=${STEPS:-1}" --set "Output/Metrics interval=1" --set "Output/Field formats=none" \
  --set "Output/Directory=/work/runs/s29/$NAME" > /work/runs/s29/$NAME.log 2>&1
