# --- Sharp interfaces: the extended pressure (issue 27) ---------------------
# 'Viscous flow/Pressure space = extended' (ExtendedPressureStokes,
# doc/numerics.md and doc/validation.md, "Sharp interfaces"). Each CI check
# runs the continuous form's CI case with the extended pressure; its limits
# are ~15-20 % above the extended form's measured value and well below the
# continuous form's, so losing the jump fails them.
set(SHARP_EXTENDED --set "Viscous flow/Pressure space=extended")
set(SHARP_SCENES ${CMAKE_SOURCE_DIR}/parameter_files)

# Elastic inclusion, the case of mechanics_elastic_inclusion_2d (uniform
# R/h = 6.4, 12.8; 3 steps), on 1 and 2 ranks, at eta_f/(G dt) = 1e-3 and
# 1e-5 (at 1e-7 the fluid's errors fall to 1e-10, the solver's tolerance,
# where the two rank counts cannot agree to 1e-7; its solid error is 0.00805).
# Measured at R/h = 12.8, worst step and ratio: L2 error of p in the
# solid 0.00809 (continuous: 0.113), fluid 1.63e-4 (0.035), fluid
# undershoot 9.7e-4 of p_in (ratio 1e-3; 3e-5 at 1e-5), drift of the
# solid's mean p 5.1e-4 (2.2 %), FGMRES 35-41 (24-27). The two rank counts
# agree to 1e-9 (iterations aside: the AMG differs): limit 1e-7.
ranks_test(sharp_elastic_inclusion_2d COMMAND ${INCLUSION}
  ${SHARP_SCENES}/elastic_inclusion_2d.prm 3,4 --steps 3
  --ratios 1e-3,1e-5 ${SHARP_EXTENDED}
  --max-l2-in 0.0095 --max-l2-out 2e-4 --max-undershoot 1.2e-3
  --max-drift 1e-3 --max-its 48 --csv sharp_elastic_inclusion_np@np@.csv
  AGREE sharp_elastic_inclusion_np@np@.csv 1e-7 iterations)
set_tests_properties(sharp_elastic_inclusion_2d_np1
  sharp_elastic_inclusion_2d_np2 PROPERTIES
  RESOURCE_LOCK elastic_inclusion_output)

# The same in 3D: elastic sphere, one octant, R/h = 6.4, 2 steps (the case
# of mechanics_elastic_inclusion_3d). Measured: L2 error of p in the solid
# 0.0133 (continuous 0.193), fluid 1.57e-6 (0.0284), undershoot 1.73e-5
# (1.4e-3), mean p in the solid 9.0497 against 2 gamma / R = 9 (8.08),
# drift 1.1e-5, FGMRES 37-38 (27).
add_test(NAME sharp_elastic_inclusion_3d COMMAND ${INCLUSION}
  ${SHARP_SCENES}/elastic_inclusion_3d.prm 3 --steps 2 ${SHARP_EXTENDED}
  --max-l2-in 0.016 --max-l2-out 2e-6 --max-undershoot 2.1e-5
  --max-drift 1e-4 --max-its 44)
set_tests_properties(sharp_elastic_inclusion_3d PROPERTIES
  RESOURCE_LOCK elastic_inclusion_output)

# Static bubble, one solve at h = 1/64 (R/h = 12.8), sharp tensorial form.
# Measured: mean pressure-jump error 4.77e-3 (continuous 3.38e-2), C =
# v_max eta / gamma 1.82e-3 (9.9e-3).
add_test(NAME sharp_static_bubble_2d COMMAND ${VISCOUS} bubble
  ${VISCOUS_SCENES}/static_bubble_2d.prm 4 sharp ${SHARP_EXTENDED}
  --max-pressure-error 0.0058 --max-C 0.0022)

# Static bubble over 50 steps at R/h = 8 without the volume correction (the
# case of bubble_over_time_sharp_2d). Measured: area change +7.8e-5 after 50
# steps, 1.6e-6 a step (continuous: -5.8e-2, 1.2e-3 a step; the aim is
# 1e-5 a step); C 3.0e-3 at the first step, falling to 6.0e-4. Limits:
# area 1e-4 (2e-6 a step), C never above the first step's.
add_test(NAME sharp_bubble_over_time_2d COMMAND ${VISCOUS} bubble-time
  ${BUBBLE_TIME} 3 --set "Time/Maximum steps=50"
  --set "Viscous flow/Surface tension form=sharp" ${SHARP_EXTENDED}
  --max-C-growth 1.01 --max-area-drift 1e-4)
set_tests_properties(sharp_bubble_over_time_2d PROPERTIES
  RESOURCE_LOCK bubble_time_output)

# Viscous mode 2 of a cylinder at R/h = 32 over a quarter of an e-folding
# time in 32 steps (exact rate n gamma / (2 eta R) = 4). Measured: rate
# error -7.3e-4 (continuous +1.21e-2), area change 5.1e-5 (continuous
# -1.5e-3). The step's own error is O(s dt / 2) = 0.2 %: limit 3e-3.
add_test(NAME sharp_cylinder_mode2_2d COMMAND ${SD_VALIDATE} mullins
  ${SHARP_SCENES}/perturbed_cylinder_viscous_2d.prm 5 32 --mode 2
  --time-fraction 0.25 ${SHARP_EXTENDED} --max-rate-error 3e-3
  --max-volume-change 1.5e-4)

# Volume diffusion with the extended pressure: the elastic displacement
# travels across mesh changes and through a checkpoint as with the
# continuous pressure (restart_two_grains_vd_*; same limits).
restart_test(sharp_restart_two_grains_vd_np1_np1
  ${SHARP_SCENES}/two_grains_volume_diffusion_2d.prm 1 1
  5e-6 "${RESTART_VD_IGNORED}" ${RESTART_VD_ARGS} ${SHARP_EXTENDED})
restart_test(sharp_restart_two_grains_vd_np1_np2
  ${SHARP_SCENES}/two_grains_volume_diffusion_2d.prm 1 2
  5e-6 "${RESTART_VD_IGNORED};cells;dofs" ${RESTART_VD_ARGS}
  ${SHARP_EXTENDED})

# What the extended pressure refuses, each with the entry named.
bad_input_test(extended_direct_solver "Viscous flow/Linear solver"
  ${SHARP_EXTENDED} --set "Viscous flow/Linear solver=direct"
  ${SHARP_SCENES}/static_bubble_2d.prm)
bad_input_test(extended_csf "Viscous flow/Surface tension form"
  ${SHARP_EXTENDED} --set "Viscous flow/Surface tension form=csf"
  ${SHARP_SCENES}/static_bubble_2d.prm)
bad_input_test(extended_viscoelastic "Viscous flow/Pressure space"
  ${SHARP_EXTENDED} ${SHARP_SCENES}/viscoelastic_pair_circles_2d.prm)

# Studies behind doc/validation.md, "Sharp interfaces" (validation-long):
# both pressure spaces side by side.
foreach(space continuous extended)
  set(space_arg --set "Viscous flow/Pressure space=${space}")
  add_test(NAME study_sharp_elastic_inclusion_${space}_2d COMMAND ${INCLUSION}
    ${SHARP_SCENES}/elastic_inclusion_2d.prm 4,5,6,7 --min-level 3 --steps 2
    ${space_arg} --csv sharp_elastic_inclusion_${space}_2d.csv)
  add_test(NAME study_sharp_cylinder_mode2_${space}_2d COMMAND ${SD_VALIDATE}
    mullins ${SHARP_SCENES}/perturbed_cylinder_viscous_2d.prm 4,5,6 128
    --mode 2 --time-fraction 0.5 ${space_arg}
    --csv sharp_cylinder_mode2_${space}_2d.csv)
  add_test(NAME study_sharp_bubble_${space}_2d COMMAND ${VISCOUS} bubble
    ${VISCOUS_SCENES}/static_bubble_2d.prm 3,4,5,6 sharp ${space_arg}
    --csv sharp_bubble_${space}_2d.csv)
  add_test(NAME study_sharp_bubble_time_${space}_2d COMMAND ${VISCOUS}
    bubble-time ${BUBBLE_TIME} 3 --set "Time/Maximum steps=50"
    --set "Viscous flow/Surface tension form=sharp" ${space_arg}
    --csv sharp_bubble_time_${space}_2d.csv)
  set_tests_properties(study_sharp_elastic_inclusion_${space}_2d
    study_sharp_cylinder_mode2_${space}_2d study_sharp_bubble_${space}_2d
    study_sharp_bubble_time_${space}_2d PROPERTIES LABELS validation-long)
  set_tests_properties(study_sharp_elastic_inclusion_${space}_2d PROPERTIES
    RESOURCE_LOCK elastic_inclusion_output)
  set_tests_properties(study_sharp_bubble_time_${space}_2d PROPERTIES
    RESOURCE_LOCK bubble_time_output)
endforeach()

# --- Issue 27, second increment (doc/validation.md, "Sharp interfaces:
# balanced force, shape modes, volume diffusion") -----------------------------

# Balanced force: the sharp-curvature form (gamma kappa n on alpha_h = 0)
# with the exact kappa = 1/R and the extended pressure holds the static
# bubble at rest to the solver tolerance. Measured at h = 1/64 (finest of
# the two), FGMRES to 1e-10: C = 6.6e-10, jump error 9.0e-10 (h = 1/128:
# 2.7e-8 / 4.4e-8, falling to 2.4e-11 / 6.8e-11 with the tolerance 1e-12;
# the same load with the continuous pressure: C 6.8e-3; the smeared
# balanced force csf-curvature: C 1.1e-10 but jump error 4.8e-2). Limits
# 1e-7: above the tolerance's noise, 1000x below the computed curvature's
# C (1.0e-4). 1 and 2 ranks each meet them.
ranks_test(sharp_static_bubble_balanced_2d COMMAND ${VISCOUS} bubble
  ${VISCOUS_SCENES}/static_bubble_2d.prm 3,4 sharp-curvature-exact
  ${SHARP_EXTENDED} --max-pressure-error 1e-7 --max-C 1e-7)
# The same on a sphere (axisymmetric, 2 gamma / R), h = 1/64. Measured: C
# 5.0e-9, jump error 1.3e-9.
add_test(NAME sharp_static_sphere_balanced_axisymmetric COMMAND ${VISCOUS}
  bubble ${VISCOUS_SCENES}/static_sphere_axisymmetric.prm 4
  sharp-curvature-exact ${SHARP_EXTENDED} --max-pressure-error 1e-7
  --max-C 1e-7)
# With the curvature projected from the level set, h = 1/64. Measured:
# jump error 1.55e-5 (continuous csf-curvature: 4.8e-2), C 1.02e-4 (9.9e-5),
# both second order in h (doc/validation.md). Limits 20 % above.
add_test(NAME sharp_static_bubble_curvature_2d COMMAND ${VISCOUS} bubble
  ${VISCOUS_SCENES}/static_bubble_2d.prm 4 sharp-curvature ${SHARP_EXTENDED}
  --max-pressure-error 1.9e-5 --max-C 1.25e-4)

# Viscous mode 3 of a cylinder, the case of sharp_cylinder_mode2_2d (R/h =
# 32, a quarter of an e-folding in 32 steps; exact rate 3 gamma / (2 eta R)
# = 6). Measured: rate error -8.3e-3, area change 3.7e-5 (continuous over
# half an e-folding: -1.8e-3). The rate alone cannot tell the spaces apart
# at this resolution (continuous +0.9 %, doc/validation.md), the area can:
# limits 1e-2 and 4.5e-5.
add_test(NAME sharp_cylinder_mode3_2d COMMAND ${SD_VALIDATE} mullins
  ${SHARP_SCENES}/perturbed_cylinder_viscous_2d.prm 5 32 --mode 3
  --time-fraction 0.25 ${SHARP_EXTENDED} --max-rate-error 1e-2
  --max-volume-change 4.5e-5)
# Viscous mode 2 of a sphere (axisymmetric, exact rate 20/19 gamma / (eta
# R)), R/h = 32, a quarter of an e-folding in 32 steps, +delta and -delta.
# Measured: rate error +3.4e-3 (the step's own s dt / 2 is +3.9e-3), area
# change 8.1e-5 (continuous: +2.6e-2 and -4.3e-3). Limits 4.5e-3 and 1e-4.
add_test(NAME sharp_sphere_mode2_axisymmetric COMMAND ${SD_VALIDATE} mullins
  ${SHARP_SCENES}/perturbed_sphere_viscous_axisymmetric.prm 5 32 --mode 2
  --time-fraction 0.25 --signs 2 ${SHARP_EXTENDED} --max-rate-error 4.5e-3
  --max-volume-change 1e-4)
# The mullins driver names its output by dimension, mode, level and steps:
# the cylinder's mode-2 runs write the same directories.
set_tests_properties(sharp_sphere_mode2_axisymmetric sharp_cylinder_mode2_2d
  PROPERTIES RESOURCE_LOCK sharp_mode2_output)

# Studies behind doc/validation.md, "Sharp interfaces: balanced force, shape
# modes, volume diffusion" (validation-long).
add_test(NAME study_sharp_bubble_balanced_extended_2d COMMAND ${VISCOUS}
  bubble ${VISCOUS_SCENES}/static_bubble_2d.prm 3,4,5,6
  sharp-curvature-exact,sharp-curvature ${SHARP_EXTENDED}
  --csv sharp_bubble_balanced_extended_2d.csv)
add_test(NAME study_sharp_bubble_balanced_continuous_2d COMMAND ${VISCOUS}
  bubble ${VISCOUS_SCENES}/static_bubble_2d.prm 3,4,5,6
  csf-curvature-exact,sharp-curvature-exact
  --csv sharp_bubble_balanced_continuous_2d.csv)
add_test(NAME study_sharp_sphere_balanced_extended_axisymmetric
  COMMAND ${VISCOUS} bubble ${VISCOUS_SCENES}/static_sphere_axisymmetric.prm
  4,5 sharp-curvature-exact,sharp-curvature ${SHARP_EXTENDED}
  --csv sharp_sphere_balanced_extended_axisymmetric.csv)
set(SHARP_STUDIES study_sharp_bubble_balanced_extended_2d
  study_sharp_bubble_balanced_continuous_2d
  study_sharp_sphere_balanced_extended_axisymmetric)
# Shape modes, half an e-folding in 128 steps at R/h = 16, 32, 64; mode 4
# and the sphere with +delta and -delta (--signs 2).
set(SHARP_SPHERE
  ${SHARP_SCENES}/perturbed_sphere_viscous_axisymmetric.prm)
foreach(space continuous extended)
  set(space_arg --set "Viscous flow/Pressure space=${space}")
  set(modes_args ${SHARP_SCENES}/perturbed_cylinder_viscous_2d.prm 4,5,6 128
    --time-fraction 0.5 ${space_arg})
  add_test(NAME study_sharp_cylinder_mode3_${space}_2d COMMAND ${SD_VALIDATE}
    mullins ${modes_args} --mode 3 --csv sharp_cylinder_mode3_${space}_2d.csv)
  add_test(NAME study_sharp_cylinder_mode4_${space}_2d COMMAND ${SD_VALIDATE}
    mullins ${modes_args} --mode 4 --signs 2
    --csv sharp_cylinder_mode4_${space}_2d.csv)
  add_test(NAME study_sharp_cylinder_mode4_one_sign_${space}_2d
    COMMAND ${SD_VALIDATE} mullins ${modes_args} --mode 4
    --csv sharp_cylinder_mode4_one_sign_${space}_2d.csv)
  add_test(NAME study_sharp_sphere_mode2_${space}_axisymmetric
    COMMAND ${SD_VALIDATE} mullins ${SHARP_SPHERE} 4,5,6 128 --mode 2
    --time-fraction 0.5 --signs 2 ${space_arg}
    --csv sharp_sphere_mode2_${space}_axisymmetric.csv)
  # Both write the +delta runs' output directories.
  set_tests_properties(study_sharp_cylinder_mode4_${space}_2d
    study_sharp_cylinder_mode4_one_sign_${space}_2d PROPERTIES
    RESOURCE_LOCK sharp_mode4_${space}_output)
  set_tests_properties(study_sharp_sphere_mode2_${space}_axisymmetric
    study_sharp_cylinder_mode2_${space}_2d PROPERTIES
    RESOURCE_LOCK sharp_mode2_${space}_output)
  list(APPEND SHARP_STUDIES study_sharp_cylinder_mode3_${space}_2d
    study_sharp_cylinder_mode4_${space}_2d
    study_sharp_cylinder_mode4_one_sign_${space}_2d
    study_sharp_sphere_mode2_${space}_axisymmetric)
endforeach()
# Two grains by volume diffusion with the extended pressure, xi read
# lambda = 6 cells deep, to t* = 0.029: R/h = 12.8, 25.6, 51.2, filter and
# band scaled with h as study_vd_neck_R0.2_level*_2d (the continuous form).
foreach(level_e_band "4;0.24;0.236" "5;0.12;0.118" "6;0.06;0.059")
  list(GET level_e_band 0 level)
  list(GET level_e_band 1 filter)
  list(GET level_e_band 2 band)
  add_test(NAME study_sharp_vd_neck_l${level}_lambda6_2d COMMAND ${SD_VALIDATE}
    neck ${VD_GRAINS} 2000 --sample-interval 1 ${SHARP_EXTENDED}
    --set "Mesh refinement/Maximum level=${level}"
    --set "Level set/Filter thickness=${filter}"
    --set "Mesh refinement/Band width=${band}" --set "Time/End time=0.02"
    --csv sharp_vd_neck_l${level}_lambda6_2d.csv)
  list(APPEND SHARP_STUDIES study_sharp_vd_neck_l${level}_lambda6_2d)
endforeach()
set_tests_properties(${SHARP_STUDIES} PROPERTIES LABELS validation-long)

# --- Issue 27, third increment: a pore that closes (doc/validation.md,
# "Sharp interfaces: a pore that closes") ------------------------------------
# The hollow cylinder (hollow_cylinder_2d.prm in a box of 0.6, so that
# a0 / h = 8 at level 4) with the extended pressure and the small-pore rule
# below one cell ('Viscous flow/Pore closure radius = 1'), to t = 0.3 (the
# exact closing time is 0.2196): the case of
# study_sharp_hole_closing_extended_rule_2d at this level. Measured: closing
# time 0.22058, +0.44 % (the rule's neglect of the load term adds +0.62 %,
# scripts/hollow_cylinder_closing.py); without the rule the hole stalls
# below a cell and does not close by t = 0.3 (NaN fails); mean
# inner-radius rate -0.11 %. The closing time moves with the steps (to
# t = 0.24: +1.04 %; doc/validation.md). Limits: the aim, 1 %, and 0.5 %.
# The 1 vs 2 ranks check is sharp_hole_closing_ranks_2d below.
ranks_test(sharp_hole_closing_2d RANKS 1 COMMAND ${SHAPES} hollow ${HOLLOW} 4
  --set "Domain/Upper corner=0.6, 0.6" --set "Time/End time=0.3"
  ${SHARP_EXTENDED} --set "Viscous flow/Pore closure radius=1"
  --max-closing-error 0.01 --max-rate-error 0.005)
# The driver writes shapes_output/hollow_level4 (as the study does).
set_tests_properties(sharp_hole_closing_2d_np1 PROPERTIES
  RESOURCE_LOCK hollow_output)
# The study behind it (validation-long): a0 / h = 4, 8, 16 to t = 0.3, the
# extended pressure with and without the rule and the continuous one.
foreach(case_args
    "extended_rule;${SHARP_EXTENDED};--set;Viscous flow/Pore closure radius=1"
    "extended;${SHARP_EXTENDED}"
    "continuous;--set;Viscous flow/Pressure space=continuous")
  list(GET case_args 0 case)
  list(REMOVE_AT case_args 0)
  add_test(NAME study_sharp_hole_closing_${case}_2d COMMAND ${SHAPES} hollow
    ${HOLLOW} 3,4,5 --set "Domain/Upper corner=0.6, 0.6"
    --set "Time/End time=0.3" ${case_args}
    --csv ${CMAKE_SOURCE_DIR}/doc/validation_data/sharp_hole_closing_${case}_2d.csv)
  set_tests_properties(study_sharp_hole_closing_${case}_2d PROPERTIES
    LABELS validation-long RESOURCE_LOCK hollow_output)
endforeach()

# --- Issue 27, fourth increment -----------------------------------------------
# The extended pressure on 2 ranks: the case of sharp_hole_closing_2d_np1
# (a0 / h = 8, the rule on, closed at t = 0.22) in levelsinter, every step's
# metrics on 1 and 2 ranks. It has what the static cases lack: symmetry
# planes (constrained velocities on the ghost penalty's faces, which stopped
# the 2-rank run at t = 0 before), hanging nodes, adaptation and the pore
# search across ranks. Measured: all 27 steps agree to 3e-7 (volume_change,
# a difference; pore_closure_volume 4.5e-9, the rest below 1e-9), the
# transport's and Stokes' iterations aside: limit 1e-6.
ranks_agree(sharp_hole_closing_ranks_2d sharp_hole_closing_ranks
  ${HOLLOW} 1e-6 "transport_iterations;stokes_iterations"
  --set "Domain/Upper corner=0.6, 0.6" --set "Time/End time=0.3"
  --set "Mesh refinement/Maximum level=4"
  --set "Mesh refinement/Band width=0.1125"
  --set "Level set/Filter thickness=0.15" --set "Output/Metrics interval=1"
  ${SHARP_EXTENDED} --set "Viscous flow/Pore closure radius=1")
# Hopper from two circles overlapping at x0 = 0.05 R (doc/validation.md,
# "Sharp interfaces: two ranks, the rule's cost"): two_cylinders_2d.prm
# (R/h = 20, k curvature levels) started from the circles at t = 0, to
# t gamma/(eta R) = 0.5 + tau0; neck errors at tau = 0.05, 0.1, 0.2, 0.5.
set(HOPPER_CIRCLES_005 --circle-start 1 --set "Geometry/Shape=particles"
  --set "Geometry/Particles=-0.24968730444297724, 0, 0.25\; 0.24968730444297724, 0, 0.25"
  --set "Time/Start time=0" --set "Time/End time=0.125")
foreach(case_args "continuous_k4;--set;Viscous flow/Pressure space=continuous"
    "extended_k4;${SHARP_EXTENDED}"
    "continuous_k6;--set;Mesh refinement/Curvature refinement levels=6"
    "extended_k6;--set;Mesh refinement/Curvature refinement levels=6;${SHARP_EXTENDED}")
  list(GET case_args 0 case)
  list(REMOVE_AT case_args 0)
  add_test(NAME study_sharp_hopper_circles_${case}_2d COMMAND ${VISCOUS} hopper
    ${VISCOUS_SCENES}/two_cylinders_2d.prm 5 ${HOPPER_CIRCLES_005} ${case_args}
    --csv ${CMAKE_SOURCE_DIR}/doc/validation_data/sharp_hopper_circles_${case}_2d.csv)
  set_tests_properties(study_sharp_hopper_circles_${case}_2d PROPERTIES
    LABELS validation-long RESOURCE_LOCK viscous_hopper_output)
endforeach()

# --- Issue 27, sixth increment (doc/validation.md, "Sharp interfaces: what
# limited modes 3-4") ----------------------------------------------------------

# Viscous mode 4 of a cylinder at R/h = 32 with the solid's interior one
# level coarser than the band (--coarse-levels 1; the studies above use 3,
# which leaves 4 cells per radius inside and made modes 3-4 1-2 % slow).
# A quarter of an e-folding in 32 steps (exact rate 2 gamma / (eta R) = 8).
# Measured: rate error +3.4e-3 (the step's own s dt / 2 is +3.9e-3; the
# velocity alone -1.9e-3), 3 coarse levels -9.7e-3 (velocity -1.5e-2).
# Limit 6e-3: the old mesh rule fails it.
add_test(NAME sharp_cylinder_mode4_resolved_2d COMMAND ${SD_VALIDATE} mullins
  ${SHARP_SCENES}/perturbed_cylinder_viscous_2d.prm 5 32 --mode 4
  --time-fraction 0.25 --coarse-levels 1 ${SHARP_EXTENDED}
  --max-rate-error 6e-3)
