#!/bin/bash
# The coupled packing's mesh study redone with the scene as it is now (solid
# pressure space, recovered xi, CFL 1.5): 8 spheres made like the 154 at h
# (the scene) and h / 2 at fixed physics (xi's depth lambda h = 0.028 um:
# lambda = 6 at h / 2; band and filter in um unchanged), 1 rank, to t =
# 0.005 s. Frozen build of main 03469df (/work/runs/s28/bin154).
export LD_LIBRARY_PATH=/work/runs/s28/bin154
nice -n 5 /usr/bin/python3 /work/main/scripts/packing_convergence.py /work/runs/s28/bin154/levelsinter \
  /work/main/parameter_files/packing_154_coupled_3d.prm --work /work/runs/s28/res8 --csv /work/runs/s28/res8.csv \
  --end-time 0.005 --times 0.001,0.0025,0.005 \
  --set "Domain/Upper corner=0.6,0.6,0.6" --set "Domain/Subdivisions=2,2,2" --set "Output/Metrics interval=1" \
  --set "Geometry/Particle file=/work/main/parameter_files/packing_8_like_154_3d.csv" \
  --case "h" \
  --case "h2:Mesh refinement/Minimum level=2;Mesh refinement/Maximum level=6;Volume diffusion/Interior offset=6" \
  --reference h2 --ranks 1
