#!/bin/bash
# The coupled 154-particle scene as shipped (CFL 1.5), 2 ranks, set-up and STEPS steps, fields off,
# each rank under /usr/bin/time -v (peak memory per rank); build in $BIN.
cd /work/runs/s26
BIN=${BIN:-/work/runs/s26/bin_final}
export LD_LIBRARY_PATH=$BIN
mpirun --allow-run-as-root -np 2 -x LD_LIBRARY_PATH -x LS_AMG_TRIAL sh -c "exec /usr/bin/time -v -o /work/runs/s26/${OUT:-p154}_rank\$OMPI_COMM_WORLD_RANK.time $BIN/levelsinter --overwrite --set 'Time/Maximum steps=${STEPS:-6}' --set 'Output/Field formats=none' --set 'Output/Directory=/work/runs/s26/${OUT:-p154}' --set 'Geometry/Particle file=/work/main/parameter_files/packing_154_3d.csv' /work/main/parameter_files/packing_154_coupled_3d.prm" > ${OUT:-p154}.log 2>&1
echo "exit $?" >> ${OUT:-p154}.log
