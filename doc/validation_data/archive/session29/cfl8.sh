#!/bin/bash
# 8 spheres like the 154 (coupled scene), 1 rank, to T: CFL number C, NAME.
cd /work/runs/s29
LD_LIBRARY_PATH=/work/runs/s29/bin_new nice -n 5 /work/runs/s29/bin_new/levelsinter --overwrite /work/main/parameter_files/packing_154_coupled_3d.prm \
  --set "Domain/Upper corner=0.6,0.6,0.6" --set "Domain/Subdivisions=2,2,2" \
  --set "Geometry/Particle file=${PF:-/work/main/parameter_files/packing_8_like_154_3d.csv}" \
  --set "Time/End time=${T:-0.015}" --set "Time/CFL number=$C" --set "Output/Metrics interval=1" --set "Output/Field formats=none" \
  --set "Output/Directory=/work/runs/s29/$NAME" > /work/runs/s29/$NAME.log 2>&1
