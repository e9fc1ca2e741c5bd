#!/bin/bash
# A/B on 8 spheres like the 154 (coupled scene), 1 rank, STEPS steps: BIN dir, OUT name.
export LD_LIBRARY_PATH=$1
nice -n 5 /usr/bin/time -v -o /work/runs/s28/$2.time $1/levelsinter --overwrite /work/main/parameter_files/packing_154_coupled_3d.prm \
  --set "Domain/Upper corner=0.6,0.6,0.6" --set "Domain/Subdivisions=2,2,2" \
  --set "Geometry/Particle file=/work/main/parameter_files/packing_8_like_154_3d.csv" \
  --set "Time/Maximum steps=${STEPS:-8}" --set "Output/Metrics interval=1" --set "Output/Field formats=none" \
  --set "Output/Directory=/work/runs/s28/$2" > /work/runs/s28/$2.log 2>&1
