#!/bin/bash
# The 154-grain coupled packing with Volume diffusion/Extrapolation =
# limited, frozen build bin_lim, NP ranks (1), metrics every 5th step (the scene),
# checkpoints every 20 min, to at most STEPS steps. RESUME=1 resumes.
cd /work/runs/s30
export LD_LIBRARY_PATH=/work/runs/s30/bin_lim
NP=${NP:-1}
if [ -n "$RESUME" ]; then
  exec mpirun --allow-run-as-root -np $NP /work/runs/s30/bin_lim/levelsinter --resume /work/runs/s30/p154_lim >> p154_lim.log 2>&1
fi
/usr/bin/time -v mpirun --allow-run-as-root -np $NP /work/runs/s30/bin_lim/levelsinter --overwrite /work/main/parameter_files/packing_154_coupled_3d.prm \
  --set "Volume diffusion/Extrapolation=limited" \
  --set "Time/Maximum steps=${STEPS:-40}" --set "Output/Field formats=none" \
  --set "Output/Checkpoint minutes=20" \
  --set "Output/Directory=/work/runs/s30/p154_lim" > p154_lim.log 2> p154_lim_time_v.txt
