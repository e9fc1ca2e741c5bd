#!/bin/bash
# 8 spheres made like the 154 (the coupled_packing_8_3d CI guard of
# tests/coupled_3d.cmake run to t = 0.005 s), with an elastic solver
# tolerance TOL and an elastic solve interval INTERVAL, 1 rank.
# usage: run.sh LEVELSINTER TOL INTERVAL OUTPUT_DIRECTORY
# (session 20: the tol1e-*_interval1 runs with 9f9bab5 + c4cdcf7 and the
# scene's tolerance set by --set; the interval2 runs with the build that
# added `Elastic solve interval`; 1e-6 was the scene's tolerance then.)
root=$(cd "$(dirname "$0")/../../../.." && pwd)
"$1" --overwrite \
  --set "Domain/Upper corner=0.6,0.6,0.6" --set "Domain/Subdivisions=2,2,2" \
  --set "Geometry/Particle file=$root/parameter_files/packing_8_like_154_3d.csv" \
  --set "Time/End time=0.005" --set "Output/Metrics interval=1" \
  --set "Output/Field formats=none" --set "Viscous flow/Solver tolerance=$2" \
  --set "Volume diffusion/Elastic solve interval=$3" \
  --set "Output/Directory=$4" \
  "$root/parameter_files/packing_154_coupled_3d.prm"
