#!/bin/bash
# metrics path cost on the 27-particle packing: base (c6d9be4) and new, 1 rank, level 2, 4 steps, a metrics row each step
for v in base new; do
  bin=/work/wt-base/build/levelsinter; [ $v = new ] && bin=/work/main/build/levelsinter
  rm -rf /tmp/mcost/$v
  nice -n 19 $bin /work/main/parameter_files/packing_27_surface_diffusion_3d.prm --set "Output/Directory=/tmp/mcost/$v" --set "Mesh refinement/Maximum level=2" --set "Time/Maximum steps=4" --set "Output/Metrics interval=1" --set "Output/Field formats=none" > /tmp/mcost/$v.log 2>&1
  echo "$v exit $?"
done
