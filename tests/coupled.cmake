# --- Surface and volume diffusion together (Eq. 118, Algorithm 4) ----------
# One scene, three runs: coupled, surface only, volume only (the other
# mechanism switched off with --set).
set(COUPLED ${CMAKE_SOURCE_DIR}/parameter_files/two_grains_coupled_2d.prm)
set(COUPLED_ONLY_surface --set "Volume diffusion/Enabled=false")
set(COUPLED_ONLY_volume --set "Surface diffusion/Enabled=false")
set(COUPLED_ONLY_coupled)
set(COMPARE_NECKS ${CMAKE_SOURCE_DIR}/scripts/compare_neck_curves.py)

# Both sections in reduced time: one scene has one time.
bad_input_test(coupled_two_reduced_times "Volume diffusion/Time unit"
  --set "Surface diffusion/Time unit=reduced"
  --set "Surface diffusion/Reference radius=0.2"
  --set "Volume diffusion/Time unit=reduced"
  --set "Volume diffusion/Reference radius=0.2" ${COUPLED})

# CI: the three runs to t = 0.003 s (CFL 0.5; from x/R = 0.22), the neck
# sampled every step and compared at t = 0.002 and 0.003 (interpolated in
# log t): the coupled neck must lie above each mechanism's alone.
# Measured: x/R at t = 0.002 / 0.003: surface 0.279 / 0.300, volume
# 0.254 / 0.263, coupled 0.301 / 0.326 (8.7 % above surface diffusion at
# 0.003; 8, 2 and 8 steps; 2.7, 1.5 and 6.6 s CPU). Coupled: neck growth
# x 1.41, checked at x 1.3 (surface alone: x 1.30); volume change with
# v^c at most 8.3e-6 over the samples (-3.1e-6 at the end), without v^c
# -4.8e-3 at the end: checked at 3e-5.
set(COUPLED_CI_LIMITS_coupled --min-neck-growth 1.3 --max-volume-change 3e-5)
foreach(run coupled surface volume)
  add_test(NAME coupled_diffusion_${run}_2d COMMAND ${SD_VALIDATE} neck
    ${COUPLED} 100 --sample-interval 1 --set "Time/End time=0.003"
    ${COUPLED_ONLY_${run}} --csv coupled_ci_${run}.csv
    ${COUPLED_CI_LIMITS_${run}})
  set_tests_properties(coupled_diffusion_${run}_2d PROPERTIES
    FIXTURES_SETUP coupled_ci_${run})
endforeach()
add_test(NAME coupled_diffusion_faster_2d
  COMMAND ${Python3_EXECUTABLE} ${COMPARE_NECKS} --time t --t-star 0.002,0.003
    --window 0.22,1 --last-largest surface=coupled_ci_surface.csv
    volume=coupled_ci_volume.csv coupled=coupled_ci_coupled.csv)
set_tests_properties(coupled_diffusion_faster_2d PROPERTIES
  FIXTURES_REQUIRED "coupled_ci_coupled;coupled_ci_surface;coupled_ci_volume")

# --- Study: the coupled pair of the paper's Fig. 47 (label validation-long) --
# The scene to its end time t = 0.1 s (the paper's volume-diffusion runs
# end there, Fig. 45: 250 steps of 4e-4 s) at CFL 0.5, and at CFL 0.25 as
# the time-step check; the neck sampled every step. Fits and comparisons:
# scripts/compare_neck_curves.py --time t (doc/validation.md).
set(COUPLED_STUDIES)
foreach(cfl 0.5 0.25)
  if(cfl STREQUAL "0.5")
    set(suffix "")
  else()
    set(suffix "_cfl${cfl}")
  endif()
  foreach(run coupled surface volume)
    set(name study_coupled_pair_${run}${suffix}_2d)
    add_test(NAME ${name} COMMAND ${SD_VALIDATE} neck ${COUPLED} 3000
      --sample-interval 1 --set "Time/CFL number=${cfl}"
      ${COUPLED_ONLY_${run}} --csv coupled_pair_${run}${suffix}_2d.csv)
    set_tests_properties(${name} PROPERTIES FIXTURES_SETUP ${name})
    list(APPEND COUPLED_STUDIES ${name})
  endforeach()
endforeach()
# Fig. 47: the three neck curves against t.
add_test(NAME study_coupled_pair_plot_2d
  COMMAND ${CMAKE_SOURCE_DIR}/scripts/plot_neck_growth.py
    coupled_pair_neck_2d.png --time t
    "surface only=coupled_pair_surface_2d.csv"
    "volume only=coupled_pair_volume_2d.csv"
    "coupled=coupled_pair_coupled_2d.csv")
set_tests_properties(study_coupled_pair_plot_2d PROPERTIES FIXTURES_REQUIRED
  "study_coupled_pair_surface_2d;study_coupled_pair_volume_2d;study_coupled_pair_coupled_2d")
list(APPEND COUPLED_STUDIES study_coupled_pair_plot_2d)
set_tests_properties(${COUPLED_STUDIES} PROPERTIES LABELS validation-long)

# One scene time: the coupled scene in the volume-diffusion reduced time
# t* = C_v gamma t / R^3 = 1.4625 t (R = 0.2) must take the same steps as
# in seconds, both coefficients converted (SceneParameters::
# seconds_per_time_unit()): 3 fixed steps of 2e-4 s = 2.925e-4 in t*, end
# time 0.1 s = 0.14625 (the loop spreads the remaining time evenly over
# the steps). The geometry columns must agree to roundoff (checked at
# 1e-8); time, dt and the speeds scale with the unit, iterations and
# timings are not compared.
foreach(unit seconds reduced)
  if(unit STREQUAL "seconds")
    set(step 2e-4)
    set(end 0.1)
  else()
    set(step 2.925e-4)
    set(end 0.14625)
  endif()
  add_test(NAME coupled_time_${unit}
    COMMAND levelsinter --overwrite --set "Time/Time step=${step}"
      --set "Time/End time=${end}"
      --set "Time/CFL number=0" --set "Time/Maximum steps=3"
      --set "Volume diffusion/Time unit=${unit}"
      --set "Volume diffusion/Reference radius=0.2"
      --set "Output/Directory=coupled_time_${unit}"
      --set "Output/Field formats=none" ${COUPLED})
  set_tests_properties(coupled_time_${unit} PROPERTIES
    FIXTURES_SETUP coupled_time_${unit})
endforeach()
add_test(NAME coupled_time_reduced_as_seconds
  COMMAND compare_metrics coupled_time_seconds/metrics.csv
    coupled_time_reduced/metrics.csv 1e-8 time dt wall_time max_velocity
    volume_correction_speed transport_iterations surface_diffusion_iterations
    surface_diffusion_solve_cpu_time volume_diffusion_mechanics_iterations
    volume_diffusion_xi_iterations)
set_tests_properties(coupled_time_reduced_as_seconds PROPERTIES
  FIXTURES_REQUIRED "coupled_time_seconds;coupled_time_reduced")
