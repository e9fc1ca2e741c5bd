#!/bin/bash
# 8 spheres like the 154 (coupled scene, Extrapolation = limited), CFL 1.5,
# to t = 0.015 s, 1 rank, metrics every step, frozen build bin_lim of
# session 30 (the build of the h and h / 2 references). NAME = output,
# then any number of --set arguments.
cd /work/runs/s31
NAME=$1; shift
LD_LIBRARY_PATH=/work/runs/s30/bin_lim /work/runs/s30/bin_lim/levelsinter \
  --overwrite /work/main/parameter_files/packing_154_coupled_3d.prm \
  --set "Domain/Upper corner=0.6,0.6,0.6" --set "Domain/Subdivisions=2,2,2" \
  --set "Geometry/Particle file=/work/main/parameter_files/packing_8_like_154_3d.csv" \
  --set "Time/End time=0.015" --set "Output/Metrics interval=1" \
  --set "Output/Field formats=none" --set "Output/Checkpoint minutes=20" \
  "$@" --set "Output/Directory=/work/runs/s31/$NAME" > /work/runs/s31/$NAME.log 2>&1
