#!/bin/bash
# The relaxing pairs (the scenes' start, x/R = 0.22) with the sharp contact radius.
B=/work/h-grains15
run() { name=$1; scene=$2; shift 2
  /usr/bin/time -v nice -n 10 $B/build/levelsinter --overwrite --set "Output/Field formats=none" \
    --set "Output/Progress interval=200" --set "Output/Metrics interval=2" \
    --set "Grain boundaries/Implicit contact law=true" --set "Grain boundaries/Deposition width=6" \
    --set "Grain boundaries/Sharp contact radius=true" --set "Time/End time=0.05" \
    --set "Output/Directory=/work/out-h-grains15/$name" "$@" $B/parameter_files/$scene > $name.log 2>&1
}
R16=(--set "Mesh refinement/Maximum level=4" --set "Level set/Filter thickness=0.094" --set "Mesh refinement/Band width=0.0752")
run relax_axi_R16_kink2_sharp grains_equilibrium_axisymmetric.prm "${R16[@]}" --set "Grain boundaries/Triple-line kink width=2"
run relax2d_R32_kink4_sharp grains_equilibrium_2d.prm --set "Grain boundaries/Triple-line kink width=4"
run relax_axi_R32_kink4_sharp grains_equilibrium_axisymmetric.prm --set "Grain boundaries/Triple-line kink width=4"
