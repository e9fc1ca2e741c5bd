#!/bin/bash
# The 154-particle coupled packing for 6 steps, 2 ranks, frozen session-20 build, the scene as
# in main (elastic tolerance 1e-4): the cost per step and phase.
export LD_LIBRARY_PATH=/work/perf/study20b
exec /usr/bin/time -v mpirun --allow-run-as-root -np 2 -x LD_LIBRARY_PATH /work/perf/study20b/levelsinter --overwrite \
  --set "Output/Directory=${OUT:-out}" --set "Time/Maximum steps=6" \
  --set "Output/Field formats=none" "$@" \
  $(cd "$(dirname "$0")/../../../.." && pwd)/parameter_files/packing_154_coupled_3d.prm
