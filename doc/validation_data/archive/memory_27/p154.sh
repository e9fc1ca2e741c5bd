#!/bin/bash
# The coupled 154-particle scene as shipped, 2 ranks, set-up and STEPS steps, fields off.
cd /work/runs/s27
BIN=${BIN:-/work/runs/s27/bin_base}
OUT=${OUT:-p154perf}
export LD_LIBRARY_PATH=$BIN
mpirun --allow-run-as-root -np 2 -x LD_LIBRARY_PATH sh -c "if [ \$OMPI_COMM_WORLD_RANK = 0 ]; then exec /usr/bin/time -v -o /work/runs/s27/${OUT}_rank0.time $BIN/levelsinter --overwrite --set 'Time/Maximum steps=${STEPS:-2}' --set 'Output/Field formats=none' --set 'Output/Directory=/work/runs/s27/$OUT' --set 'Geometry/Particle file=/work/main/parameter_files/packing_154_3d.csv' /work/main/parameter_files/packing_154_coupled_3d.prm; else exec /usr/bin/time -v -o /work/runs/s27/${OUT}_rank1.time $BIN/levelsinter --overwrite --set 'Time/Maximum steps=${STEPS:-2}' --set 'Output/Field formats=none' --set 'Output/Directory=/work/runs/s27/$OUT' --set 'Geometry/Particle file=/work/main/parameter_files/packing_154_3d.csv' /work/main/parameter_files/packing_154_coupled_3d.prm; fi" > $OUT.log 2>&1
echo "exit $?" >> $OUT.log
