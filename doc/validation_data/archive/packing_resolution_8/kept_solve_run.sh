#!/bin/bash
# VD solve kept for shortened steps: old (study19, 7890ab4) vs new (build) on 8 spheres like the 154, CFL 2
which=$1   # old | new
if [ $which = old ]; then export LD_LIBRARY_PATH=/work/perf/study19; B=/work/perf/study19/levelsinter; else B=/work/main/build/levelsinter; fi
/usr/bin/time -v $B --overwrite /work/main/parameter_files/packing_154_coupled_3d.prm \
  --set "Domain/Upper corner=0.6,0.6,0.6" --set "Domain/Subdivisions=2,2,2" \
  --set "Geometry/Particle file=/work/main/parameter_files/packing_8_like_154_3d.csv" \
  --set "Time/CFL number=2" --set "Mesh refinement/Band width=0.048" --set "Time/End time=0.005" \
  --set "Output/Metrics interval=1" --set "Output/Field formats=none" --set "Output/Directory=/work/reuse/$which" > $which.log 2> $which.time
