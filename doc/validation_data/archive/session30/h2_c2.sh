#!/bin/bash
# 8 spheres like the 154 (coupled scene) at h / 2 (fixed physics: lambda h
# = 0.028 um, lambda = 6), xi's extrapolation bounded with c = 2
# (LS_XI_BOUND, archive/session29/xi_extrapolation_bound.patch build), CFL
# 1.5, to t = 0.015 s, 1 rank, checkpoints every 20 min. RESUME=1 resumes.
cd /work/runs/s30
export LD_LIBRARY_PATH=/work/runs/s29/bin_xib
export LS_XI_BOUND=2
if [ -n "$RESUME" ]; then
  exec /work/runs/s29/bin_xib/levelsinter --resume /work/runs/s30/h2_c2 >> /work/runs/s30/h2_c2.log 2>&1
fi
/work/runs/s29/bin_xib/levelsinter --overwrite /work/main/parameter_files/packing_154_coupled_3d.prm \
  --set "Domain/Upper corner=0.6,0.6,0.6" --set "Domain/Subdivisions=2,2,2" \
  --set "Geometry/Particle file=/work/main/parameter_files/packing_8_like_154_3d.csv" \
  --set "Mesh refinement/Minimum level=2" --set "Mesh refinement/Maximum level=6" --set "Volume diffusion/Interior offset=6" \
  --set "Time/End time=0.015" --set "Output/Metrics interval=1" --set "Output/Field formats=none" \
  --set "Output/Checkpoint minutes=20" \
  --set "Output/Directory=/work/runs/s30/h2_c2" >> /work/runs/s30/h2_c2.log 2>&1
