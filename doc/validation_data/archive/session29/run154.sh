#!/bin/bash
# The 154 coupled scene, set-up + STEPS steps: BIN dir, NP ranks, NAME.
cd /work/runs/s29
/usr/bin/time -v -o $NAME.time mpirun --allow-run-as-root -np $NP -x LD_LIBRARY_PATH=/work/runs/s29/$BIN \
  /work/runs/s29/$BIN/levelsinter --overwrite /work/main/parameter_files/packing_154_coupled_3d.prm \
  --set "Time/Maximum steps=${STEPS:-2}" --set "Output/Field formats=none" \
  --set "Output/Directory=/work/runs/s29/$NAME" > $NAME.log 2>&1
