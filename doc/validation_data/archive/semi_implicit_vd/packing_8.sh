#!/bin/bash
# packing_8.sh OUTDIR [--set ...]: the 8 spheres made like the 154 (coupled_packing_8_3d,
# every setting of packing_154_coupled_3d.prm) to t = 0.005 s, 1 rank, with the build of
# commit ade075e in build/ (it has 'Volume diffusion/Semi-implicit stabilisation', removed
# after this measurement), e.g. packing_8.sh b3_cfl05 --set "Volume diffusion/Semi-implicit stabilisation=3".
out=$1; shift
root=$(cd "$(dirname "$0")/../../../.." && pwd)
mkdir -p $out
/usr/bin/time -v $root/build/levelsinter --overwrite \
  --set "Domain/Upper corner=0.6,0.6,0.6" --set "Domain/Subdivisions=2,2,2" \
  --set "Geometry/Particle file=$root/parameter_files/packing_8_like_154_3d.csv" \
  --set "Time/End time=0.005" --set "Output/Metrics interval=1" \
  --set "Output/Field formats=none" \
  --set "Output/Directory=$out" "$@" \
  "$root/parameter_files/packing_154_coupled_3d.prm" > $out.log 2>&1
