#!/bin/bash
# cylinder_study.sh BUILD LAMBDA BETA START: largest stable dt* of the perturbed elastic
# cylinder (volume_diffusion_cylinder_mode2_2d's settings, h = 1/128) with the semi-implicit
# term, BUILD the build directory of commit ade075e (tests/surface_diffusion_validation).
B=$1; l=$2; b=$3; start=$4
$(cd "$(dirname "$0")/../../../.." && pwd)/scripts/largest_stable_step.py $B/tests/surface_diffusion_validation \
  $(cd "$(dirname "$0")/../../../.." && pwd)/parameter_files/perturbed_circle_2d.prm --levels 5 --rate 5.294117647058823 \
  --scheme "si_l${l}_b${b}" --start $start --max-dt 0.1 \
  --filter-thickness 0.12 --band-width 0.118 \
  --set "Surface diffusion/Enabled=true" --set "Surface diffusion/Coefficient=1e-20" \
  --set "Surface diffusion/Time unit=seconds" \
  --set "Volume diffusion/Enabled=true" --set "Volume diffusion/Coefficient=0.013" \
  --set "Volume diffusion/Interior offset=$l" --set "Volume diffusion/Time unit=reduced" \
  --set "Volume diffusion/Reference radius=0.25" --set "Materials/Surface tension=0.9" \
  --set "Materials/Fluid viscosity=1e-3" --set "Materials/Fluid compressibility=0" \
  --set "Viscous flow/Stabilisation constant=0.1" --set "Viscous flow/Linear solver=iterative" \
  --set "Phase law/Law=elastic-solid" --set "Phase law/Shear modulus=156e3" \
  --set "Phase law/Bulk modulus=390e3" --set "Mesh refinement/Minimum level=3" \
  --set "Volume diffusion/Time step factor=0" \
  --set "Volume diffusion/Semi-implicit stabilisation=$b" \
  --csv si_l${l}_b${b}.csv
