#!/bin/bash
# 2D pair from its exact state with the sharp contact radius: R/h = 16, 32, 64.
B=/work/h-grains15
run() { name=$1; shift
  /usr/bin/time -v nice -n 10 $B/build/levelsinter --overwrite --set "Output/Field formats=none" \
    --set "Output/Progress interval=100" --set "Output/Metrics interval=1" \
    --set "Geometry/Particles=" --set "Geometry/Particle file=$B/tests/grains_rest_2d.csv" \
    --set "Grain boundaries/Implicit contact law=true" --set "Grain boundaries/Deposition width=6" \
    --set "Grain boundaries/Sharp contact radius=true" --set "Time/End time=0.02" \
    --set "Output/Directory=/work/out-h-grains15/$name" "$@" $B/parameter_files/grains_equilibrium_2d.prm > $name.log 2>&1
}
R16=(--set "Mesh refinement/Maximum level=4" --set "Level set/Filter thickness=0.094" --set "Mesh refinement/Band width=0.0752")
R64=(--set "Mesh refinement/Maximum level=6" --set "Level set/Filter thickness=0.0235" --set "Mesh refinement/Band width=0.0188")
run rest2d_R32_kink4_sharp_cap --set "Grain boundaries/Triple-line kink width=4" --set "Time/Time step=2.5e-4"
run rest2d_R16_kink2_sharp "${R16[@]}" --set "Grain boundaries/Triple-line kink width=2"
run rest2d_R32_kink2_sharp --set "Grain boundaries/Triple-line kink width=2"
run rest2d_R64_kink8_sharp "${R64[@]}" --set "Grain boundaries/Triple-line kink width=8"
run rest2d_R64_kink4_sharp "${R64[@]}" --set "Grain boundaries/Triple-line kink width=4"
