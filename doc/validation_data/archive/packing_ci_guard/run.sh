#!/bin/bash
# run.sh NAME NP [--set ...]
name=$1; np=$2; shift 2
mpirun --allow-run-as-root --oversubscribe -np $np /work/main/build/levelsinter --overwrite /work/main/parameter_files/packing_154_coupled_3d.prm \
  --set "Domain/Upper corner=0.6,0.6,0.6" --set "Domain/Subdivisions=2,2,2" \
  --set "Geometry/Particle file=/work/main/parameter_files/packing_8_like_154_3d.csv" \
  --set "Time/Maximum steps=3" --set "Output/Metrics interval=1" --set "Output/Field formats=none" \
  --set "Output/Directory=/work/conv/ci8/$name" "$@" > /work/conv/ci8/$name.log 2>&1
echo "$name rc=$?"; grep "^done" /work/conv/ci8/$name.log
