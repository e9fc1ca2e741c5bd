#!/bin/bash
# Single trials of the perturbed elastic cylinder (the case of ctest
# volume_diffusion_cylinder_mode2_2d: R = 0.25, h = 1/128, Table 7 moduli)
# by volume diffusion, 20 steps of a fixed dt* with the mechanism's own
# limit off, for the gradient, pressure space and lambda of each trial;
# one row per trial in doc/validation_data/archive/sharp_vd_recovered_gradient_2d.csv
# (the driver's columns and the case). doc/validation.md, "Sharp
# interfaces: a recovered gradient for xi".
# usage: scripts/vd_gradient_trials.sh BUILD_DIR OUT.csv
set -e
build=$1; out=$2; source_dir=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "case,gradient,pressure,lambda,$(echo mode,level,h,steps,dt,max_dofs,rate,exact_rate,rate_error,volume_change,mean_iterations,mean_solve_cpu,wall_time,cpu_time,max_amplitude_ratio)" > "$out"
trial() {
  local gradient=$1 pressure=$2 lambda=$3 dt=$4
  local fraction
  fraction=$(python3 -c "print(20 * $dt * 5.294117647058823)")
  (cd "$work" && "$build/tests/surface_diffusion_validation" mullins \
    "$source_dir/parameter_files/perturbed_circle_2d.prm" 5 20 \
    --time-fraction "$fraction" --filter-thickness 0.12 --band-width 0.118 \
    --set "Surface diffusion/Enabled=false" \
    --set "Volume diffusion/Enabled=true" \
    --set "Volume diffusion/Coefficient=0.013" \
    --set "Volume diffusion/Interior offset=$lambda" \
    --set "Volume diffusion/Pressure gradient=$gradient" \
    --set "Volume diffusion/Time unit=reduced" \
    --set "Volume diffusion/Reference radius=0.25" \
    --set "Volume diffusion/Time step factor=0" \
    --set "Viscous flow/Pressure space=$pressure" \
    --set "Materials/Surface tension=0.9" \
    --set "Materials/Fluid viscosity=1e-3" \
    --set "Materials/Fluid compressibility=0" \
    --set "Viscous flow/Stabilisation constant=0.1" \
    --set "Viscous flow/Linear solver=iterative" \
    --set "Phase law/Law=elastic-solid" --set "Phase law/Shear modulus=156e3" \
    --set "Phase law/Bulk modulus=390e3" \
    --set "Mesh refinement/Minimum level=3" --csv trial.csv > /dev/null)
  echo "${gradient}_${pressure}_lambda${lambda}_dt${dt},$gradient,$pressure,$lambda,$(tail -1 "$work/trial.csv")" >> "$out"
}
# lambda = 0 is given as 0.01 (the nodal gradient refuses 0).
trial nodal continuous 0.01 1e-6
trial recovered continuous 0.01 1e-6
trial nodal extended 0.01 1e-6
trial recovered extended 0.01 1e-6
trial recovered continuous 1 1e-6
trial recovered continuous 3 1e-5
trial nodal extended 3 1e-5
trial recovered extended 3 1e-5
trial recovered extended 3 1e-4
trial recovered extended 3 3e-4
