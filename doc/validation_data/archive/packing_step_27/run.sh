#!/bin/bash
# The step study on the 27 spheres like the 154 (the shipped coupled scene), to t = 0.02 s, 1 rank per case;
# $1 = a list of case names to run in this process (the others run in a second process beside it).
M=/work/main
BIN=/work/runs/s26/bin_base
export LD_LIBRARY_PATH=$BIN
declare -A C
C[reference]="reference"
C[cfl1.5]="cfl1.5:Time/CFL number=1.5"
C[cfl3_cap2e-3]="cfl3_cap2e-3:Time/CFL number=3;Time/Time step=2e-3;Mesh refinement/Adapt interval=1"
C[cfl4_cap4e-3]="cfl4_cap4e-3:Time/CFL number=4;Time/Time step=4e-3;Mesh refinement/Adapt interval=1;Mesh refinement/Band width=0.048"
args=()
for c in $@; do args+=(--case "${C[$c]}"); done
python3 $M/scripts/packing_convergence.py $BIN/levelsinter $M/parameter_files/packing_154_coupled_3d.prm \
  --work /work/runs/s26/step27 --csv /work/runs/s26/step27_$1.csv --end-time 0.02 --times 0.005,0.01,0.02 \
  --ranks 1 --set "Domain/Upper corner=0.9,0.9,0.9" --set "Domain/Subdivisions=3,3,3" --set "Output/Metrics interval=1" \
  --set "Geometry/Particle file=$M/parameter_files/packing_27_like_154_3d.csv" --set "Time/CFL number=0.5" \
  "${args[@]}" --reference $1
