#!/bin/bash
# usage: run.sh NAME "ML settings" [--set ENTRY=VALUE ...]
# One variant of amg_variants.csv: 8 spheres like the 154, 1 rank, STEPS
# steps (default 2), output in archive/amg_8_coupled/NAME and NAME.log.
# The ML settings ("key=value;...") need the throw-away build that reads
# LEVELSINTER_AMG (README.md); BIN chooses the binary (default build/).
name=$1; export LEVELSINTER_AMG="$2"
here=$(cd "$(dirname "$0")" && pwd)
cd "$here/../.."
/usr/bin/time -v ${BIN:-./build/levelsinter} --overwrite \
  parameter_files/packing_154_coupled_3d.prm \
  --set "Domain/Upper corner=0.6,0.6,0.6" --set "Domain/Subdivisions=2,2,2" \
  --set "Geometry/Particle file=$PWD/archive/memory_8_coupled/packing_8.csv" \
  --set "Time/Maximum steps=${STEPS:-2}" --set "Output/Metrics interval=1" \
  --set "Output/Field formats=none" --set "Output/Directory=$here/$name" \
  "${@:3}" > "$here/$name.log" 2>&1
