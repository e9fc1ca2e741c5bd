#!/bin/bash
# 27 spheres like the 154 (coupled scene, Extrapolation = limited), CFL
# 1.5, to t = 0.015 s, 1 rank, metrics and fields every step, frozen build
# bin_lim. NAME = output, then --set arguments.
cd /work/runs/s30
NAME=$1; shift
LD_LIBRARY_PATH=/work/runs/s30/bin_lim /work/runs/s30/bin_lim/levelsinter --overwrite /work/main/parameter_files/packing_154_coupled_3d.prm \
  --set "Domain/Upper corner=0.9,0.9,0.9" --set "Domain/Subdivisions=3,3,3" \
  --set "Geometry/Particle file=/work/main/parameter_files/packing_27_like_154_3d.csv" \
  --set "Volume diffusion/Extrapolation=limited" \
  --set "Time/End time=0.015" --set "Output/Metrics interval=1" --set "Output/Field interval=1" \
  "$@" --set "Output/Directory=/work/runs/s30/$NAME" > /work/runs/s30/$NAME.log 2>&1
