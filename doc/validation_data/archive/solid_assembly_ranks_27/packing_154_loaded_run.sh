#!/bin/bash
# 154 coupled scene, 2 ranks, set-up + 2 steps, flat perf profile per rank
cd /work/runs/s24
export LD_LIBRARY_PATH=/work/runs/s24/bin
/usr/bin/time -v mpirun --allow-run-as-root -np 2 -x LD_LIBRARY_PATH sh -c 'exec perf record -e cpu-clock -F 100 -o /work/runs/s24/perf154.$OMPI_COMM_WORLD_RANK.data /work/runs/s24/bin/levelsinter --overwrite --set "Time/Maximum steps=2" --set "Output/Field formats=none" --set "Output/Directory=/work/runs/s24/p154" --set "Geometry/Particle file=/work/main/parameter_files/packing_154_3d.csv" /work/main/parameter_files/packing_154_coupled_3d.prm' > p154.log 2> p154.time
echo "exit $?" >> p154.log
