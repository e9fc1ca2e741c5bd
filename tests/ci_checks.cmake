# The checks run in CI: each compares a measured value with an analytic or
# published one, or guards a measured value; the comment above a test says
# what it checks and why its limits.

# --- Geometry measurements on the discrete zero level set ----------------
# Q1 interpolation of a smooth interface is O(h^2): the limits sit 1.5-2x
# above the values measured at the finest level (doc/validation.md) and the
# observed order must be second.
add_test(NAME measures_circle_2d COMMAND ${VALIDATE} measures
  ${SCENES}/rotation_2d.prm "0.35,0.5,0.15" 4,5,6
  --max-volume-error 2e-4 --max-area-error 1e-4 --min-order 1.8 --min-area-order 1.8)
# Two overlapping circles. The neck is a concave corner of the union: the
# distance has a kink outside it (min(d1, d2)) and a cone inside it (the
# true depth to the junction points), and Q1 interpolates neither exactly,
# so the interface length converges more slowly than h^2 (doc/numerics.md).
# With the mid-plane on a grid line (x = 0.5) measured at levels 4-6:
# volume 1.4e-3, 3.3e-4, 9.4e-5; length 5.3e-3, 3.4e-3, 1.05e-3 (order
# 1.7 between the last two). Limits 2x the finest values.
add_test(NAME measures_two_circles_2d COMMAND ${VALIDATE} measures
  ${SCENES}/rotation_2d.prm "0.365,0.5,0.15; 0.635,0.5,0.15" 4,5,6
  --max-volume-error 2e-4 --max-area-error 2.1e-3 --min-order 1.8
  --min-area-order 1.4)
add_test(NAME measures_sphere_3d COMMAND ${VALIDATE} measures
  ${SCENES}/rotation_3d.prm "0.5,0.5,0.5,0.15" 3,4,5
  --max-volume-error 8e-3 --max-area-error 5e-3 --min-order 1.8 --min-area-order 1.8)
# Two spheres with the neck on the grid plane x = 0.5 (see the circles):
# measured volume 5.1e-3 (order 2.0), area 4.7e-3 (order 1.5) at level 5.
add_test(NAME measures_two_spheres_3d COMMAND ${VALIDATE} measures
  ${SCENES}/rotation_3d.prm "0.365,0.5,0.5,0.15; 0.635,0.5,0.5,0.15" 3,4,5
  --max-volume-error 8e-3 --max-area-error 7e-3 --min-order 1.8
  --min-area-order 1.3)

# --- Transport with convective reinitialisation -------------------------
# Translated there and back: limits 2x the finest measured values (volume
# 4.5e-4, shape 3.4e-5 at level 6).
add_test(NAME transport_translation_2d COMMAND ${VALIDATE} transport
  ${SCENES}/translation_2d.prm 4,5,6 --max-volume-error 1e-3 --max-shape-error 7e-5)
# Rotation and Zalesak (one revolution), limits 2x the values measured at
# level 5 (doc/validation.md): rotation volume 1.9e-3, shape 7.4e-4;
# Zalesak volume 9.8e-4, shape 1.6e-3.
add_test(NAME transport_rotation_2d COMMAND ${VALIDATE} transport
  ${SCENES}/rotation_2d.prm 4,5 --max-volume-error 4e-3 --max-shape-error 1.5e-3)
add_test(NAME transport_zalesak_2d COMMAND ${VALIDATE} transport
  ${SCENES}/zalesak_2d.prm 4,5 --max-volume-error 2e-3 --max-shape-error 3.2e-3)
# 3D at CI size is coarse (R/h = 2.4 and 4.8): a regression guard only.
add_test(NAME transport_translation_3d COMMAND ${VALIDATE} transport
  ${SCENES}/translation_3d.prm 3,4 --max-volume-error 4.5e-2 --max-shape-error 2.2e-3)

# --- Reinitialisation towards |grad alpha| = g(alpha) (Eq. 67) -----------
# From alpha = filter(2d) (rms deviation 0.86) 40 steps must bring the rms
# deviation below 0.1 (measured 0.054) and move alpha = 0 by less than
# 0.04 h (measured 0.018 h at h = 1/128). 400 steps show that it stays
# there (no grid-scale wiggles): measured rms 0.032, shift 0.039 h.
add_test(NAME reinitialisation_2d COMMAND ${VALIDATE} reinit
  ${SCENES}/rotation_2d.prm 4,5 --max-gradient-error 0.1 --max-shift 0.04)
add_test(NAME reinitialisation_long_2d COMMAND ${VALIDATE} reinit
  ${SCENES}/rotation_2d.prm 4 --steps 400 --max-gradient-error 0.065
  --max-shift 0.08)

# --- The application: 1 and 2 MPI ranks agree ---------------------------
# GMRES stops at 1e-10 relative residual with a block-Jacobi ILU that
# differs between 1 and 2 ranks. Those differences flip a few cells at the
# outer edge of the band (where the refine decision is a threshold), so the
# cell and DoF counts may differ by < 1 %; the geometry is measured on the
# interface, far from there, and agrees to 9e-6 (measured): checked at 2e-5.
# volume_change is a difference of nearly equal numbers; solid_volume is
# compared instead. The runs write their fields (hygiene.cmake plots them).
ranks_test(mpi_run COMMAND $<TARGET_FILE:levelsinter> --overwrite
  --set "Time/Maximum steps=40" --set "Output/Directory=mpi_np@np@"
  --set "Output/Field interval=20" ${SCENE}
  AGREE mpi_np@np@/metrics.csv 2e-5 transport_iterations cells dofs
  volume_change)

# --- Architecture: no folder includes a higher layer ---------------------
add_test(NAME architecture_layers
  COMMAND ${Python3_EXECUTABLE} ${CMAKE_SOURCE_DIR}/scripts/check_layers.py
    ${CMAKE_SOURCE_DIR})

# --- doc/validation.md traces to the tests -------------------------------
# Every CSV in doc/validation_data/ (outside archive/) is written by a
# registered test (its --csv argument), every PNG there is shown in
# doc/validation.md, and every data file, script and test the document
# names exists (the opening table's tests and sections too).
add_test(NAME validation_index
  COMMAND ${Python3_EXECUTABLE}
    ${CMAKE_SOURCE_DIR}/scripts/check_validation_index.py ${CMAKE_SOURCE_DIR}
    ${CMAKE_BINARY_DIR} ${CMAKE_CTEST_COMMAND})
# The time columns of the user guide's scene table are those of
# doc/validation_data/scene_times.csv (scripts/scene_times_table.py).
add_test(NAME scene_times_table
  COMMAND ${Python3_EXECUTABLE}
    ${CMAKE_SOURCE_DIR}/scripts/scene_times_table.py ${CMAKE_SOURCE_DIR}
    --check)
# A study does not replace a longer history there with a shorter one
# unless LEVELSINTER_REPLACE_SHORTER=1 (scripts/validation_data.py).
add_test(NAME validation_data_keeps_longer_history
  COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/validation_data_guard_test.sh
    ${CMAKE_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/validation_data_guard
    $<TARGET_FILE:pore_analysis>)

# --- Command line and bad input ------------------------------------------
add_test(NAME help COMMAND levelsinter --help)
set_tests_properties(help PROPERTIES PASS_REGULAR_EXPRESSION "Usage:")
add_test(NAME print_parameters COMMAND levelsinter --print-parameters)
set_tests_properties(print_parameters PROPERTIES
  PASS_REGULAR_EXPRESSION "Reinitialisation strength")
bad_input_test(unknown_entry "Particle radius" ${BAD}/unknown_entry.prm)
bad_input_test(out_of_range "Dimension" ${BAD}/out_of_range.prm)
bad_input_test(missing_scene "cannot be opened" ${BAD}/no_such_scene.prm)
bad_input_test(missing_particle_file "does_not_exist.csv" ${BAD}/missing_file.prm)
bad_input_test(malformed_particle_file "line 3" ${BAD}/malformed_file.prm)
bad_input_test(particle_outside "not inside the domain" ${BAD}/outside.prm)
bad_input_test(bad_override "Mesh refinement/No such entry"
  --set "Mesh refinement/No such entry=3" ${SCENE})
bad_input_test(unwritable_output "cannot be created or written"
  --set "Output/Directory=/proc/levelsinter_out" ${SCENE})
bad_input_test(bad_expression "Velocity/Expression" ${BAD}/bad_expression.prm)
# A band as wide as the filter would refine the whole box (every saturated
# node reads as distance E).
bad_input_test(band_as_wide_as_filter "smaller than Level set/Filter thickness"
  --set "Mesh refinement/Band width=0.05"
  ${CMAKE_SOURCE_DIR}/parameter_files/closed_pore_2d.prm)

# Volume correction 'auto': on with viscous flow under the sharp form (which
# loses solid area through the pressure stabilisation), off with the
# balanced csf-curvature form. The run's header lists the mechanisms.
set(CIRCLES ${CMAKE_SOURCE_DIR}/parameter_files/two_cylinders_circles_2d.prm)
add_test(NAME volume_correction_auto_sharp COMMAND levelsinter --overwrite
  --set "Volume correction/Enabled=auto" --set "Time/Maximum steps=1"
  --set "Output/Directory=volume_correction_auto_sharp"
  --set "Output/Field formats=none" ${CIRCLES})
set_tests_properties(volume_correction_auto_sharp PROPERTIES
  PASS_REGULAR_EXPRESSION "mechanisms: viscous flow, volume correction")
add_test(NAME volume_correction_auto_csf_curvature COMMAND levelsinter
  --overwrite
  --set "Volume correction/Enabled=auto" --set "Time/Maximum steps=1"
  --set "Viscous flow/Surface tension form=csf-curvature"
  --set "Output/Directory=volume_correction_auto_csf_curvature"
  --set "Output/Field formats=none" ${CIRCLES})
set_tests_properties(volume_correction_auto_csf_curvature PROPERTIES
  PASS_REGULAR_EXPRESSION "mechanisms: viscous flow\n"
  FAIL_REGULAR_EXPRESSION "volume correction")

# --- Step rejection ----------------------------------------------------------
# A step whose solver fails is retried with half the step: with at most 6
# GMRES iterations (the transport needs 6-7 at CFL 0.5) some steps fail and
# succeed at dt/2, and the run finishes. With 1 iteration every retry fails
# and the run stops with the diagnosis and exit code 1.
add_test(NAME step_retry COMMAND levelsinter --overwrite
  --set "Level set/Maximum solver iterations=6" --set "Time/Maximum steps=30"
  --set "Output/Directory=step_retry" --set "Output/Field formats=none"
  ${SCENE})
set_tests_properties(step_retry PROPERTIES
  PASS_REGULAR_EXPRESSION "retrying with dt.*done: 30 steps")
bad_input_test(step_failure "failed 4 times"
  --set "Level set/Maximum solver iterations=1" ${SCENE})
# A particle between the nodes of the coarse levels (centre (0.3125,
# 0.3125), the middle of a cell of 0.125 at Minimum level 1, R = 0.05, the
# nearest node 0.038 outside it) and a band of 0.02: no node sees it, the
# band is never found there, and the run must stop rather than run without
# it (with Minimum level = 3 the same scene runs).
bad_input_test(particle_missed_by_initial_mesh
  "the initial mesh missed particles: 4 of the 4 points"
  --set "Geometry/Particles=0.3125, 0.3125, 0.05"
  --set "Mesh refinement/Maximum level=6"
  --set "Mesh refinement/Band width=0.02"
  --set "Level set/Filter thickness=0.03"
  ${CMAKE_CURRENT_SOURCE_DIR}/scenes/translation_2d.prm)

# --- Viscous flow ------------------------------------------------------------
# Static bubble (paper Sect. 6.3.1), one solve per h and form, ASGS
# constant 0.1. The mean-pressure error is the smearing of the jump by the
# ASGS term and falls like h (doc/validation.md, "Viscous flow"); the limits
# sit ~20 % above the worst form measured at h = 1/128 (csf 2.5e-2, sharp
# C 4.9e-3), so a lost order or a wrong sign fails.
# The jump between the means over r < R/2 and r > 3R/2 (outside the
# smeared zone) converges at second order: measured 5.8e-4 (csf) and
# 1.5e-4 (sharp) at h = 1/128; limit 7e-4.
add_test(NAME viscous_static_bubble_2d COMMAND ${VISCOUS} bubble
  ${VISCOUS_SCENES}/static_bubble_2d.prm 3,4,5 sharp,csf
  --max-pressure-error 0.03 --max-C 0.006 --max-core-error 7e-4)
# The same on 2 ranks (h = 1/64; measured 4.9e-2 and 9.9e-3 on 1 and 2
# ranks alike): the numbers must not depend on the partition.
ranks_test(viscous_static_bubble_2d RANKS 2 COMMAND ${VISCOUS} bubble
  ${VISCOUS_SCENES}/static_bubble_2d.prm 3,4 sharp,csf
  --max-pressure-error 0.06 --max-C 0.012)
# Hopper's coalescence, first 0.1 time units (neck 0.1 R -> 0.5 R) at
# R/h = 20. Measured: max neck error 0.35 (the simulated neck lags in the
# first steps, where the neck is 2 cells wide, and keeps that time shift),
# area drift 0.40 %; both fall with h (study_viscous_hopper_2d). Limits
# ~15 % above the measured values.
# FGMRES iterations per step (eta_f/eta_s = 1e-3) with the preconditioner
# of doc/numerics.md ("Stokes preconditioner"): measured mean 23.4, max 24;
# limits ~20 % above, so a weaker preconditioner fails.
add_test(NAME viscous_hopper_2d COMMAND ${VISCOUS} hopper
  ${VISCOUS_SCENES}/two_cylinders_circles_2d.prm 5 --set "Time/End time=0.1"
  --max-neck-error 0.40 --max-area-drift 0.006
  --max-mean-stokes-its 30 --max-stokes-its 31)
# Volume correction (Eq. 113-116) on the whole Hopper run at R/h = 10:
# measured area drift 1.1e-5 and final neck error 0.052, against 2.9 % and
# 0.072 without it; the limits 1e-3 (what one step may lose) and 0.06 fail
# without the correction.
add_test(NAME viscous_hopper_volume_correction_2d COMMAND ${VISCOUS} hopper
  ${VISCOUS_SCENES}/two_cylinders_circles_2d.prm 4
  --set "Volume correction/Enabled=true"
  --max-area-drift 0.001 --max-final-neck-error 0.06)
# The iteration count must stay flat as h shrinks at the stiffest ratio
# eta_f/eta_s = 1e-6 (R/h = 10, 20, 40, to t = 0.1). Measured mean / max
# per step: 19.1 / 20, 24.6 / 26, 25.9 / 27; limits 35 / 38 (1.35x and
# 1.4x the R/h = 40 values).
add_test(NAME viscous_solver_ratio_1e-6_2d COMMAND ${VISCOUS} hopper
  ${VISCOUS_SCENES}/two_cylinders_circles_2d.prm 4,5,6 --set "Time/End time=0.1"
  --set "Materials/Fluid viscosity=1e-6"
  --max-mean-stokes-its 35 --max-stokes-its 38)
# The same at R/h = 80, first 13 steps (to t = 0.02), where ML's first
# coarse level (2 268 rows) is solved directly only with the 2D coarse
# size: measured 27.4 / 28. It also checks the phases on cells coarser than
# the band: a smoothing width that grows with those cells mixes solid
# viscosity into the far atmosphere and takes the count to 48.8 / 49.
# Limits 29.5 / 30 (~8 % above).
add_test(NAME viscous_solver_ratio_1e-6_r80_2d COMMAND ${VISCOUS} hopper
  ${VISCOUS_SCENES}/two_cylinders_circles_2d.prm 7 --set "Time/End time=0.02"
  --set "Materials/Fluid viscosity=1e-6"
  --max-mean-stokes-its 29.5 --max-stokes-its 30)
# Curvature refinement at the neck (doc/validation.md, "Curvature
# refinement near necks"): Hopper from y_n = 0.1 R at R/h = 10 to
# t = 0.1 (t gamma/(eta R) = 0.46) with 2 extra levels where the interface
# is sharply curved. Measured with the free rigid motion removed: final
# neck error 0.256 (0.370 without the extra levels); 186 cells above the
# band level after the first step, the farthest 0.86 R from the neck point
# (they fill the neck and the thin pore wedge above it). Limits: 0.3 on the
# neck error (between the two); at least 100 fine cells, and none 1 R or
# more from the neck, where the particles' round surface lies.
add_test(NAME viscous_hopper_curvature_refinement_2d COMMAND ${VISCOUS}
  hopper ${VISCOUS_SCENES}/two_cylinders_circles_2d.prm 4 --set "Time/End time=0.1"
  --set "Mesh refinement/Curvature refinement levels=2"
  --max-final-neck-error 0.3 --min-fine-cells 100
  --max-fine-cell-distance 1.0)
# The same on 2 ranks for the first 0.02 time units: the cells flagged on
# each rank's part of the mesh give the same refinement at the neck.
ranks_test(viscous_hopper_curvature_refinement_2d RANKS 2 COMMAND ${VISCOUS}
  hopper
  ${VISCOUS_SCENES}/two_cylinders_circles_2d.prm 4 --set "Time/End time=0.02"
  --set "Mesh refinement/Curvature refinement levels=2"
  --min-fine-cells 100 --max-fine-cell-distance 1.0)
# The application runs the viscous scene (10 steps) and writes the
# Stokes iteration column.
add_test(NAME viscous_scene_two_cylinders COMMAND $<TARGET_FILE:levelsinter>
  --overwrite --set "Time/Maximum steps=10" --set "Output/Directory=viscous_scene"
  --set "Output/Field formats=none" ${VISCOUS_SCENES}/two_cylinders_2d.prm)
set_tests_properties(viscous_scene_two_cylinders PROPERTIES
  PASS_REGULAR_EXPRESSION "step +10 ")

# Balanced force (csf-curvature, f = gamma kappa grad H_h, residual-
# consistent ASGS): with kappa = 1/R prescribed, (0, gamma kappa H_h) is the
# exact discrete solution, so C and the core pressure-jump error are at the
# FGMRES tolerance (1e-10): measured at h = 1/128 C 4.2e-11, core error
# 1.1e-10; limits ~20x above (the solver stops anywhere below 1e-10). The
# mean-pressure error (2.43e-2) is the representation of the jump by the
# continuous Q1 pressure across the transition zone E = 1.5 h, no solver
# error: limit 0.03.
add_test(NAME viscous_static_bubble_balanced_2d COMMAND ${VISCOUS} bubble
  ${VISCOUS_SCENES}/static_bubble_2d.prm 3,4,5 csf-curvature-exact
  --max-pressure-error 0.03 --max-C 1e-9 --max-core-error 2e-9)
# The same form with the curvature projected from the level set: the
# curvature error on alpha_h = 0 is second order (max 3.8e-4 at h = 1/128),
# C 2.9e-5, core error 1.4e-6; limits ~1.4x the measured values.
add_test(NAME viscous_static_bubble_curvature_2d COMMAND ${VISCOUS} bubble
  ${VISCOUS_SCENES}/static_bubble_2d.prm 3,4,5 csf-curvature
  --max-pressure-error 0.03 --max-C 4e-5 --max-core-error 2e-6
  --max-curvature-error 5.5e-4)
# On 2 ranks (h = 1/64; measured the same as on 1 rank to the printed 4
# digits: C 1.122e-4, curvature error 1.492e-3); limits ~1.4x.
ranks_test(viscous_static_bubble_curvature_2d RANKS 2 COMMAND ${VISCOUS}
  bubble
  ${VISCOUS_SCENES}/static_bubble_2d.prm 3,4 csf-curvature
  --max-C 1.6e-4 --max-curvature-error 2.1e-3)
# Semi-implicit surface tension at ten times the explicit capillary limit
# (dt = 10 eta h / gamma, R/h = 10, to t gamma/(eta R) = 10: 10 steps): no
# step is rejected. The explicit form at this dt raises the interface
# length and has its steps rejected (next test). Measured: 0 rejections,
# final neck error 0.119, area drift 8.9 % (the ASGS drift of this coarse
# mesh over the long run; the explicit run at its stable dt: 9.6 %);
# limit 10 %.
add_test(NAME viscous_hopper_semi_implicit_2d COMMAND ${VISCOUS} hopper
  ${VISCOUS_SCENES}/two_cylinders_circles_2d.prm 4 --dt-factor 10
  --set "Time/End time=2.5"
  --set "Viscous flow/Surface tension time integration=semi-implicit"
  --max-rejected 0 --max-area-drift 0.10)
# Explicit at the same dt: the energy check rejects the unstable steps and
# the retries at dt/2, dt/4 carry the run on (measured to t = 1: 12
# rejections in 11 steps, area drift 7.0 %, max neck error 0.580, from the
# first step, which is accepted; without the check the run loses 73 % of
# its area by t = 2.5). Limits ~1.13x the measured values.
add_test(NAME viscous_hopper_explicit_rejected_2d COMMAND ${VISCOUS} hopper
  ${VISCOUS_SCENES}/two_cylinders_circles_2d.prm 4 --dt-factor 10
  --set "Time/End time=1" --min-rejected 1 --max-area-drift 0.08
  --max-neck-error 0.65)

# The Stokes solution alone, on Hopper's exact shape at y_n = 0.2 R (R/h =
# 20 in the band, up to 10 extra levels at the neck where its curvature
# radius, 2.1e-3 R, spans fewer than 16 cells; one step of 1.25e-6): the
# neck point's speed against Hopper's dy_n/dt. Measured on 26 Nov 2026,
# with the mesh refined on the exact shape from the start: +0.82 % (16
# cells per curvature radius), +1.23 % (8), +2.19 % (4), +4.2 % with 6
# levels at 4 cells. The limit 1.5 % asks for the resolved meniscus. On 1
# and 2 ranks.
ranks_test(viscous_hopper_neck_speed_2d COMMAND ${VISCOUS} hopper
  ${VISCOUS_SCENES}/two_cylinders_circles_2d.prm 5
  --set "Geometry/Particles=-0.2449489743, 0, 0.25; 0.2449489743, 0, 0.25"
  --set "Mesh refinement/Curvature refinement levels=10"
  --set "Mesh refinement/Cells per curvature radius=16"
  --set "Time/End time=1.25e-6" --dt-factor 1e-4
  --max-initial-neck-speed-error 0.015)

# Hopper's two cylinders at boundary-element accuracy (doc/validation.md,
# "Hopper's two cylinders at boundary-element accuracy"): the default
# scene, from Hopper's exact shape at t gamma/(eta R) = 0.2 to 0.7 (t =
# 0.05 to 0.175, the scene's Start time being Hopper's; 155 steps, 11 s on
# 1 or 2 ranks). Measured on 26 Nov 2026: the
# largest relative neck error 0.00381 on 1 and 2 ranks, area drift
# 7.8e-8. Limits: 0.005, the issue's target at every time (30 % above the
# measured value; over the whole run the error is 0.82 % without the volume
# correction and 1.10 % with one curvature level less), and 1e-6 on the
# drift (the correction's level; without it 1.1 % over the whole run).
ranks_test(viscous_hopper_default_2d COMMAND ${VISCOUS} hopper
  ${VISCOUS_SCENES}/two_cylinders_2d.prm 5 --set "Time/End time=0.175"
  --max-neck-error-from-tau0.2 0.005 --max-area-drift 1e-6)
# The hopper mode writes and reads back viscous_validation_output/
# hopper_levelN/metrics.csv: runs of it must not overlap.
set_tests_properties(viscous_hopper_2d viscous_solver_ratio_1e-6_2d
  viscous_solver_ratio_1e-6_r80_2d
  viscous_hopper_volume_correction_2d viscous_hopper_semi_implicit_2d
  viscous_hopper_explicit_rejected_2d viscous_hopper_curvature_refinement_2d
  viscous_hopper_curvature_refinement_2d_np2 viscous_hopper_neck_speed_2d_np1
  viscous_hopper_neck_speed_2d_np2 viscous_hopper_default_2d_np1
  viscous_hopper_default_2d_np2
  PROPERTIES RESOURCE_LOCK viscous_hopper_output)

# The direct solver gives the same solution (measured at h = 1/32 with
# FGMRES: sharp 6.45e-2 / C 1.95e-2, csf 9.63e-2 / 6.1e-3); limits ~1.15x.
add_test(NAME viscous_static_bubble_2d_direct COMMAND ${VISCOUS} bubble
  ${VISCOUS_SCENES}/static_bubble_2d.prm 3 sharp,csf
  --set "Viscous flow/Solver=direct" --max-pressure-error 0.11 --max-C 0.023)
# 3D with two symmetry planes and one pinned mode: two steps run.
add_test(NAME viscous_scene_two_spheres_3d COMMAND $<TARGET_FILE:levelsinter>
  --overwrite --set "Mesh refinement/Maximum level=3" --set "Time/Maximum steps=2"
  --set "Output/Directory=viscous_scene_3d" --set "Output/Field formats=none"
  ${VISCOUS_SCENES}/two_spheres_3d.prm)
set_tests_properties(viscous_scene_two_spheres_3d PROPERTIES
  PASS_REGULAR_EXPRESSION "step +2 ")
# The same spheres with csf-curvature, 4 steps on 1 and 2 ranks: its
# redistanced level set gathers the interface points of every rank, in 3D
# too. Measured: the metrics agree to 2.3e-9 (not compared: times, the
# transport's iterations, volume_change and centre_distance_change,
# differences of nearly equal numbers). Limit 1e-7.
ranks_agree(viscous_two_spheres_csf_curvature_3d viscous_csf_3d
  ${VISCOUS_SCENES}/two_spheres_3d.prm 1e-7
  "transport_iterations;volume_change;centre_distance_change"
  --set "Mesh refinement/Maximum level=3"
  --set "Viscous flow/Surface tension form=csf-curvature"
  --set "Time/Maximum steps=4" --set "Output/Progress interval=0")
# Closed pore (closed_pore_2d.prm, h = 1/128, the scene's band 0.04 and
# filter thickness 0.05 as 5.12 and 6.4 cells): the pore between four
# cylinders closes (measured: below a hundredth of a finest cell at
# t = 0.538, 1.9e-5 of its initial 7.07e-3 left at t = 0.6) while the solid
# area drifts by 0.53 % (the ASGS transfer across the jump, first order in
# h, see Hopper). Limits: closed by t = 0.6, remnant 1e-4, drift 0.6 %.
add_test(NAME viscous_closed_pore_2d COMMAND ${VISCOUS} pore
  ${VISCOUS_SCENES}/closed_pore_2d.prm 5 --pore-half-width 0.15
  --band-cells 5.12 --filter-cells 6.4 --set "Time/End time=0.6"
  --max-closure-time 0.6 --max-pore-area-ratio 1e-4 --max-area-drift 0.006)
# Radii 1:4 (unequal_cylinders_2d.prm, a stiff case): the small cylinder is
# absorbed and the pair relaxes to one circle. At h = R1/6.4 to t = 1
# (measured: interface length 5.6e-5 above the circle of the same area,
# area drift 2.15 %; at h = R1/12.8: 2.7e-5 and 1.10 %, first order).
# Band 0.045 and filter thickness 0.05 (3.6 and 4 cells). Limits 2x and
# 1.4x those.
add_test(NAME viscous_unequal_cylinders_2d COMMAND ${VISCOUS} coalescence
  ${VISCOUS_SCENES}/unequal_cylinders_2d.prm 5 --band-cells 3.6
  --filter-cells 4 --set "Time/End time=1"
  --max-roundness-error 1.2e-4 --max-area-drift 0.03)
# Two spheres (eighth of the pair), R/h = 5, band 4 h, filter 6 h, 4 steps
# to t = 0.05. Measured: neck x 1.360, solid-volume drift 2.58 % (the ASGS
# transfer at this coarse h, first order in h), a mean of 24 FGMRES
# iterations per solve. Limits: the neck must grow by 25 %, drift 3.5 %,
# iterations 29 (~20 % above the measured count).
add_test(NAME viscous_two_spheres_3d COMMAND ${VISCOUS} spheres
  ${VISCOUS_SCENES}/two_spheres_3d.prm 3 --band-cells 4 --filter-cells 6
  --set "Time/End time=0.05" --min-neck-growth 1.25 --max-volume-drift 0.035
  --max-mean-stokes-its 29)
# Two spheres to one (eighth of the pair, R/h = 5, capillary factor 0.5,
# volume correction) to t gamma/(eta a) = 8: the coalesced sphere must have
# radius 2^(1/3) a. Measured: neck / a 1.2537 (0.50 % below 2^(1/3)), volume
# drift 1.8e-4, 80 steps, 11 s CPU (before v^c mirrored its normals on the
# planes: 1.2450, 1.19 %, 9.0e-4); without the correction the drift is
# 35 % by t gamma/(eta a) = 5 and the radius 15 % short. Limits: 2 %
# (the run is still 0.015 a from the end state), drift 2e-3.
add_test(NAME viscous_two_spheres_coalescence_3d COMMAND ${VISCOUS} spheres
  ${SPHERES} 3 ${SPHERES_VC} --set "Time/End time=2"
  --max-final-radius-error 0.02 --max-volume-drift 0.002)
# Two spheres with one level of curvature refinement (R/h = 5, 10 steps to
# t gamma/(eta a) = 0.52), on 1 and 2 ranks. At R/h = 5 the sphere itself
# reads as curved enough (sqrt(2) N_r h / a = 1.13 > 1), and the neck on
# the symmetry plane x = 0 is seen through the mirrored nodal normals.
# Measured (since the volume correction mirrors its normals on the planes,
# 26 Nov 2026): x/a at t gamma/(eta a) = 0.5 0.3332 with the extra level
# (4.0 s CPU on 1 rank), 0.3459 without it (before: 0.3414 and 0.3325; at
# R/h = 5 the neck is not in the asymptotic range, doc/validation.md "With
# curvature refinement"). Limit 0.3395, halfway: a run whose refinement
# does not take effect fails.
ranks_test(viscous_two_spheres_curvature_refinement_3d COMMAND ${VISCOUS}
  spheres ${SPHERES} 3 ${SPHERES_VC} --set "Time/End time=0.125"
  --set "Mesh refinement/Curvature refinement levels=1"
  --max-neck_tau0.5 0.3395)
# FGMRES count in 3D at R/h = 10, eta_f/eta_s = 1e-6, first 2 solves:
# measured 28 / 28. Limit 31: the count at R/h = 20 is 32.
add_test(NAME viscous_solver_3d_r10 COMMAND ${VISCOUS} spheres ${SPHERES} 4
  --set "Time/End time=0.006" --set "Materials/Fluid viscosity=1e-6"
  --max-mean-stokes-its 31)
# The spheres mode writes viscous_validation_output/spheres_levelN.
set_tests_properties(viscous_solver_3d_r10 viscous_two_spheres_3d
  viscous_two_spheres_coalescence_3d
  viscous_two_spheres_curvature_refinement_3d_np1
  viscous_two_spheres_curvature_refinement_3d_np2
  PROPERTIES RESOURCE_LOCK viscous_spheres_output)
# A symmetry plane the box does not have is refused, naming the entry.
bad_input_test(viscous_symmetry_plane "Viscous flow/Symmetry planes"
  --set "Viscous flow/Symmetry planes=z-" ${VISCOUS_SCENES}/two_cylinders_circles_2d.prm)
# A Stokes solve that does not converge stops the run with a diagnosis.
bad_input_test(viscous_no_convergence "FGMRES did not reach"
  --set "Viscous flow/Maximum solver iterations=2"
  ${VISCOUS_SCENES}/static_bubble_2d.prm)

# --- Surface diffusion (doc/validation.md, "Surface diffusion") ----------
# Mullins decay r = R(1 + delta cos n theta), one e-folding at h = 1/128,
# E = 0.047, with the rules of the user guide: refined band 0.8 E = 0.0375
# and (C_s dt)^(1/4) <= 0.8 E (n = 2: 160 steps; n = 3: 40 steps, 0.73 E).
# A wrong sign makes the mode grow (rate error > 100 %). Measured (doc/
# validation.md, "Band and rate, traced"): n = 2 rate error -2.1 %, area
# change +0.115 %; n = 3 -5.5 %, +0.034 %. Limits: n = 2 4 % (2x: with
# the band at 4 h the same run drifts to +3.6 % and +2.6 % area); n = 3
# 8 % (1.45x); area 0.3 % for both (2.6x n = 2's; the 4 h band reaches
# +1.0 % for n = 3).
add_test(NAME surface_diffusion_mullins_n2_2d COMMAND ${SD_VALIDATE} mullins
  ${PERTURBED} 5 160 --mode 2 --band-width 0.0375 --max-rate-error 0.04
  --max-volume-change 0.003)
add_test(NAME surface_diffusion_mullins_n3_2d COMMAND ${SD_VALIDATE} mullins
  ${PERTURBED} 5 40 --mode 3 --band-width 0.0375 --max-rate-error 0.08
  --max-volume-change 0.003)
# Two grains, 30 steps: measured neck 0.0461 -> 0.0603 (x 1.31) and area
# change -0.098 %; checked at x 1.2 (a reinitialisation diffusion by the
# plain Laplacian, which fills the concave neck, gives x 1.46) and 0.15 %.
add_test(NAME surface_diffusion_two_grains_2d COMMAND ${SD_VALIDATE} neck
  ${TWO_GRAINS} 30 --min-neck-growth 1.2 --max-volume-change 1.5e-3)
# The same with v^c (Eq. 113-116), which gives back at each step the area
# lost since t = 0: measured -1.8e-5 after 30 steps (without v^c the loss
# is 3.3e-5 per step), checked at 5e-5, i.e. about one step's uncorrected
# loss. The centres do not move: the centre distance read off the level
# set changes by 1.1e-5 d0 (0.0005 h); checked at 5e-5.
add_test(NAME surface_diffusion_two_grains_vc_2d COMMAND ${SD_VALIDATE} neck
  ${TWO_GRAINS} 30 --set "Volume correction/Enabled=true"
  --csv two_grains_vc.csv --min-neck-growth 1.2 --max-volume-change 5e-5
  --max-centre-shift 5e-5)
# Symmetry planes: the two grains on the whole box, on its half x >= 0.5
# (the neck on the plane x-) and its quarter (x-, y-: a plane through the
# centres too), 40 steps. The nodal normals of the kappa / v_s solver and
# of v^c are mirrored on the planes; before they were, the half's neck
# shrank (0.0461 -> 0.0439 at t = 0.04, against 0.0631 on the whole box).
# The neck curvature's parabola fit mirrors the sections beyond a plane
# through the neck (before: 2.26 on the half box against 164.0).
# Measured: the intensive columns agree to 2.9e-9 (neck), 1.5e-8 (volume
# change), 4.6e-8 (max velocity), 2.6e-8 in all; checked at 1e-6. Not compared: what
# scales with the box (volume, area, cells, dofs, its extent), timings,
# the interior coordination number (not reported on the quarter).
set(SYMMETRY_IGNORED cells dofs solid_volume interface_area wall_time
  under_resolved_curvature_cells surface_diffusion_solve_cpu_time size_ratio_x
  interior_coordination_number)
foreach(spec "full:0,0:4,4:" "half:0.5,0:2,4:x-" "quarter:0.5,0.5:2,2:x-,y-")
  string(REPLACE ":" ";" spec "${spec}")
  list(GET spec 0 part)
  list(GET spec 1 lower)
  list(GET spec 2 subdivisions)
  list(GET spec 3 planes)
  add_test(NAME surface_diffusion_symmetry_${part}_2d COMMAND levelsinter
    --overwrite --set "Time/Maximum steps=40"
    --set "Domain/Lower corner=${lower}"
    --set "Domain/Subdivisions=${subdivisions}"
    --set "Domain/Symmetry planes=${planes}"
    --set "Output/Metrics interval=10" --set "Output/Field formats=none"
    --set "Output/Progress interval=0"
    --set "Output/Directory=sd_symmetry_${part}" ${TWO_GRAINS})
  set_tests_properties(surface_diffusion_symmetry_${part}_2d PROPERTIES
    FIXTURES_SETUP sd_symmetry_${part})
endforeach()
foreach(part half quarter)
  add_test(NAME surface_diffusion_symmetry_${part}_vs_full_2d
    COMMAND compare_metrics sd_symmetry_full/metrics.csv
    sd_symmetry_${part}/metrics.csv 1e-6 ${SYMMETRY_IGNORED})
  set_tests_properties(surface_diffusion_symmetry_${part}_vs_full_2d
    PROPERTIES FIXTURES_REQUIRED "sd_symmetry_full;sd_symmetry_${part}")
endforeach()
# Unequal grains R1 = 0.1, R2 = 0.2, 30 steps (t* = 9.5e-5). The neck is
# found on the narrowest cross-section: at t = 0 it lies 0.0094 Rbar from
# the plane where the circles meet (the Q1 interface's narrowest chord sits
# on a grid line, at most h/2 = 0.029 Rbar away); checked at 0.03. Measured:
# neck x 1.46 (checked at x 1.3), area change -2.0e-3 (checked at 3e-3),
# centre distance change 4.5e-5 d0 (checked at 1e-4).
add_test(NAME surface_diffusion_unequal_grains_2d COMMAND ${SD_VALIDATE} neck
  ${UNEQUAL} 30 --csv unequal_grains.csv --min-neck-growth 1.3
  --max-neck-offset 0.03 --max-volume-change 3e-3 --max-centre-shift 1e-4)
# No shrinkage up to x/R = 0.5: R = 0.1 (R/h = 12.8), 200 steps, no v^c
# (v^c puts the volume lost at the neck back everywhere, far ends included).
# Measured: neck 0.0156 -> 0.0495 (x 3.17, x/R 0.156 -> 0.495), area change
# -0.59 %, far-end-to-far-end length change -5.0e-5 L0 (0.005 h; the
# centre-distance measure reads the change of shape there, -6.7e-3 d0).
# Limits: growth x 3, area 0.9 % (1.5x), length 1e-4 L0 (2x, 0.01 h).
add_test(NAME surface_diffusion_two_grains_length_2d COMMAND ${SD_VALIDATE}
  neck ${TWO_GRAINS} 200 --set "${GRAINS_R01}"
  --csv two_grains_length.csv --min-neck-growth 3 --max-volume-change 9e-3
  --max-length-change 1e-4)
# Steps that grow with t: Time/Relative time step r = 0.1 from the first
# step 1e-7 takes 10 steps of 1e-7 to t = 1e-6 (r t reaches the first step
# there) and then 26 steps growing x 1.1 to t = 1e-5: 36 steps (the count
# of dt = max(1e-7, 0.1 t), the remaining time spread evenly, computed
# outside the code), against 100 at the fixed first step.
add_test(NAME surface_diffusion_relative_time_step COMMAND levelsinter
  --overwrite --set "Time/Time step=1e-7" --set "Time/Relative time step=0.1"
  --set "Time/CFL number=0" --set "Time/End time=1e-5"
  --set "Output/Directory=relative_time_step"
  --set "Output/Field formats=none" ${TWO_GRAINS})
set_tests_properties(surface_diffusion_relative_time_step PROPERTIES
  PASS_REGULAR_EXPRESSION "done: 36 steps to t = 1e-05")
# The first step is 'Time step': a relative step without it is refused,
# the message naming both --set that make the rule fail.
bad_input_test(relative_time_step_without_time_step
  "--set 'Time/Relative time step=0.1', --set 'Time/Time step=0': entry 'Time/Time step': must be positive with a 'Relative time step'"
  --set "Time/Relative time step=0.1" --set "Time/Time step=0"
  --set "Time/CFL number=0.5" ${TWO_GRAINS})
# The neck at 6 curvature levels and r = 0.025 with the solid reinitialised
# from band cells grows to the end: measured x/R 0.0099 -> 0.3576 (x 36.2),
# volume change 1.5e-6, 508 steps, 144 s CPU. Limits: growth 30 (with the
# finest cell's reinitialisation the neck is lost and ends at 0), volume
# change 1e-3. The scene leaves the option at `auto`, so this also checks
# that a surface-diffusion scene gets it.
add_neckref_relative_run(surface_diffusion_neck_k6_solid_band_2d
  neck_k6_solid_band.csv 20000 6 0.025 8
  --min-neck-growth 30 --max-volume-change 1e-3)

# --- Surface diffusion in 3D -------------------------------------------------
# Y_2 on a sphere, R/h = 8 (h = 1/32), half an e-folding in 20 steps
# (dt = 1.04e-3), with +delta and -delta (--signs 2: the mean rate cancels
# the mode's second-order self-coupling, worth -4 % at delta = 0.05 in 3D,
# doc/validation.md). Measured: rates 21.90 and 24.19, mean 23.05 against
# 24 (-4.0 %), volume change -0.41 % (the larger of the two runs), 36 s CPU
# for both. A flipped sign makes the mode grow (error > 100 %). Limits 1.5x
# the measured values: 6 % and 0.6 %.
add_test(NAME surface_diffusion_mullins_sphere_3d COMMAND ${SD_VALIDATE}
  mullins ${SPHERE} 3 20 --time-fraction 0.5 --signs 2 --max-rate-error 0.06
  --max-volume-change 0.006)
# Two spheres at h = 1/40 (R/h = 8), 4 steps, on 1 and 2 ranks: the
# geometry must not depend on the partition.
# FGMRES stops at a relative 1e-8 with an AMG that depends on the
# partition: neck, volume and area agreed to 2.1e-8 with MappingQ1 and
# agree to 1.2e-7 (the neck at step 4; the curvature 3.6e-8) with the box
# mapping (28 Nov 2026: another round-off, another AMG path on one of the
# partitions); checked at 3e-7, 2.5x the measured. max_velocity (the
# largest nodal speed) differs by up to 4 % in the same runs while the
# interface agrees: where it is reached is not traced,
# so it is not compared; nor are times, iterations and mesh counts.
# centre_distance_change is, like volume_change, a difference of nearly
# equal numbers (5e-6 here): centre_distance is compared instead.
ranks_agree(surface_diffusion_3d sd_3d ${GRAINS_3D} 3e-7
  "surface_diffusion_iterations;transport_iterations;cells;dofs;volume_change;max_velocity;centre_distance_change"
  --set "Mesh refinement/Maximum level=2"
  --set "Level set/Filter thickness=0.15" --set "Mesh refinement/Band width=0.1"
  --set "Time/Maximum steps=4" --set "Output/Metrics interval=1")
# The neck mode in 3D: the two spheres at R/h = 8, dt = 0.01 (t* = 6.25e-6
# per step), 10 steps. Measured: neck 0.04967 -> 0.05150 (x 1.037; the
# growth starts slowly, doc/validation.md), volume change -6.0e-4, centre
# distance change 3.0e-5 d0 (0.0005 h). Limits: growth x 1.02, volume
# 9e-4 (1.5x), centre distance 1e-4 d0 (0.0016 h, far below one cell).
add_test(NAME surface_diffusion_two_grains_3d COMMAND ${SD_VALIDATE} neck
  ${GRAINS_3D} 10 --sample-interval 5 --set "Mesh refinement/Maximum level=2"
  --set "Level set/Filter thickness=0.15" --set "Mesh refinement/Band width=0.1"
  --set "Time/Time step=0.01" --csv two_grains_3d.csv
  --min-neck-growth 1.02 --max-volume-change 9e-4 --max-centre-shift 1e-4)
# The 8-sphere packing on 2 ranks, 2 steps (dt 0.02 from the CFL limit,
# then 0.1): the neck mode's packing path (smallest neck over the 12
# overlapping pairs, centre shifts from rays away from the necks).
# Measured: smallest neck 0.06854 -> 0.07051 (x 1.029), volume change
# -1.36e-3, centre distance change -7.7e-4 d0 (0.012 h). Limits: growth
# x 1.015, volume 2e-3 (1.5x), centre distance 1.5e-3 d0 (2x; 0.024 h).
ranks_test(surface_diffusion_packing_3d RANKS 2 COMMAND ${SD_VALIDATE} neck
  ${CMAKE_SOURCE_DIR}/parameter_files/packing_surface_diffusion_3d.prm 2
  --sample-interval 2 --csv packing_3d.csv
  --min-neck-growth 1.015 --max-volume-change 2e-3 --max-centre-shift 1.5e-3)
