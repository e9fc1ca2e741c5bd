#!/bin/bash
# The viscous shape modes' velocity on the initial interface, and the
# whole mode-3 run, with the solid's interior 3 / 1 / 0 levels coarser than
# the band (doc/validation.md, "Sharp interfaces: what limited modes 3-4").
# One step of 1e-3 e-folding times: velocity_rate_error is the rate the
# Stokes velocity stands for, before any transport.
#   scripts/sharp_mode_velocity.sh BUILD_DIR OUT_DIR
# writes OUT_DIR/sharp_mode_velocity_2d.csv (a case column first) and
# OUT_DIR/sharp_cylinder_mode3_resolved_2d.csv, and candidate_*.csv (the
# candidates tried first, sharp_cylinder_mode3_candidates_2d.csv).
set -e
build=$(realpath "$1")
mkdir -p "$2"
out=$(realpath "$2")
scenes=$(realpath "$(dirname "$0")/../parameter_files")
cd "$out"
run() { # case scene mode levels [options]
  local case=$1 scene=$2 mode=$3 levels=$4
  shift 4
  nice -n 10 "$build/tests/surface_diffusion_validation" mullins \
    "$scenes/$scene" "$levels" 1 --mode "$mode" --time-fraction 0.001 \
    --set "Viscous flow/Pressure space=extended" "$@" --csv "$case.tmp.csv"
  tail -n +2 "$case.tmp.csv" | sed "s/^/$case,/" >> sharp_mode_velocity_2d.csv
  rm "$case.tmp.csv"
}
cylinder=perturbed_cylinder_viscous_2d.prm
sphere=perturbed_sphere_viscous_axisymmetric.prm
rm -f sharp_mode_velocity_2d.csv
for mode in 2 3 4; do
  run cylinder_n${mode}_coarse3 $cylinder $mode 4,5,6,7
  run cylinder_n${mode}_coarse1 $cylinder $mode 4,5,6,7 --coarse-levels 1
done
run cylinder_n3_coarse0 $cylinder 3 4,5,6,7 --coarse-levels 0
run cylinder_n3_coarse1_delta1 $cylinder 3 5 --coarse-levels 1 \
  --set "Geometry/Perturbation amplitude=0.01"
run cylinder_n3_coarse1_delta1_eta1e-5 $cylinder 3 5 --coarse-levels 1 \
  --set "Geometry/Perturbation amplitude=0.01" \
  --set "Materials/Fluid viscosity=1e-5"
run sphere_n2_coarse3 $sphere 2 4,5,6 --signs 2
run sphere_n2_coarse1 $sphere 2 4,5,6 --signs 2 --coarse-levels 1
run sphere_n3_coarse3 $sphere 3 4,5,6
run sphere_n3_coarse1 $sphere 3 4,5,6 --coarse-levels 1
# The header once, with the case column.
header=$(nice -n 10 "$build/tests/surface_diffusion_validation" mullins \
  "$scenes/$cylinder" 4 1 --mode 2 --time-fraction 0.001 \
  --set "Viscous flow/Pressure space=extended" --csv header.tmp.csv \
  > /dev/null && head -1 header.tmp.csv)
rm header.tmp.csv
sed -i "1i case,$header" sharp_mode_velocity_2d.csv
# The whole mode-3 run, 128 steps over half an e-folding time.
nice -n 10 "$build/tests/surface_diffusion_validation" mullins \
  "$scenes/$cylinder" 4,5,6 128 --mode 3 --time-fraction 0.5 \
  --coarse-levels 1 --set "Viscous flow/Pressure space=extended" \
  --csv sharp_cylinder_mode3_resolved_2d.csv
# The candidates tried first (mode 3, R/h = 32, 3 coarse levels, the
# study's 128 steps over half an e-folding time); one CSV each.
candidate() { # name [options]
  local name=$1
  shift
  nice -n 10 "$build/tests/surface_diffusion_validation" mullins \
    "$scenes/$cylinder" 5 128 --mode 3 --time-fraction 0.5 \
    --set "Viscous flow/Pressure space=extended" "$@" \
    --csv "candidate_$name.csv"
}
candidate none
candidate stabilisation_0.01 --set "Viscous flow/Stabilisation constant=0.01"
candidate ghost_penalty_0.01 --set "Viscous flow/Ghost penalty=0.01"
candidate sharp_curvature \
  --set "Viscous flow/Surface tension form=sharp-curvature"
candidate delta_0.01 --set "Geometry/Perturbation amplitude=0.01"
candidate no_reinitialisation --set "Level set/Reinitialisation strength=0"
nice -n 10 "$build/tests/surface_diffusion_validation" mullins \
  "$scenes/$cylinder" 5 256 --mode 3 --time-fraction 0.5 \
  --set "Viscous flow/Pressure space=extended" --csv candidate_steps_256.csv
