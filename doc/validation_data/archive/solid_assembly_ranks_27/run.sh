#!/bin/bash
# The 27 spheres like the 154 with packing_154_coupled_3d.prm as of
# session 24 (CFL 1.5), 3 steps, 1 and 2 ranks on idle cores, each rank
# under `perf record -e cpu-clock -F 200`; build 8c1d120 (the elastic
# set-up timed apart). The *_profile_top60.txt files: samples per
# symbol (perf report --sort symbol -F overhead,sample,sym), 200 a second.
M=/work/main
for np in 1 2; do
/usr/bin/time -v mpirun --allow-run-as-root -np $np sh -c "exec perf record -e cpu-clock -F 200 -o perf27_np$np.\$OMPI_COMM_WORLD_RANK.data levelsinter --overwrite \
  --set 'Domain/Upper corner=0.9,0.9,0.9' --set 'Domain/Subdivisions=3,3,3' \
  --set 'Geometry/Particle file=$M/parameter_files/packing_27_like_154_3d.csv' \
  --set 'Time/Maximum steps=3' --set 'Output/Field formats=none' --set 'Output/Metrics interval=100' \
  --set 'Output/Directory=perf27_np$np' \
  $M/parameter_files/packing_154_coupled_3d.prm" > perf27_np$np.log 2> perf27_np$np.time
done
