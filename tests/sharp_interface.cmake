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
