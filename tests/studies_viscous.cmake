# Studies of viscous flow behind doc/validation.md ("Viscous flow"). Label
# validation-long, not in CI; each writes the CSV named by --csv (the hopper
# and spheres modes also CSV.levelN.csv, the neck against time).
add_test(NAME study_viscous_bubble_2d COMMAND ${VISCOUS} bubble
  ${VISCOUS_SCENES}/static_bubble_2d.prm 3,4,5,6
  sharp,csf,csf-curvature,csf-curvature-exact --csv viscous_bubble_2d.csv)
add_test(NAME study_viscous_bubble_narrow_2d COMMAND ${VISCOUS} bubble
  ${VISCOUS_SCENES}/static_bubble_2d.prm 3,4,5,6
  csf-curvature,csf-curvature-exact
  --set "Viscous flow/Interface half width=0.5"
  --csv viscous_bubble_narrow_2d.csv)
add_test(NAME study_viscous_hopper_2d COMMAND ${VISCOUS} hopper
  ${VISCOUS_SCENES}/two_cylinders_circles_2d.prm 4,5,6 --csv viscous_hopper_2d.csv)
# Semi-implicit surface tension at 10x the explicit capillary limit against
# the explicit form at the limit (fixed dt both), to t gamma/(eta R) = 2.06.
add_test(NAME study_viscous_hopper_semi_implicit_2d COMMAND ${VISCOUS} hopper
  ${VISCOUS_SCENES}/two_cylinders_circles_2d.prm 4,5,6 --dt-factor 10
  --set "Viscous flow/Surface tension time integration=semi-implicit"
  --csv viscous_hopper_semi_implicit_2d.csv)
add_test(NAME study_viscous_hopper_explicit_fixed_dt_2d COMMAND ${VISCOUS}
  hopper ${VISCOUS_SCENES}/two_cylinders_circles_2d.prm 4,5,6 --dt-factor 1
  --csv viscous_hopper_explicit_fixed_dt_2d.csv)
# Work-precision: the same levels at a half and a double time step (CFL
# 0.25 and 1; the scene's is 0.5). At CFL 1 the band must hold the 5 * 1
# cells the interface may move between adaptations plus one: 6.5 cells.
add_test(NAME study_viscous_hopper_cfl0.25_2d COMMAND ${VISCOUS} hopper
  ${VISCOUS_SCENES}/two_cylinders_circles_2d.prm 4,5,6 --set "Time/CFL number=0.25"
  --csv viscous_hopper_2d_cfl0.25.csv)
add_test(NAME study_viscous_hopper_cfl1_2d COMMAND ${VISCOUS} hopper
  ${VISCOUS_SCENES}/two_cylinders_circles_2d.prm 4,5,6 --set "Time/CFL number=1"
  --band-cells 6.5 --csv viscous_hopper_2d_cfl1.csv)
set_tests_properties(study_viscous_hopper_cfl0.25_2d
  study_viscous_hopper_cfl1_2d PROPERTIES LABELS validation-long)
# The closed pore with a stiffer and a softer atmosphere (doc/validation.md).
foreach(c 0.1 1 10)
  add_test(NAME study_viscous_closed_pore_c${c}_2d COMMAND ${VISCOUS} pore
    ${VISCOUS_SCENES}/closed_pore_2d.prm 5 --pore-half-width 0.15
    --band-cells 5.12 --filter-cells 6.4 --set "Time/End time=0.8" --set "Materials/Fluid compressibility=${c}"
    --csv closed_pore_2d_c${c}.csv)
  set_tests_properties(study_viscous_closed_pore_c${c}_2d PROPERTIES
    LABELS validation-long)
endforeach()
# FGMRES iterations against h and viscosity ratio (doc/validation.md,
# "Solver"): Hopper to t = 0.1 at R/h = 10, 20, 40, 80, 160.
foreach(ratio 1 1e-3 1e-6)
  add_test(NAME study_viscous_solver_ratio_${ratio}_2d COMMAND ${VISCOUS}
    hopper ${VISCOUS_SCENES}/two_cylinders_circles_2d.prm 4,5,6,7,8
    --set "Time/End time=0.1" --set "Materials/Fluid viscosity=${ratio}"
    --csv viscous_solver_ratio_${ratio}.csv)
  list(APPEND VISCOUS_STUDIES study_viscous_solver_ratio_${ratio}_2d)
endforeach()
# The first steps (to t = 0.02) at R/h = 10-320 (doc/validation.md,
# "Solver").
foreach(ratio 1 1e-6)
  add_test(NAME study_viscous_solver_t002_ratio_${ratio}_2d COMMAND ${VISCOUS}
    hopper ${VISCOUS_SCENES}/two_cylinders_circles_2d.prm 4,5,6,7,8,9
    --set "Time/End time=0.02" --set "Materials/Fluid viscosity=${ratio}"
    --csv viscous_solver_t002_ratio_${ratio}.csv)
  list(APPEND VISCOUS_STUDIES study_viscous_solver_t002_ratio_${ratio}_2d)
endforeach()
# The same with the semi-implicit surface tension at 1x and 10x the
# explicit capillary step, R/h = 10, 20, 40, to t = 0.5.
foreach(factor 1 10)
  add_test(NAME study_viscous_solver_semi_implicit_dt${factor}_2d
    COMMAND ${VISCOUS} hopper ${VISCOUS_SCENES}/two_cylinders_circles_2d.prm 4,5,6
    --dt-factor ${factor} --set "Time/End time=0.5"
    --set "Viscous flow/Surface tension time integration=semi-implicit"
    --csv viscous_solver_semi_implicit_dt${factor}.csv)
  list(APPEND VISCOUS_STUDIES study_viscous_solver_semi_implicit_dt${factor}_2d)
endforeach()
# The whole Hopper run at the stiff ratio 1e-6 and at 1e-3, R/h = 20.
foreach(ratio 1e-3 1e-6)
  add_test(NAME study_viscous_hopper_ratio_${ratio}_2d COMMAND ${VISCOUS}
    hopper ${VISCOUS_SCENES}/two_cylinders_circles_2d.prm 5
    --set "Materials/Fluid viscosity=${ratio}"
    --csv viscous_hopper_ratio_${ratio}.csv)
  list(APPEND VISCOUS_STUDIES study_viscous_hopper_ratio_${ratio}_2d)
endforeach()
# Two spheres to coalescence (eighth of the pair, capillary factor 0.5):
# R/h = 5 and 10 to t gamma/(eta a) = 8 with the volume correction, and to
# 5 without it (doc/validation.md, "Two spheres in 3D").
add_test(NAME study_viscous_spheres_3d_vc COMMAND ${VISCOUS} spheres ${SPHERES}
  3,4 ${SPHERES_VC} --set "Time/End time=2" --csv two_spheres_3d_vc.csv)
add_test(NAME study_viscous_spheres_3d_no_vc COMMAND ${VISCOUS} spheres
  ${VISCOUS_SCENES}/two_spheres_3d.prm 3,4 --band-cells 4 --filter-cells 6
  --set "Time/End time=1.25"
  --set "Viscous flow/Capillary time step factor=0.5"
  --csv two_spheres_3d_novc.csv)
# The same with curvature refinement ("With curvature refinement" there):
# 1 extra level at R/h = 5 and 10 and 2 at R/h = 5 to t gamma/(eta a) = 8,
# 2 at R/h = 10 to 2 (the early neck, the finest run of the study).
add_test(NAME study_viscous_spheres_3d_curvature_k1 COMMAND ${VISCOUS} spheres
  ${SPHERES} 3,4 ${SPHERES_VC} --set "Time/End time=2"
  --set "Mesh refinement/Curvature refinement levels=1"
  --csv two_spheres_3d_curvature_k1_symfix.csv)
add_test(NAME study_viscous_spheres_3d_curvature_k2 COMMAND ${VISCOUS} spheres
  ${SPHERES} 3 ${SPHERES_VC} --set "Time/End time=2"
  --set "Mesh refinement/Curvature refinement levels=2"
  --csv two_spheres_3d_curvature_k2.csv)
add_test(NAME study_viscous_spheres_3d_curvature_k2_early COMMAND ${VISCOUS}
  spheres ${SPHERES} 4 ${SPHERES_VC} --set "Time/End time=0.5"
  --set "Mesh refinement/Curvature refinement levels=2"
  --csv two_spheres_3d_curvature_k2_early.csv)
# The same in 3D: two spheres (eighth of the pair) at R/h = 5, 10, 20, the
# first steps (to t = 0.006), three viscosity ratios.
foreach(ratio 1 1e-3 1e-6)
  add_test(NAME study_viscous_solver_3d_ratio_${ratio} COMMAND ${VISCOUS}
    spheres ${SPHERES} 3,4,5 --set "Time/End time=0.006"
    --set "Materials/Fluid viscosity=${ratio}"
    --csv viscous_solver_3d_ratio_${ratio}.csv)
  list(APPEND SPHERES_STUDIES study_viscous_solver_3d_ratio_${ratio})
endforeach()
set_tests_properties(study_viscous_bubble_2d study_viscous_bubble_narrow_2d
  study_viscous_hopper_2d study_viscous_hopper_semi_implicit_2d
  study_viscous_hopper_explicit_fixed_dt_2d
  ${VISCOUS_STUDIES} study_viscous_spheres_3d_vc
  study_viscous_spheres_3d_no_vc study_viscous_spheres_3d_curvature_k1
  study_viscous_spheres_3d_curvature_k2
  study_viscous_spheres_3d_curvature_k2_early ${SPHERES_STUDIES} PROPERTIES
  LABELS validation-long)
# All spheres runs write viscous_validation_output/spheres_levelN.
set_tests_properties(study_viscous_spheres_3d_vc study_viscous_spheres_3d_no_vc
  study_viscous_spheres_3d_curvature_k1 study_viscous_spheres_3d_curvature_k2
  study_viscous_spheres_3d_curvature_k2_early ${SPHERES_STUDIES} PROPERTIES
  RESOURCE_LOCK viscous_spheres_output)
set_tests_properties(study_viscous_hopper_2d
  study_viscous_hopper_semi_implicit_2d
  study_viscous_hopper_explicit_fixed_dt_2d study_viscous_hopper_cfl0.25_2d
  study_viscous_hopper_cfl1_2d ${VISCOUS_STUDIES} PROPERTIES
  RESOURCE_LOCK viscous_hopper_output)


# Hopper's two cylinders at boundary-element accuracy (doc/validation.md):
# the default scene (Hopper's exact shape at t gamma/(eta R) = 0.2, R/h =
# 20 + 4 curvature levels, capillary step factor 2, CFL 1, volume
# correction) to t gamma/(eta R) = 2.06 on 2 ranks, the old default, and
# one change at a time for the error budget. Each writes
# doc/validation_data/hopper_accuracy_NAME.csv and its .level5/6.csv.
function(hopper_accuracy name scene level)
  add_test(NAME study_hopper_accuracy_${name}_2d COMMAND ${MPIRUN}
    ${MPIRUN_FLAGS} -np 2 ${VISCOUS} hopper ${VISCOUS_SCENES}/${scene}
    ${level} --samples 23 ${ARGN}
    --csv ${CMAKE_SOURCE_DIR}/doc/validation_data/hopper_accuracy_${name}.csv)
  set_tests_properties(study_hopper_accuracy_${name}_2d PROPERTIES
    LABELS validation-long RESOURCE_LOCK viscous_hopper_output)
endfunction()
hopper_accuracy(default two_cylinders_2d.prm 5)
hopper_accuracy(old_default two_cylinders_circles_2d.prm 6 --circle-start 1)
hopper_accuracy(circle_start two_cylinders_2d.prm 5 --circle-start 1
  --set "Geometry/Shape=particles")
hopper_accuracy(no_volume_correction two_cylinders_2d.prm 5
  --set "Volume correction/Enabled=false")
foreach(k 2 3)
  hopper_accuracy(k${k} two_cylinders_2d.prm 5
    --set "Mesh refinement/Curvature refinement levels=${k}")
endforeach()
hopper_accuracy(band40_k3 two_cylinders_2d.prm 6
  --set "Mesh refinement/Curvature refinement levels=3")
# Refined further, one way at a time: the band (R/h = 40 with the
# default's 4 levels) and the neck (5 levels), for the error budget.
hopper_accuracy(band40 two_cylinders_2d.prm 6)
hopper_accuracy(k5 two_cylinders_2d.prm 5
  --set "Mesh refinement/Curvature refinement levels=5")
# The atmosphere (Hopper's is a void): viscosity and compressibility.
hopper_accuracy(fluid_viscosity1e-6 two_cylinders_2d.prm 5
  --set "Materials/Fluid viscosity=1e-6")
foreach(c 0.1 10)
  hopper_accuracy(compressibility${c} two_cylinders_2d.prm 5
    --set "Materials/Fluid compressibility=${c}")
endforeach()
hopper_accuracy(capillary1_cfl0.5 two_cylinders_2d.prm 5
  --set "Viscous flow/Capillary time step factor=1"
  --set "Time/CFL number=0.5")
hopper_accuracy(capillary3_cfl1.5 two_cylinders_2d.prm 5
  --set "Viscous flow/Capillary time step factor=3"
  --set "Time/CFL number=1.5" --set "Mesh refinement/Adapt interval=1")
hopper_accuracy(semi_implicit_cfl1 two_cylinders_2d.prm 5
  --set "Viscous flow/Surface tension time integration=semi-implicit")
