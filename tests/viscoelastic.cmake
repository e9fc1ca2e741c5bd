# --- Viscoelastic melts: the conformation models (viscoelastic seed) ------
add_executable(conformation_models conformation_models.cc)
target_link_libraries(conformation_models levelsinter_lib)
deal_ii_setup_target(conformation_models)

# Closed forms in homogeneous flows, each in the direct and the
# log-conformation form; the limits are in the driver. RK4 at 1000 steps per
# relaxation time; measured errors: Oldroyd-B shear / extension 5e-15,
# Giesekus steady shear (eta, Psi1, Psi2 at Wi 0.1, 1, 10) 1.6e-11 direct,
# 1.8e-13 log, relaxation 2e-14; XPP linear limit 9.9e-7 (the O(Wi^2)
# nonlinearity at Wi = 1e-3, limit 1e-5); direct against log 5.5e-13
# (Giesekus) and 1.7e-13 (XPP) at Wi 5 in shear and 2 in extension.
foreach(form direct log)
  foreach(case shear-oldroyd extension-oldroyd shear-giesekus relax-giesekus
          linear-xpp)
    add_test(NAME conformation_${case}_${form}
      COMMAND conformation_models ${case} ${form})
  endforeach()
endforeach()
foreach(case forms-giesekus forms-xpp relax-step)
  add_test(NAME conformation_${case} COMMAND conformation_models ${case})
endforeach()

add_executable(conformation_field conformation_field.cc)
target_link_libraries(conformation_field levelsinter_study)
deal_ii_setup_target(conformation_field)

# The conformation field in a solid-body rotation (closed form in the
# driver's header): transport, upper-convected rotation and relaxation.
# Measured (max nodal error of c / amplitude, a quarter turn, Courant 0.5):
#   2D h = 1/8, 1/16, 1/32, 1/64: 0.219, 0.0309, 0.00308, 0.000460
#   (orders 2.82, 3.33, 2.74); 3D h = 1/4, 1/8, 1/16: 0.352, 0.219,
#   0.0309 (the 3D error equals the 2D one at the same h: the field does
#   not vary along the axis of rotation beyond the bump); GMRES <= 6 (ILU).
# CI limits about 1.5 x the measured error and orders 0.6 below (3D: 0.25
# below the pre-asymptotic 0.68 between the two coarsest meshes).
add_test(NAME conformation_rotation_2d
  COMMAND conformation_field 2 5,6 --max-error 5.7e-3 --min-order 2.5)
add_test(NAME conformation_rotation_3d
  COMMAND conformation_field 3 3,4 --max-error 0.35 --min-order 0.4)
# 1 and 2 ranks: GMRES to 1e-12 relative; the errors agree to all printed
# digits (measured); compared at 1e-8.
ranks_test(conformation_rotation_2d COMMAND $<TARGET_FILE:conformation_field>
  2 5,6 --csv conformation_rotation_np@np@.csv
  AGREE conformation_rotation_np@np@.csv 1e-8 max_gmres)
# The convergence study behind doc/validation.md.
add_test(NAME study_conformation_rotation_2d COMMAND conformation_field 2
  4,5,6,7 --csv ${CMAKE_SOURCE_DIR}/doc/validation_data/conformation_rotation_2d.csv)
add_test(NAME study_conformation_rotation_3d COMMAND conformation_field 3
  3,4,5 --csv ${CMAKE_SOURCE_DIR}/doc/validation_data/conformation_rotation_3d.csv)
set_tests_properties(study_conformation_rotation_2d study_conformation_rotation_3d
  PROPERTIES LABELS validation-long)

# The Newtonian limit through the application: Hopper's two cylinders
# (R/h = 20, fixed dt = 0.01 to t = 0.05) as a Newtonian melt of viscosity
# 1 and as a Giesekus melt with eta_s = 0.01, eta_p = 0.99 and lambda =
# 1e-6 (De = 4e-6): the implicit polymer stress gives the particles
# eta_s + eta_p dt / (lambda + dt) and the explicit part carries
# lambda / (lambda + dt) = 1e-4 of tau^n, so the runs must agree to about
# that. Measured with the CFL choosing the steps (different step sequences
# from the first one on): necks within 0.17-0.21 % to t = 0.1; with the
# fixed step the largest difference over all compared columns is 1.03e-4
# (measured). The
# velocity at t = 0 (dt = 0) is the melt's instantaneous response, limited
# by eta_s alone (100 times the Newtonian one here): max_velocity is not
# compared.
# add_newtonian_limit_check(SUFFIX SCENE OPTIONS...): the two runs of SCENE
# with OPTIONS and their comparison, viscoelastic_newtonian_*_SUFFIX.
function(add_newtonian_limit_check suffix scene)
  add_test(NAME viscoelastic_newtonian_reference_${suffix}
    COMMAND $<TARGET_FILE:levelsinter> ${ARGN}
      --set "Output/Directory=ve_newtonian_${suffix}" ${scene})
  add_test(NAME viscoelastic_newtonian_limit_${suffix}
    COMMAND $<TARGET_FILE:levelsinter> ${ARGN}
      --set "Output/Directory=ve_limit_${suffix}" --set "Phase law/Law=giesekus"
      --set "Viscous flow/Solid viscosity=0.01"
      --set "Phase law/Polymer viscosity=0.99"
      --set "Phase law/Relaxation time=1e-6" ${scene})
  set_tests_properties(viscoelastic_newtonian_reference_${suffix} PROPERTIES
    FIXTURES_SETUP ve_newtonian_${suffix})
  set_tests_properties(viscoelastic_newtonian_limit_${suffix} PROPERTIES
    FIXTURES_SETUP ve_limit_${suffix})
  add_test(NAME viscoelastic_newtonian_limit_agrees_${suffix}
    COMMAND compare_metrics ve_newtonian_${suffix}/metrics.csv
      ve_limit_${suffix}/metrics.csv 1e-3
      wall_time stokes_solve_cpu stokes_iterations transport_iterations
      max_velocity viscoelastic_iterations viscoelastic_max_trace_c
      neck_viscoelastic_trace_c)
  set_tests_properties(viscoelastic_newtonian_limit_agrees_${suffix}
    PROPERTIES FIXTURES_REQUIRED "ve_newtonian_${suffix};ve_limit_${suffix}")
endfunction()
add_newtonian_limit_check(2d ${VISCOUS_SCENES}/two_cylinders_circles_2d.prm
  --overwrite --set "Time/End time=0.05"
  --set "Time/Time step=0.01" --set "Time/CFL number=0"
  --set "Mesh refinement/Maximum level=5" --set "Mesh refinement/Band width=0.075"
  --set "Output/Field formats=none" --set "Output/Metrics interval=1")

# The seed's geometry at De = 1 (parameter_files/viscoelastic_cylinders_2d
# .prm), the first 5 steps: it runs, the neck grows (measured 0.476 ->
# 0.529 by t = 8.6e-4: the fast initial response over beta lambda = 0.01)
# and the polymer is stretched (max tr c 3 -> 3.44).
add_test(NAME viscoelastic_cylinders_2d
  COMMAND $<TARGET_FILE:levelsinter> --overwrite
    --set "Time/Maximum steps=5" --set "Output/Field formats=none"
    --set "Output/Metrics interval=1" --set "Output/Directory=ve_cylinders"
    ${CMAKE_SOURCE_DIR}/parameter_files/viscoelastic_cylinders_2d.prm)
set_tests_properties(viscoelastic_cylinders_2d PROPERTIES
  PASS_REGULAR_EXPRESSION "done: 5 steps")
# A viscoelastic law without the viscous flow it belongs to.
bad_input_test(viscoelastic_without_viscous_flow "Phase law/Law"
  --set "Viscous flow/Enabled=false"
  ${CMAKE_SOURCE_DIR}/parameter_files/viscoelastic_cylinders_2d.prm)
bad_input_test(viscoelastic_zero_relaxation_time "Phase law/Relaxation time"
  --set "Phase law/Relaxation time=0"
  ${CMAKE_SOURCE_DIR}/parameter_files/viscoelastic_cylinders_2d.prm)

# The De sweep behind doc/validation.md ("The De sweep"): the seed's
# geometry (R_n rounding) to t = 0.5 at R/h = 40 (the scene's band and
# filter, 9.6 and 12.8 cells) as a Newtonian melt of viscosity 1 and as
# Giesekus melts (alpha = 0.1, beta = 0.01) at De = 0.01, 0.1, 0.5, 1;
# De = 0.1 also at R/h = 20 and with half the steps (relative step, CFL and
# first step halved) for the convergence in h and dt. Neck radius, neck
# curvature, tr c at the neck against t in CSV.levelN.csv.
# The same runs on the spheres (viscoelastic_spheres_axisymmetric.prm) end
# in _axisymmetric.
function(add_viscoelastic_scene_sweep_run suffix scene name levels)
  add_test(NAME study_viscoelastic_sweep_${name}_${suffix}
    COMMAND ${VISCOUS} neck-history ${scene}
      ${levels} --band-cells 9.6 --filter-cells 12.8
      --set "Time/End time=0.5" ${ARGN}
      --csv ${CMAKE_SOURCE_DIR}/doc/validation_data/viscoelastic_sweep_${name}_${suffix}.csv)
  set_tests_properties(study_viscoelastic_sweep_${name}_${suffix} PROPERTIES
    LABELS validation-long
    FIXTURES_SETUP study_viscoelastic_sweep_${name}_${suffix})
endfunction()
# add_viscoelastic_sweep_plot(PNG "LABEL=RUN_SUFFIX:LEVEL;..." [--t-max T]):
# doc/validation_data/PNG from the runs' histories
# (scripts/plot_neck_history.py, run as its #! says: Debian's python3 has
# matplotlib).
function(add_viscoelastic_sweep_plot png curves)
  set(entries)
  set(fixtures)
  foreach(curve ${curves})
    string(REGEX MATCH "^(.*)=(.*):(.*)$" match "${curve}")
    list(APPEND entries
      "${CMAKE_MATCH_1}=${CMAKE_SOURCE_DIR}/doc/validation_data/viscoelastic_sweep_${CMAKE_MATCH_2}.csv.level${CMAKE_MATCH_3}.csv")
    list(APPEND fixtures study_viscoelastic_sweep_${CMAKE_MATCH_2})
  endforeach()
  add_test(NAME study_viscoelastic_plot_${png}
    COMMAND ${CMAKE_SOURCE_DIR}/scripts/plot_neck_history.py
      ${CMAKE_SOURCE_DIR}/doc/validation_data/${png}.png ${ARGN} ${entries})
  set_tests_properties(study_viscoelastic_plot_${png} PROPERTIES
    LABELS validation-long FIXTURES_REQUIRED "${fixtures}")
endfunction()
function(add_viscoelastic_sweep_run name levels)
  add_viscoelastic_scene_sweep_run(2d
    ${CMAKE_SOURCE_DIR}/parameter_files/viscoelastic_cylinders_2d.prm
    ${name} ${levels} ${ARGN})
endfunction()
add_viscoelastic_sweep_run(newtonian 6 --set "Phase law/Law=newtonian"
  --set "Viscous flow/Solid viscosity=1")
add_viscoelastic_sweep_run(de0.01 6 --set "Phase law/Relaxation time=0.01")
add_viscoelastic_sweep_run(de0.1 5,6 --set "Phase law/Relaxation time=0.1")
add_viscoelastic_sweep_run(de0.1_dt_half 6 --set "Phase law/Relaxation time=0.1"
  --set "Time/Time step=5e-4" --set "Time/Relative time step=0.025"
  --set "Time/CFL number=0.25")
add_viscoelastic_sweep_run(de0.5 6 --set "Phase law/Relaxation time=0.5")
add_viscoelastic_sweep_run(de1 6)

# --- The viscoelastic seed's own validation (Sect. 5, Eq. 44) -------------
# Hopper's cylinders with R = 1/sqrt(2), y_n = 0.075 from Hopper's exact
# shape, to t = 3.8375 (parameter_files/hopper_seed_validation_2d.prm); the
# Eq. 44 error over 23 equally spaced samples (column sampled_neck_error),
# as a Newtonian melt and as a Giesekus melt in the Newtonian limit
# (beta = 0.01, lambda = 1e-4: De = lambda gamma / (eta_0 R) = 1.4e-4),
# R/h = 19, 38, 75 (doc/validation.md, "The seed's validation").
set(SEED_HOPPER ${CMAKE_SOURCE_DIR}/parameter_files/hopper_seed_validation_2d.prm)
set(GIESEKUS_LIMIT --set "Phase law/Law=giesekus"
  --set "Viscous flow/Solid viscosity=0.01"
  --set "Phase law/Polymer viscosity=0.99"
  --set "Phase law/Relaxation time=1e-4")
add_test(NAME study_viscoelastic_seed_hopper_newtonian_2d COMMAND ${VISCOUS}
  hopper ${SEED_HOPPER} 5,6,7 --samples 23
  --csv ${CMAKE_SOURCE_DIR}/doc/validation_data/seed_hopper_newtonian_2d.csv)
add_test(NAME study_viscoelastic_seed_hopper_giesekus_2d COMMAND ${VISCOUS}
  hopper ${SEED_HOPPER} 5,6,7 --samples 23 ${GIESEKUS_LIMIT}
  --csv ${CMAKE_SOURCE_DIR}/doc/validation_data/seed_hopper_giesekus_2d.csv)
# The Newtonian melt with 2 curvature-refinement levels at the neck and the
# volume correction, band levels 5 and 6 (finest cells R/75 and R/151).
add_test(NAME study_viscoelastic_seed_hopper_newtonian_k2_vc_2d
  COMMAND ${VISCOUS} hopper ${SEED_HOPPER} 5,6 --samples 23
  --set "Mesh refinement/Curvature refinement levels=2"
  --set "Volume correction/Enabled=true"
  --csv ${CMAKE_SOURCE_DIR}/doc/validation_data/seed_hopper_newtonian_k2_vc_2d.csv)
set_tests_properties(study_viscoelastic_seed_hopper_newtonian_2d
  study_viscoelastic_seed_hopper_giesekus_2d
  study_viscoelastic_seed_hopper_newtonian_k2_vc_2d PROPERTIES
  LABELS validation-long RESOURCE_LOCK viscous_hopper_output)
# The same in CI, the Giesekus limit at R/h = 19 to t = 0.5: Eq. 44 over
# 23 samples measured 0.288 (the early neck, 2 cells wide, grows too
# slowly: the neck error at t gamma/(eta R) = 0.1 is 9.6 %), area drift
# 7.0e-3; limits 1.2 x those.
add_test(NAME viscoelastic_seed_hopper_2d COMMAND ${VISCOUS} hopper
  ${SEED_HOPPER} 5 --samples 23 --set "Time/End time=0.5" ${GIESEKUS_LIMIT}
  --max-sampled-neck-error 0.35 --max-area-drift 8.4e-3)
set_tests_properties(viscoelastic_seed_hopper_2d PROPERTIES
  RESOURCE_LOCK viscous_hopper_output)

# --- Stiff melt: De = 10, beta = 0.001 (doc/validation.md, "Stiff melt") --
# The seed's geometry at R/h = 20 to t = 0.01, the elastic jump of the neck
# (0.476 -> 1.293) over beta lambda = 0.01 with the semi-implicit surface
# tension: measured 42 steps, none rejected, largest tr c 21.4 (21.7
# before the atmosphere's c was left unstretched); limits: no rejected
# step, tr c below 30.
set(STIFF_MELT --set "Viscous flow/Solid viscosity=0.001"
  --set "Phase law/Polymer viscosity=0.999"
  --set "Phase law/Relaxation time=10")
add_test(NAME viscoelastic_stiff_2d COMMAND ${VISCOUS} neck-history
  ${CMAKE_SOURCE_DIR}/parameter_files/viscoelastic_cylinders_2d.prm 5
  --band-cells 9.6 --filter-cells 12.8 --set "Time/End time=0.01"
  ${STIFF_MELT} --max-rejected 0 --max-trace-c 30 --csv viscoelastic_stiff.csv)
# The study behind doc/validation.md: the same at R/h = 40 to t = 0.05.
add_test(NAME study_viscoelastic_stiff_2d COMMAND ${VISCOUS} neck-history
  ${CMAKE_SOURCE_DIR}/parameter_files/viscoelastic_cylinders_2d.prm 6
  --band-cells 9.6 --filter-cells 12.8 --set "Time/End time=0.05"
  ${STIFF_MELT}
  --csv ${CMAKE_SOURCE_DIR}/doc/validation_data/viscoelastic_stiff_2d.csv)
set_tests_properties(study_viscoelastic_stiff_2d PROPERTIES
  LABELS validation-long)
# The clear stop: the stiff melt at R/h = 20 with explicit surface tension
# and a fixed step of 4e-3, 80 times its capillary limit (no limit
# applied): the step from t = 0.0045 fails four times, down to 4.8e-4,
# and the run stops with the diagnosis, exit code 1 and a checkpoint of
# step 2 (measured, 1.4 s CPU).
bad_input_test(stiff_melt_stop "is in a checkpoint"
  --set "Time/End time=0.02" --set "Time/Time step=4e-3"
  --set "Time/Relative time step=0" --set "Time/CFL number=0"
  --set "Mesh refinement/Maximum level=5" --set "Mesh refinement/Band width=0.48"
  --set "Level set/Filter thickness=0.64" --set "Mesh refinement/Adapt interval=1"
  --set "Output/Field formats=none" ${STIFF_MELT}
  --set "Viscous flow/Surface tension time integration=explicit"
  --set "Viscous flow/Capillary time step factor=0"
  --set "Output/Directory=stop"
  ${CMAKE_SOURCE_DIR}/parameter_files/viscoelastic_cylinders_2d.prm)

# The alpha sweep at De = 1 (the seed's Figs. 16-17) and XPP (q = 2,
# xi = lambda / lambda_s = 2; Figs. 18-19) at De = 0.1 and 1, to t = 0.2
# (the largest tr c comes during the start-up), R/h = 40.
foreach(alpha 0.1875 0.275 0.3625 0.45)
  add_viscoelastic_sweep_run(alpha${alpha} 6
    --set "Phase law/Giesekus mobility=${alpha}" --set "Time/End time=0.2")
endforeach()
add_viscoelastic_sweep_run(xpp_de0.1 6 --set "Phase law/Law=xpp"
  --set "Phase law/Relaxation time=0.1"
  --set "Phase law/XPP stretch relaxation time=0.05" --set "Time/End time=0.2")
add_viscoelastic_sweep_run(xpp_de1 6 --set "Phase law/Law=xpp"
  --set "Phase law/XPP stretch relaxation time=0.5" --set "Time/End time=0.2")

# --- Axisymmetric spheres (the seed's own case) ----------------------------
# The hoop entries of the conformation equation and of the polymer stress
# (doc/numerics.md, "Axisymmetric scenes"). The uniaxial extension
# v = (-eps r / 2, eps z) with its steady Oldroyd-B conformation in closed
# form (driver header), c_thth = c_rr: measured max nodal error of c at
# h = 1/8, 1/16, 1/32, 1/64: 0.0454, 0.0132, 0.00352, 0.000904 (orders
# 1.78, 1.91, 1.96); without L_thth = v_r / r it stays at 0.198. Limits
# 1.5 x the measured error, order 0.4 below.
add_test(NAME conformation_extension_axisymmetric
  COMMAND conformation_field 2 5,6 --case axisymmetric-extension
    --max-error 5.3e-3 --min-order 1.5)
set(VE_SPHERES ${CMAKE_SOURCE_DIR}/parameter_files/viscoelastic_spheres_axisymmetric.prm)
# The Newtonian limit on two spheres (two_spheres_axisymmetric.prm, fixed
# dt = 0.01 to t = 0.1), as in 2D above: Giesekus with lambda = 1e-6
# against the Newtonian melt; measured largest difference 1.8e-4 (the
# explicit part lambda / (lambda + dt) = 1e-4 of tau^n), limit 1e-3.
add_newtonian_limit_check(axisymmetric
  ${CMAKE_SOURCE_DIR}/parameter_files/two_spheres_axisymmetric.prm
  --overwrite --set "Time/End time=0.1"
  --set "Time/Time step=0.01" --set "Time/CFL number=0"
  --set "Viscous flow/Capillary time step factor=0"
  --set "Output/Field formats=none" --set "Output/Metrics interval=1")
# The seed's spheres at De = 1, R/h = 20, to t = 0.02 (25 steps, about 1 s)
# on 1 and 2 ranks: every column but timings, iteration counts and the
# near-zero volume change and correction speed (values of 1e-6, equal to
# 1e-4 relative) agrees to 5.0e-8 (measured); limit 1e-6.
ranks_agree(viscoelastic_spheres_axisymmetric ve_spheres ${VE_SPHERES} 1e-6
  "stokes_iterations;transport_iterations;viscoelastic_iterations;volume_change;volume_correction_speed"
  --set "Time/End time=0.02" --set "Mesh refinement/Maximum level=5"
  --set "Mesh refinement/Band width=0.48"
  --set "Level set/Filter thickness=0.64" --set "Output/Metrics interval=1")
set_tests_properties(viscoelastic_spheres_axisymmetric_np1
  viscoelastic_spheres_axisymmetric_np2 PROPERTIES
  PASS_REGULAR_EXPRESSION "done: 25 steps")
# The De sweep on the seed's spheres (doc/validation.md, "Axisymmetric
# spheres: the seed's Figs. 5-13"), the cylinders' settings.
add_viscoelastic_scene_sweep_run(axisymmetric ${VE_SPHERES} newtonian 5,6,7,8
  --set "Phase law/Law=newtonian" --set "Viscous flow/Solid viscosity=1")
add_viscoelastic_scene_sweep_run(axisymmetric ${VE_SPHERES} de0.01 6
  --set "Phase law/Relaxation time=0.01")
add_viscoelastic_scene_sweep_run(axisymmetric ${VE_SPHERES} de0.1 5,6,7
  --set "Phase law/Relaxation time=0.1")
add_viscoelastic_scene_sweep_run(axisymmetric ${VE_SPHERES} de0.1_dt_half 6
  --set "Phase law/Relaxation time=0.1"
  --set "Time/Time step=5e-4" --set "Time/Relative time step=0.025"
  --set "Time/CFL number=0.25")
add_viscoelastic_scene_sweep_run(axisymmetric ${VE_SPHERES} de0.5 6
  --set "Phase law/Relaxation time=0.5")
add_viscoelastic_scene_sweep_run(axisymmetric ${VE_SPHERES} de1 5,6,7)
# The same spheres in 3D (an eighth) at R/h = 20, against the axisymmetric
# run's level 5.
add_viscoelastic_scene_sweep_run(3d
  ${CMAKE_SOURCE_DIR}/parameter_files/viscoelastic_spheres_3d.prm de1 5)
add_viscoelastic_scene_sweep_run(3d
  ${CMAKE_SOURCE_DIR}/parameter_files/viscoelastic_spheres_3d.prm newtonian 5
  --set "Phase law/Law=newtonian" --set "Viscous flow/Solid viscosity=1")

# The plots of doc/validation.md's viscoelastic sections.
add_viscoelastic_sweep_plot(viscoelastic_sweep_2d
  "Newtonian=newtonian_2d:6;De = 0.01=de0.01_2d:6;De = 0.1=de0.1_2d:6;De = 0.5=de0.5_2d:6;De = 1=de1_2d:6")
add_viscoelastic_sweep_plot(viscoelastic_alpha_xpp_2d
  "alpha = 0.1=de1_2d:6;alpha = 0.1875=alpha0.1875_2d:6;alpha = 0.275=alpha0.275_2d:6;alpha = 0.3625=alpha0.3625_2d:6;alpha = 0.45=alpha0.45_2d:6;XPP De = 0.1=xpp_de0.1_2d:6;XPP De = 1=xpp_de1_2d:6"
  --t-max 0.2)
add_viscoelastic_sweep_plot(viscoelastic_sweep_axisymmetric
  "Newtonian (R/h 160)=newtonian_axisymmetric:8;De = 0.01=de0.01_axisymmetric:6;De = 0.1 (R/h 80)=de0.1_axisymmetric:7;De = 0.5=de0.5_axisymmetric:6;De = 1 (R/h 80)=de1_axisymmetric:7")
