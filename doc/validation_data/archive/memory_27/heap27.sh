#!/bin/bash
cd /work/runs/s27
M=/work/main; BIN=/work/runs/s27/bin_base; export LD_LIBRARY_PATH=$BIN
heaptrack -o /work/runs/s27/heap27_trace $BIN/levelsinter --overwrite \
  --set 'Domain/Upper corner=0.9,0.9,0.9' --set 'Domain/Subdivisions=3,3,3' \
  --set "Geometry/Particle file=$M/parameter_files/packing_27_like_154_3d.csv" \
  --set "Time/Maximum steps=1" --set 'Output/Field formats=none' --set 'Output/Metrics interval=1' \
  --set "Output/Directory=/work/runs/s27/heap27" \
  $M/parameter_files/packing_154_coupled_3d.prm > heap27.log 2>&1
echo "exit $?" >> heap27.log
