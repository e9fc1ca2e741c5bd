# --- Volume diffusion: the mechanism (Algorithm 3) ------------------------
set(VD_GRAINS ${CMAKE_SOURCE_DIR}/parameter_files/two_grains_volume_diffusion_2d.prm)

# Two equal grains R = 0.2 (paper Sect. 6.6, Table 7), h = 1/128, the CFL
# number 0.5 and the explicit limit (vd_stability.cmake) choosing dt, with
# the volume correction (Eq. 116), to the scene's end time t = 0.1 s (37
# steps, 28 with the CFL number alone; at most 40). Measured: neck
# 0.04614 -> 0.1305 (x/R 0.23 -> 0.65, x 2.83), |dV/V| at most 7.8e-6
# over the samples (1.7e-6 with 28 steps); 15.8 s CPU. Limits: growth x 2 (a wrong sign of v shrinks
# the neck), |dV/V| 1e-5. A check of the wiring and of the trend, not of
# the rate (no reference value at these settings). On a circle (xi = 0
# exactly) the scene's lambda = 6 cells leaves a spurious C_v |xi| of
# 0.011 um/s (0.60 at the default lambda = 3, measured).
add_test(NAME volume_diffusion_two_grains_2d COMMAND ${SD_VALIDATE} neck
  ${VD_GRAINS} 40 --sample-interval 5 --min-neck-growth 2
  --max-volume-change 1e-5)

# 1 and 2 ranks, 10 steps: the elastic solve (AMG/ILU per rank, relative
# 1e-10) differs with the partition, the interface hardly. Measured: neck
# and area agree to 7.0e-6 and 7.9e-7; max_velocity and the volume
# correction speed (a difference of nearly equal volumes) to 5.6e-5 (not
# compared, nor iterations, times and mesh counts); checked at 2e-5.
ranks_agree(volume_diffusion vd ${VD_GRAINS} 2e-5
  "transport_iterations;cells;dofs;volume_change;max_velocity;volume_correction_speed;volume_diffusion_mechanics_iterations;volume_diffusion_xi_iterations"
  --set "Time/Maximum steps=10" --set "Output/Metrics interval=1")

# The combinations SceneParameters refuses.
bad_input_test(volume_diffusion_with_viscous_flow "Volume diffusion/Enabled"
  --set "Viscous flow/Enabled=true" ${VD_GRAINS})
bad_input_test(volume_diffusion_newtonian "Phase law/Law"
  --set "Phase law/Law=newtonian" ${VD_GRAINS})

# The linear check: the perturbed cylinder r = R (1 + delta cos 2 theta),
# R = 0.25, delta = 0.05, elastic (Table 7 moduli, nu = 0.25), decays at
# s_2 = (2/3)(1 + nu) n (n^2 - 1) = 5.294 in t* = C_v gamma t / R^3
# (doc/numerics.md). h = 1/128, lambda = 6 cells, E = 0.12 covered by the
# refined band, half an e-folding time. The explicit limit
# (vd_stability.cmake) turns the 20 steps asked into 43 (measured +2.4 %). Measured rate 5.477 (+3.5 %) with
# 20 steps per e-folding time, 5.429 (+2.6 %) with 40 (first order in dt:
# ~+1.6 % at dt -> 0); area change 1.8e-4; 5 s. At the default lambda = 3
# cells the mode grew instead (rate -297: the spurious xi of the elastic
# pressure, measured). Limits: 6 % and 3e-4.
set(VD_CYLINDER
  --set "Surface diffusion/Enabled=false"
  --set "Volume diffusion/Enabled=true"
  --set "Volume diffusion/Coefficient=0.013"
  --set "Volume diffusion/Interior offset=6"
  --set "Volume diffusion/Time unit=reduced"
  --set "Volume diffusion/Reference radius=0.25"
  --set "Materials/Surface tension=0.9"
  --set "Materials/Fluid viscosity=1e-3"
  --set "Materials/Fluid compressibility=0"
  --set "Viscous flow/Stabilisation constant=0.1"
  --set "Viscous flow/Linear solver=iterative"
  --set "Phase law/Law=elastic-solid"
  --set "Phase law/Shear modulus=156e3"
  --set "Phase law/Bulk modulus=390e3"
  --set "Mesh refinement/Minimum level=3")
add_test(NAME volume_diffusion_cylinder_mode2_2d COMMAND ${SD_VALIDATE}
  mullins ${PERTURBED} 5 20 --time-fraction 0.5 --filter-thickness 0.12
  --band-width 0.118 ${VD_CYLINDER} --max-rate-error 0.06
  --max-volume-change 3e-4)

# vd_elastic_solves_test(NAME DIRECTORY OUTPUT CALLS ARGS...): the two
# grains with ARGS must print OUTPUT and solve the elastic problem CALLS
# times (timer_calls.cmake).
function(vd_elastic_solves_test name directory output calls)
  # Quoted, ARGN keeps an escaped \; inside an argument.
  set(command "$<TARGET_FILE:levelsinter>;--overwrite;${VD_GRAINS};${ARGN}")
  list(APPEND command --set "Output/Field formats=none"
    --set "Output/Directory=${directory}")
  add_test(NAME ${name} COMMAND ${CMAKE_COMMAND} "-DCOMMAND=${command}"
    "-DOUTPUT=${output}" -DDIRECTORY=${directory}
    "-DSECTION=volume diffusion: elastic solve" -DCALLS=${calls}
    -P ${CMAKE_CURRENT_SOURCE_DIR}/timer_calls.cmake)
endfunction()

# A step taken again shorter keeps the elastic solve (VolumeDiffusion::
# shorten_step(): with Delta u = dt v the elastic pressure does not depend
# on dt). The two grains with a translation that jumps from 0 to 30 (about
# 20x the diffusion speed) at t = 0.004: 14 steps to t = 0.0052, 2 of them
# computed again; 15 elastic solves (the steps and the first step's speed
# probe), where recomputing took 17. Against the recomputing build
# (7890ab4, tests/reference/vd_shortened_step_2d_metrics.csv) the metrics
# agree to 5.9e-5 (the largest speed; the neck 1.8e-5), checked at 2e-4;
# not compared: the volume change and correction speed (differences of
# nearly equal volumes, 1.4e-3 and 1.6e-3 relative of values near 1e-6),
# the neck curvature (a second derivative, 1.2e-3), times and iterations.
vd_elastic_solves_test(volume_diffusion_shortened_step_keeps_solve
  vd_shortened_step "done: 14 steps.*2 step\\(s\\) computed again" 15
  --set "Velocity/Type=expression"
  --set "Velocity/Expression=U*(t < 0.004 ? 0 : 1)\\; 0"
  --set "Velocity/Expression constants=U=30" --set "Time/End time=0.0052")
set_tests_properties(volume_diffusion_shortened_step_keeps_solve PROPERTIES
  FIXTURES_SETUP vd_shortened_step)
metrics_unchanged(volume_diffusion_shortened_step_unchanged
  vd_shortened_step vd_shortened_step_2d_metrics.csv 2e-4
  transport_iterations volume_change volume_correction_speed neck_curvature
  volume_diffusion_mechanics_iterations volume_diffusion_xi_iterations)

# `Elastic solve interval = 2`: a step between two mesh adaptations (the
# scene adapts every 2nd step) keeps the elastic solve of the step before.
# The two grains to t = 0.02: 10 steps, 6 elastic solves (the first step's
# speed probe and every second step) where interval 1 takes 11. The neck
# at t = 0.02 is 0.0792 against 0.0799 (measured, 27 Nov 2026).
vd_elastic_solves_test(volume_diffusion_solve_interval_keeps_solve
  vd_solve_interval "done: 10 steps" 6
  --set "Volume diffusion/Elastic solve interval=2"
  --set "Time/End time=0.02")

# --- xi from a recovered gradient (issue 27, fifth increment) ---------------
# 'Volume diffusion/Pressure gradient = recovered': grad p projected over the
# solid part of the cells (doc/numerics.md, "Volume diffusion: a recovered
# gradient"). The cylinder of volume_diffusion_cylinder_mode2_2d at
# lambda = 3 cells with the extended pressure, 20 steps of dt* = 1e-5 (below
# the explicit limits). Measured rate error +0.48 % (area change -2.6e-6)
# against +3.3 % with the nodal gradient, and with the continuous pressure
# +18.5 % recovered, +55 % nodal (doc/validation.md, "Sharp interfaces: a
# recovered gradient for xi"). Limit 2 %: the nodal gradient fails it.
add_test(NAME volume_diffusion_recovered_gradient_lambda3_2d
  COMMAND ${SD_VALIDATE} mullins ${PERTURBED} 5 20 --time-fraction 1.0588e-3
  --filter-thickness 0.12 --band-width 0.118 ${VD_CYLINDER}
  --set "Volume diffusion/Interior offset=3"
  --set "Volume diffusion/Pressure gradient=recovered"
  --set "Viscous flow/Pressure space=extended"
  --set "Volume diffusion/Time step factor=0" --max-rate-error 0.02)
# 1 and 2 ranks, the two grains' 10 steps of the ranks_agree check above with
# the recovered gradient (its sums over the cut cells are added across
# ranks). Measured (the same code switched by an environment variable, the
# build with the entry did not finish in the session that added it): neck
# 9.3e-6, neck curvature 4.3e-5 (a second derivative; the nodal check's
# 2e-5 fails on it), solid volume 1.7e-9; checked at 1e-4.
ranks_agree(volume_diffusion_recovered vd_recovered ${VD_GRAINS} 1e-4
  "transport_iterations;cells;dofs;volume_change;max_velocity;volume_correction_speed;volume_diffusion_mechanics_iterations;volume_diffusion_xi_iterations"
  --set "Volume diffusion/Pressure gradient=recovered"
  --set "Time/Maximum steps=10" --set "Output/Metrics interval=1")
