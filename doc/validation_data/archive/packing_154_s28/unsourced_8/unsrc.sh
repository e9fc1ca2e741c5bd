#!/bin/bash
# 8 spheres like the 154 (coupled scene), 10 steps, fields every 5: NAME then --set pairs.
export LD_LIBRARY_PATH=/work/runs/s28/bin_rg
name=$1; shift
nice -n 5 /work/runs/s28/bin_rg/levelsinter --overwrite /work/main/parameter_files/packing_154_coupled_3d.prm --set "Domain/Upper corner=0.6,0.6,0.6" --set "Domain/Subdivisions=2,2,2" --set "Geometry/Particle file=/work/main/parameter_files/packing_8_like_154_3d.csv" --set "Time/Maximum steps=10" --set "Output/Metrics interval=1" --set "Output/Field interval=5" --set "Output/Directory=/work/runs/s28/$name" "$@" > /work/runs/s28/$name.log 2>&1
