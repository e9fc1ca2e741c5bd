# --- Grain boundaries and densification (issue 28) --------------------------
# doc/numerics.md and doc/validation.md, "Grain boundaries and
# densification"; scripts/check_grains.py prints what it measures. Runs of
# 20 steps (6 in 3D), metrics every step, no fields.
set(GRAIN_SCENES ${CMAKE_SOURCE_DIR}/parameter_files)
set(CHECK_GRAINS ${Python3_EXECUTABLE} ${CMAKE_SOURCE_DIR}/scripts/check_grains.py)
set(GRAINS_CI_OUTPUT --set "Output/Field formats=none"
  --set "Output/Metrics interval=1" --set "Output/Progress interval=0")
# grains_run(NAME SCENE STEPS ARGS...): levelsinter on SCENE for STEPS
# steps into NAME/, the fixture NAME.
function(grains_run name scene steps)
  add_test(NAME ${name}_run COMMAND $<TARGET_FILE:levelsinter> --overwrite
    ${GRAINS_CI_OUTPUT} --set "Time/Maximum steps=${steps}"
    --set "Output/Directory=${name}" ${ARGN} ${GRAIN_SCENES}/${scene})
  set_tests_properties(${name}_run PROPERTIES FIXTURES_SETUP ${name})
endfunction()
# The equilibrium scenes (R/h = 32) at R/h = 16 and 8. The refined band is 0.8 E,
# surface diffusion's band rule (doc/numerics.md, "Filter thickness
# against the step"): at 0.66 E (0.062, before the ninth increment) the
# surface loses solid, the volume correction returns it uniformly, and the
# contact law turns the neck's biased curvature into a drift of the rigid
# grains apart (doc/validation.md, "Settling the pair: the refined band").
set(GRAINS_R16
  --set "Mesh refinement/Maximum level=4"
  --set "Level set/Filter thickness=0.094"
  --set "Mesh refinement/Band width=0.0752")
set(GRAINS_R8
  --set "Mesh refinement/Maximum level=3"
  --set "Level set/Filter thickness=0.188"
  --set "Mesh refinement/Band width=0.1504")
# grains_check(NAME FIXTURES MODE ARGS...): check_grains.py MODE ARGS.
function(grains_check name fixtures mode)
  add_test(NAME ${name} COMMAND ${CHECK_GRAINS} ${mode} ${ARGN})
  set_tests_properties(${name} PROPERTIES FIXTURES_REQUIRED "${fixtures}")
endfunction()
# grains_rest(NAME SCENE PARTICLES ARGS...): the pair of SCENE started
# from its exact end state (tests/PARTICLES) with the implicit contact law
# and its accuracy limit, up to 1000 steps, into NAME/.
function(grains_rest name scene particles)
  grains_run(${name} ${scene} 1000
    --set "Geometry/Particles="
    --set "Geometry/Particle file=${CMAKE_CURRENT_SOURCE_DIR}/${particles}"
    --set "Grain boundaries/Implicit contact law=true" ${ARGN})
endfunction()

# Scene rules (SceneParameters::check_grains, GrainBoundaryParameters).
bad_input_test(grains_energy_ratio "Grain boundaries/Energy ratio"
  --set "Grain boundaries/Energy ratio=2" ${GRAIN_SCENES}/grains_two_2d.prm)
bad_input_test(grains_without_surface_diffusion "Surface diffusion/Enabled = true"
  --set "Surface diffusion/Enabled=false" ${GRAIN_SCENES}/grains_two_2d.prm)
bad_input_test(grains_cut_by_plane "crosses the domain's boundary"
  --set "Domain/Symmetry planes=x-" --set "Domain/Lower corner=0.5, 0"
  ${GRAIN_SCENES}/grains_two_2d.prm)

# Two grains in 2D (R = 0.2, x0/R = 0.22, C_gb = C_s = 1e-6, gamma_gb /
# gamma_s = 0.5), 20 steps to t = 0.02, on 1 and 2 ranks: measured
# largest relative difference 7.0e-8 (the iteration counts aside);
# limit 1e-6.
ranks_agree(grains_two_2d grains_two_2d ${GRAIN_SCENES}/grains_two_2d.prm
  1e-6 "surface_diffusion_iterations;transport_iterations"
  --set "Time/Maximum steps=20" --set "Output/Metrics interval=1"
  --set "Output/Progress interval=0")
grains_run(grains_two_2d_surface_only grains_two_2d.prm 20
  --set "Grain boundaries/Enabled=false")
# The force balance of the pair reproduces the two-grain law u = C_gb (P
# sin(psi/2) - A kappa_root) / G at every step: measured 6.6e-12 (2D),
# 4.0e-12 (axisymmetric), 2.5e-12 (3D); a wrong coefficient, time unit,
# sign or solve is off by O(1).
grains_check(grains_two_2d_law grains_two_2d_np1 law grains_two_2d_np1
  1e-6 0.5 2 1e-9)
# The grains approach: measured 5.26e-3 of the centre distance in 20
# steps (0 without the mechanism: the rigid centres then do not move);
# |volume_change| 8.13e-4 and grain_volume_change_max 8.13e-4 (surface
# diffusion alone loses 7.45e-4 here). Limits 4e-3, 1e-3, 1e-3.
grains_check(grains_two_2d_densify grains_two_2d_np1 densify
  grains_two_2d_np1 4e-3 1e-3 1e-3)
# The level set moves with the grains: the approach of the solid's
# power-cell centroids (the packing analysis, on the level set) beyond
# surface diffusion's own is the rigid approach within 1.8 % (measured;
# the rest is the matter deposited at the neck and the Q1 transport),
# limit 5 %; without the rigid velocity in the field it would be 100 %
# off. The grain boundaries lose 6.8e-5 of the solid (7 % of the volume
# they move in these steps); limit 1.5e-4.
grains_check(grains_two_2d_centroids
  "grains_two_2d_np1;grains_two_2d_surface_only" centroids
  grains_two_2d_np1 grains_two_2d_surface_only 0.05 1.5e-4)

# Axisymmetric pair (the 3D contact law), 20 steps: measured approach
# 1.35e-2, |volume_change| 8.8e-4 (limits 1e-2, 1.5e-3).
grains_run(grains_two_axisymmetric grains_two_axisymmetric.prm 20)
grains_check(grains_two_axisymmetric_law grains_two_axisymmetric law
  grains_two_axisymmetric 1e-6 0.5 3 1e-9)
grains_check(grains_two_axisymmetric_densify grains_two_axisymmetric densify
  grains_two_axisymmetric 1e-2 1.5e-3 1.5e-3)

# 3D pair on a quarter box (symmetry planes through the line of centres),
# 6 steps (15 s): measured approach 5.34e-3, |volume_change| 3.3e-4
# (limits 4e-3, 1e-3).
grains_run(grains_two_3d grains_two_3d.prm 6)
grains_check(grains_two_3d_law grains_two_3d law grains_two_3d
  1e-6 0.5 3 1e-9)
grains_check(grains_two_3d_densify grains_two_3d densify grains_two_3d
  4e-3 1e-3 1e-3)

# Four grains around a pore: the four grain boundaries close alike;
# measured spread 3.2e-11 (centre distance) and 6.7e-12 (radius) after 20
# steps. Before nodes on a boundary took the mean of its grains'
# velocities (they took the first grain's) the spread was 1.5e-2; limit
# 1e-8.
grains_run(grains_four_2d grains_four_2d.prm 20)
grains_check(grains_four_2d_equal grains_four_2d equal grains_four_2d 1e-8)

# A row of 4 grains shrinks at the strain rate of 2 (each grain's velocity
# follows from its boundaries' contact laws): shrinkage_x after 20 steps
# 6.96e-3 (4 grains) against 7.37e-3 (2 grains), 5.5 % apart at h =
# 0.0094 and 1.8 % at h / 2 (the end grains of the row translate faster
# and their necks diffuse more in the transport); limit 10 %. A
# Wang-type rigid-body advection (only the end grains move) would give a
# third of the pair's strain.
grains_run(grains_line_4 grains_line_2d.prm 20)
# (add_test itself: a function's arguments would split the particle list
# at its semicolon.)
add_test(NAME grains_line_2_run COMMAND $<TARGET_FILE:levelsinter> --overwrite
  ${GRAINS_CI_OUTPUT} --set "Time/Maximum steps=20"
  --set "Output/Directory=grains_line_2"
  --set "Geometry/Particles=0.3, 0.5, 0.2; 0.69375, 0.5, 0.2"
  ${GRAIN_SCENES}/grains_line_2d.prm)
set_tests_properties(grains_line_2_run PROPERTIES FIXTURES_SETUP grains_line_2)
grains_check(grains_line_2_vs_4 "grains_line_2;grains_line_4" same
  grains_line_2 grains_line_4 shrinkage_x 0.1)

# Restart: every grain's centre (and the step limit's speed) is in the
# checkpoint; the two grains, 20 steps, a checkpoint every 5 (not
# compared besides the restart tests' columns: the surface-diffusion
# solve's iterations and CPU time). Measured largest relative difference
# 6.6e-9 (1 -> 1) and 1.7e-8 (1 -> 2; the uninterrupted 1- and 2-rank runs
# differ by 7e-8); grain_boundaries.csv is not compared. Centres lost at
# the restart would reset grain_centre_distance_change_mean (-1.4e-3 at
# step 5) to 0. Limits 1e-7 and 1e-6, as the surface-diffusion restarts.
set(RESTART_GRAINS_IGNORED ${RESTART_SD_IGNORED})
set(RESTART_GRAINS_ARGS
  --set "Time/Maximum steps=20" --set "Output/Checkpoint interval=5"
  --set "Output/Metrics interval=1" --set "Output/Progress interval=0"
  --set "Output/Field formats=none")
restart_test(restart_grains_two_2d_np1_np1 ${GRAIN_SCENES}/grains_two_2d.prm
  1 1 1e-7 "${RESTART_GRAINS_IGNORED}" ${RESTART_GRAINS_ARGS})
restart_test(restart_grains_two_2d_np1_np2 ${GRAIN_SCENES}/grains_two_2d.prm
  1 2 1e-6 "${RESTART_GRAINS_IGNORED};cells;dofs" ${RESTART_GRAINS_ARGS})

# --- Studies (validation-long; doc/validation.md, "Grain boundaries and
# densification") ---------------------------------------------------------
# The axisymmetric pair to t = 0.5 at R/h = 16 and 32 (Maximum level 3, 4):
# the grain-boundary radius against the initial-stage law of the model,
# (a/R)^6 = 192 C_gb t / R^4, and the approach against Coble's neck
# geometry h = a^2 / (4 R).
foreach(case "3;0.075;0.05;16" "4;0.0375;0.025;32")
  list(GET case 0 level)
  list(GET case 1 filter)
  list(GET case 2 band)
  list(GET case 3 resolution)
  set(name study_grains_two_axisymmetric_R${resolution})
  add_test(NAME ${name}_run COMMAND $<TARGET_FILE:levelsinter> --overwrite
    --set "Output/Field formats=none" --set "Output/Metrics interval=1"
    --set "Mesh refinement/Maximum level=${level}"
    --set "Level set/Filter thickness=${filter}"
    --set "Mesh refinement/Band width=${band}"
    --set "Output/Directory=${name}"
    ${GRAIN_SCENES}/grains_two_axisymmetric.prm)
  add_test(NAME ${name} COMMAND ${CHECK_GRAINS} kinetics ${name} 0.2 1e-6 0.05
    --csv ${CMAKE_SOURCE_DIR}/doc/validation_data/grains_two_axisymmetric_R${resolution}.csv)
  set_tests_properties(${name}_run PROPERTIES FIXTURES_SETUP ${name}
    LABELS validation-long)
  set_tests_properties(${name} PROPERTIES FIXTURES_REQUIRED ${name}
    LABELS validation-long)
endforeach()
# The densification curves: the 8-grain packing to t = 2.4 (25 steps,
# about 2-5 min on 1 core) and the 27 grains to t = 3 (15 steps, 157 s
# wall and 66 s CPU on 1 core at the load of the session).
foreach(n 8 27)
  set(name study_grains_packing_${n}_3d)
  add_test(NAME ${name}_run COMMAND $<TARGET_FILE:levelsinter>
    --overwrite --set "Output/Field formats=none"
    --set "Output/Directory=${name}" ${GRAIN_SCENES}/grains_packing_${n}_3d.prm)
  add_test(NAME ${name}
    COMMAND ${CMAKE_SOURCE_DIR}/scripts/plot_densification.py ${name}
      ${CMAKE_SOURCE_DIR}/doc/validation_data/grains_packing_${n}_3d.png
      --csv ${CMAKE_SOURCE_DIR}/doc/validation_data/grains_packing_${n}_3d.csv)
  set_tests_properties(${name}_run PROPERTIES
    FIXTURES_SETUP ${name} LABELS validation-long)
  set_tests_properties(${name} PROPERTIES
    FIXTURES_REQUIRED ${name} LABELS validation-long)
endforeach()

# With the volume correction on (Eq. 113-116 after both mechanisms) the
# solid and every grain keep their volume: measured |volume_change| and
# grain_volume_change_max 8.8e-7 in 20 steps (5.1e-7 in 100), the approach
# 5.254e-3 against 5.260e-3 uncorrected (0.3 % apart in 100 steps);
# limits 1e-5 (without the correction 8.1e-4).
grains_run(grains_two_2d_volume_correction grains_two_2d.prm 20
  --set "Volume correction/Enabled=true")
grains_check(grains_two_2d_volume_correction_densify
  grains_two_2d_volume_correction densify grains_two_2d_volume_correction
  4e-3 1e-5 1e-5)

# RayCaster on rays along mesh faces (tests/ray_caster_test.cc): origins on
# faces, directions along an axis, exact or tilted by 1e-16 ... 1e-9 rad;
# every exit within h^2 / R of the ball's surface. 1 and 2 ranks (the
# rays cross the ranks' partition).
add_executable(ray_caster_test ray_caster_test.cc)
target_link_libraries(ray_caster_test levelsinter_lib levelsinter_study)
deal_ii_setup_target(ray_caster_test)
ranks_test(ray_caster_2d COMMAND $<TARGET_FILE:ray_caster_test> 2 6)
ranks_test(ray_caster_3d COMMAND $<TARGET_FILE:ray_caster_test> 3 4)

# --- The dihedral angle at the triple line (issue 28, second increment;
# doc/numerics.md and doc/validation.md, "The dihedral angle at the triple
# line") ----------------------------------------------------------------
# The triple-line condition on the pair of grains_two_2d.prm (gamma_gb /
# gamma_s = 0.5), 10 steps, 1 and 2 ranks: measured largest relative
# difference 6.6e-8 (as without it); limit 1e-6. The pair of
# grains_equilibrium_2d.prm is not used here: its first step's speed at
# the under-resolved initial cusp differs by 1.1e-3 between 1 and 2 ranks
# with the condition on or off (the kappa / v_s solve there).
ranks_agree(grains_two_2d_triple_line grains_two_2d_triple_line
  ${GRAIN_SCENES}/grains_two_2d.prm 1e-6
  "surface_diffusion_iterations;transport_iterations"
  --set "Grain boundaries/Triple-line condition=true"
  --set "Time/Maximum steps=10" --set "Output/Metrics interval=1"
  --set "Output/Progress interval=0")
# With the triple-line potential in kappa the contact law reads the neck
# root's chemical potential; the force balance still reproduces the law
# at every step: measured 4.7e-12 (as grains_two_2d_law).
grains_check(grains_two_2d_triple_line_law grains_two_2d_triple_line_np1 law
  grains_two_2d_triple_line_np1 1e-6 0.5 2 1e-9)
# The measurement of the dihedral angle (circles fitted to each grain's
# surface beyond the triple-line kernel, met with the grain boundary's
# plane) on the initial state of grains_equilibrium_2d.prm at R/h = 16,
# two circles of R = 0.25 meeting at psi = 25.42 degrees: measured 25.74
# degrees (25.32 at R/h = 32), the fitted radius 2.9e-4 and the centre
# distance 6e-6 off. Limits 1 degree, 1e-3.
grains_run(grains_equilibrium_2d grains_equilibrium_2d.prm 1 ${GRAINS_R16})
grains_check(grains_equilibrium_2d_initial grains_equilibrium_2d initial
  grains_equilibrium_2d 0.25 1 1e-3)
# The end state against the exact equilibrium (t = 0.01, R/h = 16 and 32,
# gamma_gb / gamma_s = 0.5 and 1; kernel l = 6 h): studies, 5-100 s CPU per
# run, not yet within the issue's 1 % (doc/validation.md; R/h = 32 at 0.5
# added in the third increment).
# grains_equilibrium_studies(VARIANT END_TIME INTERVAL ARGS...): the pair
# of grains_equilibrium_2d.prm at R/h = 16 and 32, gamma_gb / gamma_s = 1
# and 0.5, kernel l = 6 h, to END_TIME, against the exact end state
# (check_grains.py equilibrium, which writes its table to
# doc/validation_data/grains_equilibrium_2d<VARIANT>_R*_ratio*.csv).
function(grains_equilibrium_studies variant end_time interval)
  foreach(case "4;0.094;0.062;16;1" "5;0.047;0.031;32;1" "4;0.094;0.062;16;0.5"
      "5;0.047;0.031;32;0.5")
    list(GET case 0 level)
    list(GET case 1 filter)
    list(GET case 2 band)
    list(GET case 3 resolution)
    list(GET case 4 ratio)
    set(name study_grains_equilibrium_2d${variant}_R${resolution}_ratio${ratio})
    add_test(NAME ${name}_run COMMAND $<TARGET_FILE:levelsinter> --overwrite
      --set "Output/Field formats=none"
      --set "Output/Metrics interval=${interval}"
      --set "Mesh refinement/Maximum level=${level}"
      --set "Level set/Filter thickness=${filter}"
      --set "Mesh refinement/Band width=${band}"
      --set "Grain boundaries/Energy ratio=${ratio}"
      --set "Grain boundaries/Deposition width=6"
      --set "Time/End time=${end_time}" --set "Output/Directory=${name}"
      ${ARGN} ${GRAIN_SCENES}/grains_equilibrium_2d.prm)
    add_test(NAME ${name} COMMAND ${CHECK_GRAINS} equilibrium ${name} ${ratio} 2
      --csv ${CMAKE_SOURCE_DIR}/doc/validation_data/grains_equilibrium_2d${variant}_R${resolution}_ratio${ratio}.csv)
    set_tests_properties(${name}_run PROPERTIES FIXTURES_SETUP ${name}
      LABELS validation-long)
    set_tests_properties(${name} PROPERTIES FIXTURES_REQUIRED ${name}
      LABELS validation-long)
  endforeach()
endfunction()
grains_equilibrium_studies("" 0.01 10)

# --- The sharp triple-line condition (issue 28, fourth increment;
# doc/numerics.md and doc/validation.md, "The sharp triple-line
# condition") -------------------------------------------------------------
bad_input_test(grains_kink_without_condition "Triple-line kink width"
  --set "Grain boundaries/Triple-line kink width=2"
  ${GRAIN_SCENES}/grains_two_2d.prm)
# The pair of grains_two_2d.prm with the sharp condition (kink width 2,
# deposition width 6), 10 steps, 1 and 2 ranks: measured largest relative
# difference 7.2e-8; limit 1e-6.
ranks_agree(grains_two_2d_sharp grains_two_2d_sharp
  ${GRAIN_SCENES}/grains_two_2d.prm 1e-6
  "surface_diffusion_iterations;transport_iterations"
  --set "Grain boundaries/Triple-line condition=true"
  --set "Grain boundaries/Triple-line kink width=2"
  --set "Grain boundaries/Deposition width=6"
  --set "Time/Maximum steps=10" --set "Output/Metrics interval=1"
  --set "Output/Progress interval=0")
# The dihedral angle during the run, grains_equilibrium_2d.prm at R/h = 16,
# gamma_gb / gamma_s = 1 (psi = 120 degrees), to t = 0.01 (49 steps, metrics
# every step, 20 s of wall at load 9): psi at the 6 rows with t >= 0.005
# measured 122.9 to 127.9 degrees (the band at 0.66 E before the ninth
# increment: 114.1 to 127.8, oscillating about the equilibrium,
# doc/validation.md); limit 10 degrees. The regularised condition (kink
# width 0) read 93 to 104 there, no condition one disc.
grains_run(grains_equilibrium_2d_sharp grains_equilibrium_2d.prm 1000
  ${GRAINS_R16}
  --set "Grain boundaries/Deposition width=6"
  --set "Grain boundaries/Triple-line kink width=2"
  --set "Time/End time=0.01")
grains_check(grains_equilibrium_2d_sharp_angle grains_equilibrium_2d_sharp
  angle grains_equilibrium_2d_sharp 1 0.005 10)
# The end state and the angle over the run against the exact equilibrium:
# studies to t = 0.01 (doc/validation.md).
grains_equilibrium_studies(_sharp 0.01 5
  --set "Grain boundaries/Triple-line kink width=2")

# --- Settling and the axisymmetric pair (issue 28, fifth increment;
# doc/validation.md, "The sharp triple-line condition: settling, the
# axisymmetric pair") ------------------------------------------------------
# grains_equilibrium_axisymmetric.prm (two spheres, sharp condition) at
# R/h = 16, 1 and 2 ranks, 10 steps: measured largest relative difference
# 1.06e-4 in grain_volume_change_max (4.5e-6, the volume correction's
# residual; 4.8e-10 apart), 2.8e-6 in volume_change, 4.4e-7 in the other
# columns (with the band at 0.66 E before the ninth increment: 4.1e-5 and
# 8.5e-8); limit 3e-4. The contact law (3D form) at every step: measured
# 6.1e-12 (as grains_two_axisymmetric_law).
ranks_agree(grains_equilibrium_axisymmetric grains_equilibrium_axisymmetric
  ${GRAIN_SCENES}/grains_equilibrium_axisymmetric.prm 3e-4
  "surface_diffusion_iterations;transport_iterations"
  ${GRAINS_R16}
  --set "Time/Maximum steps=10" --set "Output/Metrics interval=1"
  --set "Output/Progress interval=0")
grains_check(grains_equilibrium_axisymmetric_law
  grains_equilibrium_axisymmetric_np1 law grains_equilibrium_axisymmetric_np1
  1 1 3 1e-9)
# The relaxing pair against the exact truncated spheres (the run's solid
# volume), R/h = 16 to t = 0.005 (48 steps, metrics every step, 10 s of
# wall at load 9): at the 7 rows with t >= 0.003 measured R, a, d within
# 3.8, 1.8, 3.6 % (a where the near circles meet the plane since the tenth
# increment; the rays' a 3.4 %) and psi 117.2 to 118.8 degrees, mean
# 118.4, the rigid
# centres +3.0 % (with the band at 0.66 E before the ninth increment: 29
# rows, 2.7, 1.5, 5.7 %, psi's mean 117.4, the centres +24 % and the pair
# lost at t = 0.0072, doc/validation.md); limits 8 % and 5 degrees on the
# mean. It fails when the pair merges or loses its grain boundary.
grains_run(grains_equilibrium_axisymmetric_relaxed
  grains_equilibrium_axisymmetric.prm 1000 ${GRAINS_R16}
  --set "Time/End time=0.005")
grains_check(grains_equilibrium_axisymmetric_settled
  grains_equilibrium_axisymmetric_relaxed settled
  grains_equilibrium_axisymmetric_relaxed 1 3 0.003 0.08 5)

# --- The 27-grain packing (grains_packing_27_3d.prm) ----------------------
# 2 steps at h = 0.05 on 1 and 2 ranks (about 30 s CPU, 3 min wall at the
# session's load): measured largest relative difference 5.8e-9, limit
# 1e-6. The grains approach by 4.36e-3 (grain_centre_distance_change_mean),
# |volume_change| 1.03e-4 (the volume correction), grain_volume_change_max
# 2.5e-3 (2.8e-3 before the ramp split of grain_volumes(); the partition
# moves matter between grains, doc/validation.md "Volume per grain");
# limits 3e-3, 2e-4, 5e-3.
ranks_agree(grains_packing_27_3d grains_packing_27_3d
  ${GRAIN_SCENES}/grains_packing_27_3d.prm 1e-6
  "surface_diffusion_iterations;transport_iterations"
  --set "Time/Maximum steps=2" --set "Output/Metrics interval=1"
  --set "Output/Progress interval=0")
grains_check(grains_packing_27_3d_densify grains_packing_27_3d_np1 densify
  grains_packing_27_3d_np1 3e-3 2e-4 5e-3)

# --- Volume per grain (issue 28, third increment) -------------------------
# Two unequal grains (R = 0.2, 0.15) with `Conserve grain volumes`, 20
# steps on 1 and 2 ranks: measured largest relative difference 6.5e-7,
# limit 5e-6 (the weights' Newton stops at 1e-6 of each grain's volume,
# and the ranks' rounding may take it one iteration further or less).
# Every grain keeps its share of the solid:
# grain_volume_change_max - |volume_change| measured 1.1e-14 (1.5e-4 with
# the plain power partition: the radical plane moves relative to unequal
# grains and surface diffusion carries matter across it); limit 1e-6, the
# Newton tolerance of the weights.
ranks_agree(grains_unequal_2d grains_unequal_2d
  ${GRAIN_SCENES}/grains_unequal_2d.prm 5e-6
  "surface_diffusion_iterations;transport_iterations"
  --set "Time/Maximum steps=20" --set "Output/Metrics interval=1"
  --set "Output/Progress interval=0")
grains_check(grains_unequal_2d_conserved grains_unequal_2d_np1 conserved
  grains_unequal_2d_np1 1e-6)
grains_check(grains_unequal_2d_np2_conserved grains_unequal_2d_np2 conserved
  grains_unequal_2d_np2 1e-6)
# The 27-grain packing with the weights corrected, to t = 24 (120 steps,
# 59 min of wall at load 5-8 in the eighth increment; its densification
# curve, doc/validation.md "Densification of the 27-grain packing"):
# measured grain_volume_change_max - |volume_change| 9.8e-7 to t = 3 and
# 2.6e-6 to t = 24 (1.3e-2 at t = 3 without), grain_volume_change_max at
# most 1.4e-4 (the solid's own drift); limit 1e-5. At t = 24.4 a new
# contact's neck sets the step to 0.02 and below, so the curve ends
# before it.
# grains_packing_study(NAME ARGS...): the 27-grain packing with conserved
# grain volumes to t = 24 with the extra ARGS, each grain's share of the
# solid checked (limit 1e-5), and its densification plot and CSV
# (doc/validation_data/NAME without "study_").
function(grains_packing_study name)
  string(REPLACE "study_" "" data ${name})
  add_test(NAME ${name}_run COMMAND $<TARGET_FILE:levelsinter> --overwrite
    --set "Output/Field formats=none" --set "Output/Directory=${name}"
    --set "Grain boundaries/Conserve grain volumes=true" ${ARGN}
    --set "Time/End time=24" ${GRAIN_SCENES}/grains_packing_27_3d.prm)
  add_test(NAME ${name} COMMAND ${CHECK_GRAINS} conserved ${name} 1e-5)
  add_test(NAME ${name}_plot
    COMMAND ${CMAKE_SOURCE_DIR}/scripts/plot_densification.py ${name}
      ${CMAKE_SOURCE_DIR}/doc/validation_data/${data}.png
      --csv ${CMAKE_SOURCE_DIR}/doc/validation_data/${data}.csv)
  set_tests_properties(${name}_run PROPERTIES FIXTURES_SETUP ${name}
    LABELS validation-long)
  set_tests_properties(${name} ${name}_plot PROPERTIES
    FIXTURES_REQUIRED ${name} LABELS validation-long)
endfunction()
grains_packing_study(study_grains_packing_27_3d_conserve)
# The same packing at Maximum level 3 (R/h = 6.4-8, the band at 0.8 E)
# to t = 24: run to t = 11.1 in the tenth increment (58 steps, 22.5 min of
# CPU, 1 rank; doc/validation.md "Densification of the 27-grain packing
# at level 3", data in archive/grains_packing_27_3d_level3/), every
# grain's share of the solid measured within 9.4e-7; limit 1e-5 as above.
# The whole curve is about 122 steps, 45 min of CPU on an idle core.
grains_packing_study(study_grains_packing_27_3d_level3
  --set "Mesh refinement/Maximum level=3"
  --set "Level set/Filter thickness=0.075"
  --set "Mesh refinement/Band width=0.06"
  --set "Output/Checkpoint minutes=10")
# Restart 1 -> 2 ranks with the weights and the volumes at t = 0 in the
# checkpoint (the settings of restart_grains_two_2d_np1_np2): measured
# largest relative difference 5.6e-8, limit 1e-6. Volumes at t = 0 lost
# at the restart would be measured again there, and grain_volume_change_max
# (3e-5 to 4e-4 here) would differ by what the grains exchanged before it.
restart_test(restart_grains_unequal_2d_np1_np2
  ${GRAIN_SCENES}/grains_unequal_2d.prm 1 2 1e-6
  "${RESTART_GRAINS_IGNORED};cells;dofs" ${RESTART_GRAINS_ARGS})

# --- The root curvature and the 3D pair (issue 28, seventh increment;
# doc/validation.md, "Settling the pair: the root curvature's bias") -------
# The dihedral angle's fit in 3D: step 0 of grains_equilibrium_3d.prm (the
# pair in a quarter box, R/h = 16), two overlapping spheres of R = 0.25
# meeting at psi = 25.42 degrees: measured 25.07 degrees with the near
# circle centred on the line of centres (the free circle read 23.24 and,
# later in the run, 0-111 degrees), the fitted radius 6.4e-4 and the
# centre distance 1e-6 off. Limits 1 degree, 1e-3 (as the 2D check).
# One step, 15 s on the shared machine.
grains_run(grains_equilibrium_3d grains_equilibrium_3d.prm 1)
grains_check(grains_equilibrium_3d_initial grains_equilibrium_3d initial
  grains_equilibrium_3d 0.25 1 1e-3)
# The 3D pair relaxing (the law kept), 100 steps to t = 0.0024 (6 min of
# wall at load 3-7): at the rows with t >= 0.0018 (steps 75-100) measured
# R, a, d within 1.9, 2.7, 2.5 % and psi 118.3-119.4 degrees (mean 118.8)
# with the centred near circle (the free circle read 53-95 on these
# steps). The trajectory changes with the step times (the end time alone
# moves it by a few per cent: End time 1 is the measured run's), so the
# limits are 5 % and 3 degrees on the mean. Not in CI: the pair needs
# about 100 steps to relax.
set(name study_grains_equilibrium_3d_relaxing)
add_test(NAME ${name}_run COMMAND $<TARGET_FILE:levelsinter> --overwrite
  --set "Output/Field formats=none" --set "Output/Progress interval=0"
  --set "Time/Maximum steps=100" --set "Time/End time=1"
  --set "Output/Directory=${name}" ${GRAIN_SCENES}/grains_equilibrium_3d.prm)
add_test(NAME ${name} COMMAND ${CHECK_GRAINS} settled ${name} 1 3 0.0018 0.05 3
  0.25)
set_tests_properties(${name}_run PROPERTIES FIXTURES_SETUP ${name}
  LABELS validation-long)
set_tests_properties(${name} PROPERTIES FIXTURES_REQUIRED ${name}
  LABELS validation-long)

# --- The periodic row of grains (issue 28, eighth increment;
# doc/numerics.md and doc/validation.md, "The periodic row of grains") ----
# grains_ring_2d.prm: twelve grains on a circle (a row without ends; a
# straight row between fixed symmetry planes cannot shrink), R0 = 0.25,
# x/R = 0.22, gamma_gb = gamma_s; exact state per grain that of the
# straight row: R = 0.3197, a = 0.2769, d = 0.3197 (d0 = 0.48775).
# Step 0 at R/h = 32 (the scene): every grain boundary's circles fitted
# beyond the grain's two grooves, against the twelve overlapping circles
# of R = 0.25 meeting at psi = 25.42 degrees: measured 25.20-25.33
# degrees, the radius 1.1e-4 and the centre distance 2e-6 off (R/h = 16:
# 23.18 degrees on the boundaries along the mesh's diagonals). Limits 1
# degree, 1e-3, as grains_equilibrium_2d_initial.
grains_run(grains_ring_2d grains_ring_2d.prm 1)
grains_check(grains_ring_2d_initial grains_ring_2d initial grains_ring_2d
  0.25 1 1e-3)
# 1 and 2 ranks, R/h = 16, 6 steps: metrics.csv and every grain
# boundary's row (the rays and the fits) agree; measured largest relative
# differences 3.1e-7 and 3.2e-7; limit 1e-6. The meshes may differ by a
# few cells (11920 against 11926 at step 4: the adaptation's ties), so
# cells and dofs are not compared.
ranks_agree(grains_ring_2d_ranks grains_ring_2d_ranks
  ${GRAIN_SCENES}/grains_ring_2d.prm 1e-6
  "surface_diffusion_iterations;transport_iterations;cells;dofs"
  ${GRAINS_R16} --set "Time/Maximum steps=6"
  --set "Output/Metrics interval=1" --set "Output/Progress interval=0")
add_test(NAME grains_ring_2d_fits_1_vs_2_ranks COMMAND compare_metrics
  grains_ring_2d_ranks_np1/grain_boundaries.csv
  grains_ring_2d_ranks_np2/grain_boundaries.csv 1e-6)
set_tests_properties(grains_ring_2d_fits_1_vs_2_ranks PROPERTIES
  FIXTURES_REQUIRED "grains_ring_2d_ranks_np1;grains_ring_2d_ranks_np2")
# The row densifies to its equilibrium at R/h = 8 (the scene at Maximum
# level 3), t = 0.04 (93 steps, 35 s CPU): the rigid grains' centre
# spacing measured +5.2 % from the exact state at t = 0.04, +4.8 to +6.1 %
# over t >= 0.005 and not drifting (R/h = 16: +4.8 to +5.6 %, R/h = 32:
# +4.5 %; the offset is the grains' reshaping by surface diffusion before
# the grain boundaries formed, the fitted circles' spacing is within 1-4 %,
# doc/validation.md "Settling the pair: the refined band"), from +52.6 % at
# t = 0. With the band at 0.66 E (before the ninth increment) the grains
# drifted apart: +8.5 % at t = 0.04. Limits +3 % and +7.5 %; surface
# diffusion alone leaves the solid's centroids at +51.5 % at R/h = 16.
grains_run(grains_ring_2d_R8 grains_ring_2d.prm 1000 ${GRAINS_R8}
  --set "Time/End time=0.04" --set "Output/Metrics interval=5")
grains_check(grains_ring_2d_R8_spacing grains_ring_2d_R8 spacing
  grains_ring_2d_R8 1 12 0.48775 grain_centre_distance_change_mean 0.03 0.075)
# The same run's grains' centroids (centroid_distance) against the exact
# state's centroids, whose spacing is 6.1 % above its circle centres' d
# (the grain boundaries are turned towards the ring's centre): measured
# +0.56 to +1.76 % at the 7 rows with t >= 0.005 (+0.92 % at t = 0.04;
# R/h = 16: +0.20 to +0.86 %) while the rigid centres stay at +4.8 to
# +6.1 % (doc/validation.md, "Settling the pair: the contact law's
# step"); limit 2.5 %, the rows' swing at R/h = 8 (1.2 %) above the
# largest. No extra run.
grains_check(grains_ring_2d_R8_centroids grains_ring_2d_R8 centroids-row
  grains_ring_2d_R8 1 12 --from 0.005 --limit 0.025)
# Studies: the row at R/h = 16 and 32 to t = 0.02 against the exact state
# (every grain boundary's R, a, d and psi, check_grains.py equilibrium
# --row 12, and the rigid grains' spacing), and the row with surface
# diffusion alone (Grain boundaries/Enabled = false; the spacing of the
# solid's power-cell centroids, the packing analysis) to t = 0.04: it
# stays at least 30 % above the equilibrium's (measured +51.5 % at R/h =
# 16). Plot grains_ring_2d.png of the spacings.
# (The scene is at R/h = 32; GRAINS_R16 holds the settings
# of R/h = 16.)
foreach(resolution 16 32)
  set(name study_grains_ring_2d_R${resolution})
  set(settings)
  if(resolution EQUAL 16)
    set(settings ${GRAINS_R16})
  endif()
  add_test(NAME ${name}_run COMMAND $<TARGET_FILE:levelsinter> --overwrite
    --set "Output/Field formats=none" ${settings}
    --set "Time/End time=0.02" --set "Output/Directory=${name}"
    ${GRAIN_SCENES}/grains_ring_2d.prm)
  add_test(NAME ${name} COMMAND ${CHECK_GRAINS} equilibrium ${name} 1 2
    --row 12 --csv
    ${CMAKE_SOURCE_DIR}/doc/validation_data/grains_ring_2d_R${resolution}.csv)
  add_test(NAME ${name}_spacing COMMAND ${CHECK_GRAINS} spacing ${name} 1 12
    0.48775 grain_centre_distance_change_mean -0.05 0.2 --csv
    ${CMAKE_SOURCE_DIR}/doc/validation_data/grains_ring_2d_R${resolution}_spacing.csv)
  set_tests_properties(${name}_run PROPERTIES FIXTURES_SETUP ${name}
    LABELS validation-long)
  set_tests_properties(${name} ${name}_spacing PROPERTIES
    FIXTURES_REQUIRED ${name} FIXTURES_SETUP ${name}_checked
    LABELS validation-long)
endforeach()
set(name study_grains_ring_2d_surface_only_R16)
add_test(NAME ${name}_run COMMAND $<TARGET_FILE:levelsinter> --overwrite
  --set "Output/Field formats=none" ${GRAINS_R16}
  --set "Time/End time=0.04" --set "Grain boundaries/Enabled=false"
  --set "Output/Directory=${name}" ${GRAIN_SCENES}/grains_ring_2d.prm)
add_test(NAME ${name} COMMAND ${CHECK_GRAINS} spacing ${name} 1 12 0.48775
  centre_distance_change_mean 0.3 1 --csv
  ${CMAKE_SOURCE_DIR}/doc/validation_data/grains_ring_2d_surface_only_R16_spacing.csv)
set_tests_properties(${name}_run PROPERTIES FIXTURES_SETUP ${name}
  LABELS validation-long)
set_tests_properties(${name} PROPERTIES FIXTURES_REQUIRED ${name}
  FIXTURES_SETUP ${name}_checked LABELS validation-long)
set(spacing ${CMAKE_SOURCE_DIR}/doc/validation_data/grains_ring_2d)
add_test(NAME study_grains_ring_2d_plot
  COMMAND ${CMAKE_SOURCE_DIR}/scripts/plot_grain_row.py
    ${CMAKE_SOURCE_DIR}/doc/validation_data/grains_ring_2d.png
    "rigid grains, R/h = 16=${spacing}_R16_spacing.csv"
    "rigid grains, R/h = 32=${spacing}_R32_spacing.csv"
    "surface diffusion alone (centroids), R/h = 16=${spacing}_surface_only_R16_spacing.csv")
set_tests_properties(study_grains_ring_2d_plot PROPERTIES FIXTURES_REQUIRED
  "study_grains_ring_2d_R16_checked;study_grains_ring_2d_R32_checked;study_grains_ring_2d_surface_only_R16_checked"
  LABELS validation-long)

# --- Settling: the refined band (issue 28, ninth increment;
# doc/validation.md, "Settling the pair: the refined band") ---------------
# The pair of grains_equilibrium_2d.prm (gamma_gb = gamma_s, the sharp
# condition: kink width 2, deposition width 6) to t = 0.05 at R/h = 8, 16
# and 32 with the refined band at 0.8 E, against the exact end
# state (check_grains.py equilibrium, the table in
# doc/validation_data/grains_equilibrium_2d_band_R*.csv). The R/h = 16 run
# is CI's: SETTLED_R16.
foreach(resolution 8 16 32)
  set(name study_grains_equilibrium_2d_band_R${resolution})
  set(settings)
  if(resolution LESS 32)
    set(settings ${GRAINS_R${resolution}})
  endif()
  add_test(NAME ${name}_run COMMAND $<TARGET_FILE:levelsinter> --overwrite
    ${GRAINS_CI_OUTPUT} ${settings} --set "Time/End time=0.05"
    --set "Grain boundaries/Deposition width=6"
    --set "Grain boundaries/Triple-line kink width=2"
    --set "Output/Directory=${name}"
    ${GRAIN_SCENES}/grains_equilibrium_2d.prm)
  add_test(NAME ${name} COMMAND ${CHECK_GRAINS} equilibrium ${name} 1 2
    --csv ${CMAKE_SOURCE_DIR}/doc/validation_data/grains_equilibrium_2d_band_R${resolution}.csv)
  set_tests_properties(${name}_run PROPERTIES FIXTURES_SETUP ${name})
  set_tests_properties(${name} PROPERTIES FIXTURES_REQUIRED ${name}
    LABELS validation-long)
  if(NOT resolution EQUAL 16)
    set_tests_properties(${name}_run PROPERTIES LABELS validation-long)
  endif()
endforeach()
# CI: the pair at R/h = 16 (118 steps, 26 s CPU) settled over t >= 0.03
# (52 rows): R, a, d measured within 1.05, 2.9, 1.8 % of the exact state
# (a where the near circles meet the plane since the tenth increment; the
# rays' a read 3.1 %), psi 112.9 to 120.3 degrees, mean 116.8 (the rows
# swing from step to step with the CFL steps of up to 2e-3, the explicit
# contact law's period-2 oscillation, doc/validation.md "Settling the
# pair: the contact law's step"; at t = 0.05 R, a, d within 0.2 % and psi
# 118.4); limits 5 % and 5 degrees on the mean. With the band at 0.66 E the pair
# at t in [0.005, 0.02] had R, a, d within 2.2, 9.6, 13.6 %.
grains_check(grains_equilibrium_2d_settled study_grains_equilibrium_2d_band_R16
  settled study_grains_equilibrium_2d_band_R16 1 2 0.03 0.05 5)

# --- Settling: the contact law's step (issue 28, tenth increment;
# doc/validation.md, "Settling the pair: the contact law's step") ---------
# The pair of the band studies at R/h = 16 with the step capped at 6e-5
# (Time/Time step; the CFL steps reach 2e-3), to t = 0.03 (500 steps,
# about 4 min of wall on the shared machine; the CFL step's run to t =
# 0.05 takes 118 steps): over
# the 167 rows with t >= 0.02 R, a, d measured within 0.17, 0.28, 0.18 %
# of the exact state, psi 120.4 to 121.1 degrees (mean 120.7), the mean
# change between rows 0.02-0.04 % (0.55-0.92 % with the CFL step, whose
# explicit contact law swings with period 2). Limits the issue's: 1 % and
# 2 degrees on the mean.
set(name study_grains_equilibrium_2d_step_R16)
add_test(NAME ${name}_run COMMAND $<TARGET_FILE:levelsinter> --overwrite
  ${GRAINS_CI_OUTPUT} ${GRAINS_R16} --set "Time/End time=0.03"
  --set "Time/Time step=6e-5"
  --set "Grain boundaries/Deposition width=6"
  --set "Grain boundaries/Triple-line kink width=2"
  --set "Output/Directory=${name}"
  ${GRAIN_SCENES}/grains_equilibrium_2d.prm)
add_test(NAME ${name} COMMAND ${CHECK_GRAINS} settled ${name} 1 2 0.02 0.01 2)
add_test(NAME ${name}_swing COMMAND ${CHECK_GRAINS} swing ${name} 1 2 0.02)
set_tests_properties(${name}_run PROPERTIES FIXTURES_SETUP ${name}
  LABELS validation-long)
set_tests_properties(${name} ${name}_swing PROPERTIES FIXTURES_REQUIRED
  ${name} LABELS validation-long)
# The ring's centroids at R/h = 16 (the study's run to t = 0.02): measured
# +0.20 to +0.86 % from the exact state's centroids at the 4 rows with t
# >= 0.005; limit 1.5 %.
add_test(NAME study_grains_ring_2d_R16_centroids COMMAND ${CHECK_GRAINS}
  centroids-row study_grains_ring_2d_R16 1 12 --from 0.005 --limit 0.015)
set_tests_properties(study_grains_ring_2d_R16_centroids PROPERTIES
  FIXTURES_REQUIRED study_grains_ring_2d_R16 LABELS validation-long)

# --- Settling: the implicit contact law (issue 28, eleventh increment;
# doc/validation.md, "Settling the pair: the implicit contact law") --------
# The implicit law (1 + g_e) G u = C_gb F at every step of the pair of
# grains_two_2d.prm (20 steps, damping g_e up to 0.087): measured 6.6e-12;
# the force balance reproduces it as it does the explicit law; a missing
# damping is off by up to g_e / (1 + g_e) = 8 %; limit 1e-9.
grains_run(grains_two_2d_implicit grains_two_2d.prm 20
  --set "Grain boundaries/Implicit contact law=true")
grains_check(grains_two_2d_implicit_law grains_two_2d_implicit law
  grains_two_2d_implicit 1e-6 0.5 2 1e-9)
# The pair of the band studies (grains_equilibrium_2d.prm, R/h = 16, the
# sharp condition) with the implicit law to t = 0.05. Since the twelfth
# increment the law's steps are limited by its accuracy: no contact's
# approach or deposition moves the surface by more than 0.03 of a finest
# cell in a step (doc/validation.md, "Settling the pair: the step's
# accuracy, clear stops"): 539 steps, 85 s CPU on the shared machine, so
# validation-long (at the CFL step, before the limit: 43 steps, 10 s). The
# rigid approach rate over t >= 0.005 measured -0.80 to -0.07 (the
# explicit law at the CFL step: -11.8 to +8.5, its period-2 oscillation);
# limit 2, above the explicit law's rest drift with the step capped (-2.3
# to +0.3). The shape over the 102 rows with t >= 0.02: R, a, d measured
# within 0.31, 0.53, 0.24 %, psi 118.5 to 120.0, mean 119.1 (at the CFL
# step 3.8, 3.2, 4.2 % and 127.7); limits the issue's, 1 % and 2 degrees.
set(name grains_equilibrium_2d_implicit)
grains_run(${name} grains_equilibrium_2d.prm 1000 ${GRAINS_R16}
  --set "Time/End time=0.05"
  --set "Grain boundaries/Deposition width=6"
  --set "Grain boundaries/Triple-line kink width=2"
  --set "Grain boundaries/Implicit contact law=true")
grains_check(${name}_resting ${name} resting ${name} 0.005 2)
grains_check(${name}_settled ${name} settled ${name} 1 2 0.02 0.01 2)
set_tests_properties(${name}_run ${name}_resting ${name}_settled PROPERTIES
  LABELS validation-long)
# The same at R/h = 32 (the scenes' own mesh), 2D and axisymmetric, with
# the accuracy limit (thirteenth increment; doc/validation.md, "Settling
# the pair: R/h = 32"): 1583 steps, 592 s CPU (2D); 1788 steps, 342 s
# (axisymmetric). Over t >= 0.02 measured R, a, d within 0.58, 0.82, 1.41
# % (2D) and 0.58, 0.34, 1.18 % (axisymmetric), psi's mean 120.1 and
# 120.4: d is a steady -0.9 % on the mean in both (the far circles meet
# the plane at 120.8 degrees), the same with the step capped at 2.5e-4
# (2D) or at the axisymmetric pair's late steps of 5e-5, so not the step.
# The issue's 1 % is met by R and a, not by d's largest: limits 2 % (the
# CFL step's error was 2.5 %, the tenth increment's explicit law 1.8 %)
# and 2 degrees.
foreach(body 2d axisymmetric)
  set(name grains_equilibrium_${body}_implicit_R32)
  grains_run(${name} grains_equilibrium_${body}.prm 3000
    --set "Time/End time=0.05"
    --set "Grain boundaries/Deposition width=6"
    --set "Grain boundaries/Triple-line kink width=2"
    --set "Grain boundaries/Implicit contact law=true")
  if(body STREQUAL "2d")
    set(body_dim 2)
  else()
    set(body_dim 3)
  endif()
  grains_check(${name}_settled ${name} settled ${name} 1 ${body_dim} 0.02
    0.02 2)
  set_tests_properties(${name}_run ${name}_settled PROPERTIES
    LABELS validation-long)
endforeach()

# --- Clear stops (issue 28, twelfth increment; doc/validation.md,
# "Settling the pair: the step's accuracy, clear stops") -----------------
# gamma_gb -> 2 gamma_s: at gamma_gb / gamma_s = 1.9 (psi = 36.4 degrees)
# the pair's equilibrium grain boundary, r sin(psi/2) = 0.078, is narrower
# than the triple line's kernel (l = 6 h = 0.094 at R/h = 16), where the
# eleventh increment measured a relaxation cycle that never settles: the
# run stops at step 0 and says why (measured, 0.4 s CPU).
bad_input_test(grains_neck_unresolved "the neck cannot be resolved"
  --set "Output/Field formats=none" ${GRAINS_R16}
  --set "Grain boundaries/Deposition width=6"
  --set "Grain boundaries/Triple-line kink width=2"
  --set "Grain boundaries/Energy ratio=1.9"
  --set "Output/Directory=grains_neck_unresolved"
  ${GRAIN_SCENES}/grains_equilibrium_2d.prm)
# Above l but below 2 l the runs do not settle (thirteenth increment: R/h
# = 8 at gamma_gb = gamma_s, r sin(psi/2) = 1.15 l; gamma_gb / gamma_s =
# 1.9 at R/h = 32, 1.66 l; doc/validation.md, "Settling the pair: R/h =
# 32, the axisymmetric pair, R/h = 8"), and the 27-grain packing at level
# 2 runs there: the run goes on and says so after its first step. The
# pair at R/h = 8, one step (measured 0.2 s CPU).
set(name grains_neck_barely_resolved)
add_test(NAME ${name} COMMAND $<TARGET_FILE:levelsinter> --overwrite
  --set "Output/Field formats=none" --set "Output/Progress interval=0"
  ${GRAINS_R8} --set "Grain boundaries/Deposition width=6"
  --set "Grain boundaries/Triple-line kink width=2"
  --set "Time/Maximum steps=1" --set "Output/Directory=${name}"
  ${GRAIN_SCENES}/grains_equilibrium_2d.prm)
set_tests_properties(${name} PROPERTIES PASS_REGULAR_EXPRESSION
  "warning: 1 of the 1 grain boundaries have an equilibrium radius r sin\\(psi/2\\) of fewer than 2")
# d -> 0: two grains whose centres are 0.02 apart (R/h = 16: their grain
# boundary 0.01 from each centre, less than a finest cell 0.0156), the
# state a pair reaches when gamma_gb -> 0 merges it into one disc or a
# grain is swallowed: the run stops with the diagnosis (0.4 s CPU). The
# particles are in a file: bad_input_test's arguments are a list, whose
# ';' would split an inline particle list.
bad_input_test(grains_merged "cannot represent"
  --set "Output/Field formats=none" ${GRAINS_R16}
  --set "Geometry/Particles="
  --set "Geometry/Particle file=${CMAKE_CURRENT_SOURCE_DIR}/grains_merged_2d.csv"
  --set "Output/Directory=grains_merged"
  ${GRAIN_SCENES}/grains_equilibrium_2d.prm)
# A grain boundary that disappears is said: the axisymmetric pair at R/h =
# 16 with the refined band at 0.66 E (below surface diffusion's rule, the
# fifth increment's settings) drifts apart and its grain boundary is lost
# at t = 0.0061 (measured, 12 s CPU to t = 0.0085; silently dropped from
# the contacts before the twelfth increment): the run prints the note.
# The trajectory is sensitive to the step times (doc/validation.md, "The
# sharp triple-line condition"): the same run to t = 0.0065 keeps its
# grain boundary, so the test runs the measured one.
set(name grains_lost_boundary_axisymmetric)
add_test(NAME ${name} COMMAND $<TARGET_FILE:levelsinter> --overwrite
  --set "Output/Field formats=none" --set "Output/Metrics interval=10"
  --set "Mesh refinement/Maximum level=4"
  --set "Level set/Filter thickness=0.094"
  --set "Mesh refinement/Band width=0.062"
  --set "Grain boundaries/Deposition width=6"
  --set "Grain boundaries/Triple-line kink width=2"
  --set "Output/Progress interval=0"
  --set "Time/End time=0.0085" --set "Output/Directory=${name}"
  ${GRAIN_SCENES}/grains_equilibrium_axisymmetric.prm)
set_tests_properties(${name} PROPERTIES PASS_REGULAR_EXPRESSION
  "note: t = [0-9.e-]+: the grain boundary of grains 0 and 1 is gone")

# --- The 3D pair at its equilibrium (issue 28, fourteenth increment;
# doc/validation.md, "The 3D pair at its equilibrium") --------------------
# The pair of grains_equilibrium_3d.prm (R/h = 16) started from its exact
# end state (tests/grains_rest_3d.csv: two spheres of the scene's pair
# volume, centres R apart, meeting at psi = 120 degrees) with the implicit
# law and its accuracy limit: where the discrete pair rests. Measured
# (metrics every 2nd step, 131 steps to t = 0.0142, 361 s CPU, 270 MB):
# from t = 0.009 on R, a, d within 0.15, 0.92, 1.22 % of the exact state,
# psi 118.5-118.6 (mean 118.6), the shape's rows changing by 0.01-0.02 %;
# the rigid centres drift apart at -3.6. Measured with End time 0.02,
# stopped by hand at t = 0.0142; the study as registered (End time 0.014,
# metrics every step) was not run. Limits 2 % (d's 1.2 % is above the issue's 1 %) and 2
# degrees.
# grains_rest_3d_study(NAME TOLERANCE ARGS...): that start to t = 0.014,
# validation-long; R, a, d within TOLERANCE and psi's mean within 2
# degrees over t >= 0.009 (the quarter box holds 0.25 of the pair).
function(grains_rest_3d_study name tolerance)
  grains_rest(${name} grains_equilibrium_3d.prm grains_rest_3d.csv
    --set "Time/End time=0.014" ${ARGN})
  add_test(NAME ${name} COMMAND ${CHECK_GRAINS} settled ${name} 1 3 0.009
    ${tolerance} 2 0.25)
  set_tests_properties(${name} PROPERTIES FIXTURES_REQUIRED ${name})
  set_tests_properties(${name}_run ${name} PROPERTIES LABELS validation-long)
endfunction()
grains_rest_3d_study(study_grains_equilibrium_3d_rest_R16 0.02)
# The same start in the axisymmetric pair (R/h = 16, to t = 0.02, 164
# steps, 21 s of wall): it rests where the 3D pair does (over t >= 0.01
# measured R, a, d within 0.36, 0.89, 1.40 %, psi 118.6-118.9, mean 118.8;
# a -0.8 % and d +1.1 % on the mean against the 3D pair's -0.9 and +1.2
# %), so it guards the 3D pair's rest state in CI. Limits 2 % and 2
# degrees.
set(name grains_equilibrium_axisymmetric_rest)
grains_rest(${name} grains_equilibrium_axisymmetric.prm
  grains_rest_axisymmetric.csv ${GRAINS_R16} --set "Time/End time=0.02")
grains_check(${name}_settled ${name} settled ${name} 1 3 0.01 0.02 2)

# --- The sharp contact radius (issue 28, fifteenth increment;
# doc/validation.md, "Settling the pair: the sharp contact radius") ------
bad_input_test(grains_sharp_contact_without_kink "Sharp contact radius"
  --set "Grain boundaries/Sharp contact radius=true"
  ${GRAIN_SCENES}/grains_two_2d.prm)
# The contact law reads a where the near circles meet the plane: the pairs
# from their exact end state rest within the issue's 1 %. The 2D pair at
# R/h = 32 (the scene's mesh, kink width 4; 22 steps to t = 0.02, 6 s
# CPU): measured over t >= 0.01 R, a, d within 0.23, 0.57, 0.40 %, psi's
# mean 118.8 (the rays' a, the law's before, left d at +0.99 % and the
# grains separating at -0.56). The axisymmetric pair at R/h = 16 (kink 2,
# 103 steps, 6 s CPU), which rests within 0.1 % of the 3D pair: R, a, d
# within 0.36, 0.14, 0.62 %, psi's mean 120.0 (rays: 0.36, 0.89, 1.40 %).
# Limits 1 % and 2 degrees; and the law with the a it read (measured
# 6.8e-9 and 3.1e-10: at rest u is 1e-2 of its early values and the CSV's
# 12 digits of a and kappa_root cancel in F; limit 1e-6).
set(name grains_equilibrium_2d_rest_sharp)
grains_rest(${name} grains_equilibrium_2d.prm grains_rest_2d.csv
  --set "Time/End time=0.02"
  --set "Grain boundaries/Deposition width=6"
  --set "Grain boundaries/Triple-line kink width=4"
  --set "Grain boundaries/Sharp contact radius=true")
grains_check(${name}_settled ${name} settled ${name} 1 2 0.01 0.01 2)
grains_check(${name}_law ${name} law ${name} 1 1 2 1e-6)
set(name grains_equilibrium_axisymmetric_rest_sharp)
grains_rest(${name} grains_equilibrium_axisymmetric.prm
  grains_rest_axisymmetric.csv ${GRAINS_R16} --set "Time/End time=0.02"
  --set "Grain boundaries/Sharp contact radius=true")
grains_check(${name}_settled ${name} settled ${name} 1 3 0.01 0.01 2)
grains_check(${name}_law ${name} law ${name} 1 1 3 1e-6)
# The axisymmetric pair relaxing from the scene's start (x/R = 0.22) at
# R/h = 16 with the sharp contact radius, to t = 0.05 (541 steps, 24 s
# CPU): over t >= 0.02 R, a, d within 0.10, 0.15, 0.48 % (metrics every
# step; 0.45 % with every 2nd), psi 119.6-119.8 (the rays' a: 0.29, 1.33,
# 1.97 %, psi 118.1). Limits 1 % and 2 degrees.
set(name grains_equilibrium_axisymmetric_relax_sharp)
grains_run(${name} grains_equilibrium_axisymmetric.prm 3000 ${GRAINS_R16}
  --set "Time/End time=0.05" --set "Grain boundaries/Deposition width=6"
  --set "Grain boundaries/Implicit contact law=true"
  --set "Grain boundaries/Sharp contact radius=true")
grains_check(${name}_settled ${name} settled ${name} 1 3 0.02 0.01 2)
# The 3D pair (R/h = 16, kink 2) from its exact end state with the sharp
# contact radius (77 steps to t = 0.014, 200 s CPU, 310 MB): over t >=
# 0.009 R, a, d within 0.32, 0.07, 0.49 %, psi 119.8-119.9 (the rays':
# 0.15, 0.92, 1.22 %, psi 118.6). Limits 1 % and 2 degrees.
grains_rest_3d_study(study_grains_equilibrium_3d_rest_sharp_R16 0.01
  --set "Grain boundaries/Sharp contact radius=true")

# --- gamma_gb -> 0 (issue 28, fifteenth increment; doc/validation.md,
# "Grain boundaries without energy: gamma_gb = 0") -------------------------
# The pair of grains_equilibrium_2d.prm at gamma_gb = 0 (psi = 180
# degrees, the triple-line condition off: nothing to turn), R/h = 8, the
# explicit law, to t = 0.01: the grains approach until the solid is one
# disc, the single level set's end state. Measured (to t = 0.5, 159
# steps, 46 s of wall): the interface length within +0.04 to +0.64 % of
# 2 sqrt(pi A) from t = 0.002 on; the rigid centres, held by no force
# once the body is round, then drift apart inside it and the contact is
# dropped at t = 0.234 with the note. Limit 1 % from t = 0.003.
set(name grains_energy_ratio_0)
grains_run(${name} grains_equilibrium_2d.prm 1000 ${GRAINS_R8}
  --set "Time/End time=0.01" --set "Grain boundaries/Energy ratio=0"
  --set "Grain boundaries/Triple-line condition=false"
  --set "Grain boundaries/Deposition width=6")
grains_check(${name}_disc ${name} disc ${name} 0.003 0.01)

# --- gamma_gb / gamma_s = 1.5 (issue 28, sixteenth increment;
# doc/validation.md, "Pairs at gamma_gb / gamma_s = 1.5") -----------------
# The 2D pair at R/h = 32 (kink 4 = R / 8, deposition width 6, the sharp
# contact radius, the implicit law) from its exact end state at psi =
# 82.8 degrees (tests/grains_rest_2d_ratio1.5.csv), to t = 0.02 (61 steps,
# 18 s CPU): measured over t >= 0.01 R, a, d within 0.43, 1.98, 0.52 %,
# psi's mean 81.4 (exact 82.82). Limits 2.5 % (a, the near circles' neck, rests
# 1.3 % narrow on the mean) and 2 degrees; the law to 1e-6.
set(name grains_ratio15_2d_rest)
grains_rest(${name} grains_equilibrium_2d.prm grains_rest_2d_ratio1.5.csv
  --set "Time/End time=0.02" --set "Grain boundaries/Energy ratio=1.5"
  --set "Grain boundaries/Deposition width=6"
  --set "Grain boundaries/Triple-line kink width=4"
  --set "Grain boundaries/Sharp contact radius=true")
grains_check(${name}_settled ${name} settled ${name} 1.5 2 0.01 0.025 2)
grains_check(${name}_law ${name} law ${name} 1 1.5 2 1e-6)

# --- Per-grain materials (issue 28, sixteenth increment; doc/validation.md,
# "Per-grain materials: the two-material pair") ---------------------------
bad_input_test(grains_factors_count "gives 3 factors for 2 grains"
  --set "Grain boundaries/Surface diffusion factors=1, 2, 3"
  ${GRAIN_SCENES}/grains_two_materials_2d.prm)
bad_input_test(grains_factors_positive "every factor must be positive"
  --set "Grain boundaries/Coefficient factors=1, 0"
  ${GRAIN_SCENES}/grains_two_materials_2d.prm)
# Every grain's factor k is the one-material run with C_s and C_gb times
# k: the two-material pair at R/h = 8 (kink 1 = R / 8), 10 steps, factors
# 2 for both against the coefficients 2. Measured largest relative
# difference 6.3e-7 (the scaled surface-diffusion system differs in its
# unknowns' scale, so the iterative solve stops at other iterates, one
# iteration apart); limit 5e-6. A factor lost on one path (the surface, the balance, the
# implicit law's damping or stiffness) is off by O(1).
set(GRAINS_MATERIALS_R8 ${GRAINS_R8}
  --set "Grain boundaries/Triple-line kink width=1"
  --set "Output/Field formats=none" --set "Output/Progress interval=0"
  --set "Output/Metrics interval=1" --set "Time/Maximum steps=10")
add_test(NAME grains_materials_factors_run COMMAND $<TARGET_FILE:levelsinter>
  --overwrite ${GRAINS_MATERIALS_R8}
  --set "Grain boundaries/Surface diffusion factors=2, 2"
  --set "Grain boundaries/Coefficient factors=2, 2"
  --set "Output/Directory=grains_materials_factors"
  ${GRAIN_SCENES}/grains_two_materials_2d.prm)
add_test(NAME grains_materials_coefficients_run
  COMMAND $<TARGET_FILE:levelsinter> --overwrite ${GRAINS_MATERIALS_R8}
  --set "Grain boundaries/Surface diffusion factors="
  --set "Grain boundaries/Coefficient factors="
  --set "Surface diffusion/Coefficient=2" --set "Grain boundaries/Coefficient=2"
  --set "Output/Directory=grains_materials_coefficients"
  ${GRAIN_SCENES}/grains_two_materials_2d.prm)
set_tests_properties(grains_materials_factors_run PROPERTIES
  FIXTURES_SETUP grains_materials_factors)
set_tests_properties(grains_materials_coefficients_run PROPERTIES
  FIXTURES_SETUP grains_materials_coefficients)
add_test(NAME grains_materials_scaled COMMAND compare_metrics
  grains_materials_factors/metrics.csv
  grains_materials_coefficients/metrics.csv 5e-6 ${TIMING_COLUMNS}
  surface_diffusion_iterations transport_iterations)
set_tests_properties(grains_materials_scaled PROPERTIES FIXTURES_REQUIRED
  "grains_materials_factors;grains_materials_coefficients")
# The pair of grains_two_2d.prm (the scene of grains_two_2d_1_vs_2_ranks)
# with factors 1 and 0.25 (C_gb of the boundary 0.625) on 1 and 2 ranks,
# 10 steps: measured 6.4e-8; limit 1e-6. (The pair of
# grains_two_materials_2d.prm at R/h = 8 differs by 1e-3 in max_velocity
# between 1 and 2 ranks from its first step with one material too, with
# or without the triple-line condition, the sharp radius and the implicit
# law: not this increment's, not investigated.) And the balance gives the
# contact law with the boundary's mean C_gb: u = 0.625 C_gb F / G at
# every step, measured 4.0e-12 (limit 1e-9; with C_gb it is off by 60 %).
ranks_agree(grains_two_materials grains_two_materials
  ${GRAIN_SCENES}/grains_two_2d.prm 1e-6
  "surface_diffusion_iterations;transport_iterations"
  --set "Grain boundaries/Surface diffusion factors=1, 0.25"
  --set "Grain boundaries/Coefficient factors=1, 0.25"
  --set "Time/Maximum steps=10" --set "Output/Metrics interval=1"
  --set "Output/Progress interval=0")
grains_check(grains_two_materials_law grains_two_materials_np1 law
  grains_two_materials_np1 0.625e-6 0.5 2 1e-9)
# Restart 1 -> 2 ranks of the same pair with its factors (the settings of
# restart_grains_two_2d_np1_np2): the factors are the scene's, read again
# on --resume, and the surface solve's nodal factors are written from the
# resumed centres. Measured 2.1e-8 (metrics); limit 1e-6.
restart_test(restart_grains_two_materials_2d_np1_np2
  ${GRAIN_SCENES}/grains_two_2d.prm 1 2 1e-6
  "${RESTART_GRAINS_IGNORED};cells;dofs" ${RESTART_GRAINS_ARGS}
  --set "Grain boundaries/Surface diffusion factors=1, 0.25"
  --set "Grain boundaries/Coefficient factors=1, 0.25")
# The axisymmetric pair (R/h = 16, kink 2, the settings of
# grains_equilibrium_axisymmetric_relax_sharp) with factors 1 and 0.25,
# from the scene's start: its approach lies between the one-material
# pair's (both grains 1) and the same at a quarter of the coefficients,
# which is that pair at t / 4 (the flow is linear in the coefficients;
# test grains_materials_scaled). Measured to t = 7e-4, where the fast
# pair's approach peaks: at 0.50-0.92 of the gap from the slow bound
# (mostly 0.55-0.68: like one material of about half the mobility); the
# check: strictly inside. (Beyond, the one-material pair rests and its
# rigid grains drift apart at -1.7, the two-material pair's runs away:
# doc/validation.md, "Per-grain materials: the two-material pair".)
set(GRAINS_AXISYMMETRIC_EARLY ${GRAINS_R16} --set "Time/End time=7e-4"
  --set "Grain boundaries/Deposition width=6"
  --set "Grain boundaries/Implicit contact law=true"
  --set "Grain boundaries/Sharp contact radius=true")
grains_run(grains_two_materials_axisymmetric grains_equilibrium_axisymmetric.prm
  3000 ${GRAINS_AXISYMMETRIC_EARLY}
  --set "Grain boundaries/Surface diffusion factors=1, 0.25"
  --set "Grain boundaries/Coefficient factors=1, 0.25")
grains_run(grains_one_material_axisymmetric grains_equilibrium_axisymmetric.prm
  3000 ${GRAINS_AXISYMMETRIC_EARLY})
grains_check(grains_two_materials_axisymmetric_bracket
  "grains_two_materials_axisymmetric;grains_one_material_axisymmetric"
  bracket grains_two_materials_axisymmetric grains_one_material_axisymmetric
  0.25 7e-4)
# The scene grains_two_materials_2d.prm at R/h = 16 (kink 2 = R / 8),
# relaxing from x/R = 0.22 to t = 0.1 (470 steps, 49 s CPU): over t >=
# 0.05 R, a, d within 0.35, 0.92, 0.81 % of the one-material exact state,
# psi 116.8-118.2 on the near circles (the far circles meet at 120.2);
# the one-material pair of the same settings (531 steps, 51 s CPU): 0.28,
# 0.36, 0.56 %, psi 119.0-120.2. Limits 1 % and 3 degrees (the near
# circles' mean 2.7 degrees sharp, said in doc/validation.md).
set(name study_grains_two_materials_2d_R16)
grains_run(${name} grains_two_materials_2d.prm 3000 ${GRAINS_R16}
  --set "Grain boundaries/Triple-line kink width=2")
add_test(NAME ${name} COMMAND ${CHECK_GRAINS} settled ${name} 1 2 0.05 0.01
  3)
set_tests_properties(${name} PROPERTIES FIXTURES_REQUIRED ${name})
set_tests_properties(${name}_run ${name} PROPERTIES LABELS validation-long)
