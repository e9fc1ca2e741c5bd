#!/bin/bash
# The coupled 154-particle scene as shipped, run to its end on NP ranks (default 1: the other core serves the helpers) with
# checkpoints (every 5 steps and every 20 minutes); RESUME=1 continues it.
# Frozen binary of main 03469df in /work/runs/s28/bin154.
cd /work/runs/s28
BIN=/work/runs/s28/bin154
OUT=/work/runs/s28/full154
export LD_LIBRARY_PATH=$BIN
if [ "${RESUME:-0}" = 1 ]; then
  ARGS="--resume $OUT"
else
  ARGS="--set Output/Directory=$OUT --set Output/Checkpoint\ interval=5 --set Output/Checkpoint\ minutes=20 --set Geometry/Particle\ file=/work/main/parameter_files/packing_154_3d.csv /work/main/parameter_files/packing_154_coupled_3d.prm"
fi
N=$(ls full154_*.log 2>/dev/null | wc -l)
# /usr/bin/time outside mpirun: inside, SIGUSR1 reached time, not
# levelsinter, and the run died without its stop checkpoint.
eval /usr/bin/time -v -o $OUT.time.$N mpirun --allow-run-as-root -np ${NP:-1} -x LD_LIBRARY_PATH $BIN/levelsinter $ARGS > full154_$N.log 2>&1
echo "exit $?" >> full154_$N.log
