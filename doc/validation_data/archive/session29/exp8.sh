#!/bin/bash
# 8 spheres like the 154 (coupled scene), CFL 1.5, to t = 0.015 s, 1 rank,
# with one extra setting S (entry=value); NAME.
cd /work/runs/s29
LD_LIBRARY_PATH=/work/runs/s29/bin_new /work/runs/s29/bin_new/levelsinter --overwrite /work/main/parameter_files/packing_154_coupled_3d.prm \
  --set "Domain/Upper corner=0.6,0.6,0.6" --set "Domain/Subdivisions=2,2,2" \
  --set "Geometry/Particle file=/work/main/parameter_files/packing_8_like_154_3d.csv" \
  --set "Time/End time=0.015" --set "Output/Metrics interval=1" --set "Output/Field formats=none" \
  --set "$S" --set "Output/Directory=/work/runs/s29/$NAME" > /work/runs/s29/$NAME.log 2>&1
