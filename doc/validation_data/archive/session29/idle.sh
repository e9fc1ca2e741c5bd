#!/bin/bash
# The idle-window measurements of session 29, one after the other.
cd /work/runs/s29
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
{
echo "== hw: one process on core 0"; taskset -c 0 hw/hw
echo "== hw: two processes, cores 0 and 1"; taskset -c 0 hw/hw & taskset -c 1 hw/hw; wait
echo "== hw: one process on core 1"; taskset -c 1 hw/hw
} > hw.txt 2>&1
# two spheres (3D, coupled), 2 ranks, weights alternating, 8 steps
for rep in 1 2; do
  for w in "1, 1, 1" "1, 3, 7"; do
    tag=$(echo $w | tr -d ' ,')
    mpirun -np 2 -x LD_LIBRARY_PATH=/work/runs/s29/bin_new2 bin_new2/levelsinter --overwrite \
      /work/main/parameter_files/two_spheres_coupled_3d.prm --set "Time/Maximum steps=8" \
      --set "Output/Field formats=none" --set "Mesh refinement/Partition weights=$w" \
      --set "Output/Directory=/work/runs/s29/tsw_${tag}_$rep" > tsw_${tag}_$rep.log 2>&1
  done
done
BIN=bin_new2 NP=2 NAME=r154_new_np2 ./run154.sh
echo IDLE_DONE > idle_done.txt
