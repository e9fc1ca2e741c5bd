# --- Scene parameters: cross-section checks, renamed entries (issue 14) ----
set(TWO_PARTICLES ${CMAKE_SOURCE_DIR}/parameter_files/two_particles_2d.prm)
set(CYLINDERS ${CMAKE_SOURCE_DIR}/parameter_files/two_cylinders_circles_2d.prm)

# A renamed entry still works: its value moves to the new entry, a warning
# names both, and the run proceeds (2 steps of Hopper's scene).
add_test(NAME parameters_deprecated_entry COMMAND levelsinter
  --set "Viscous flow/Symmetry planes=y-" --set "Viscous flow/Solver=iterative"
  --set "Time/Maximum steps=2" --set "Output/Field formats=none"
  --overwrite --set "Output/Directory=parameters_deprecated_entry"
  ${CYLINDERS})
set_tests_properties(parameters_deprecated_entry PROPERTIES
  PASS_REGULAR_EXPRESSION
  "warning: 'Viscous flow/Symmetry planes' is deprecated, use 'Domain/Symmetry planes'.*warning: 'Viscous flow/Solver' is deprecated, use 'Viscous flow/Linear solver'.*done: 2 steps")
# A bad value under the old name is refused naming the old entry.
bad_input_test(deprecated_entry_bad_value
  "'Viscous flow/Solver' (deprecated, now 'Viscous flow/Linear solver')"
  --set "Viscous flow/Solver=cholesky" ${CYLINDERS})

# Viscous flow with neither surface tension nor external pressure has
# nothing to drive it (zero right-hand side: the Stokes solver never ran and
# reported 4294967295 iterations).
bad_input_test(viscous_zero_surface_tension
  "entry 'Materials/Surface tension': must be positive"
  --set "Materials/Surface tension=0" ${CYLINDERS})

# A mesh that cannot fit in memory is refused with the estimate: level 14
# on two 3D spheres is about 1e12 cells.
bad_input_test(mesh_beyond_memory "GB of memory of this machine"
  --set "Mesh refinement/Maximum level=14"
  ${CMAKE_SOURCE_DIR}/parameter_files/two_spheres_3d.prm)

# Particles that cannot be a sintering problem (scene/particles.h,
# check_particle_pairs): the same centre (the smaller one inside the
# other), a particle of the particle file inside another (named by file and
# line), centres closer than one band cell (1/32 at level 5).
bad_input_test(coincident_particles
  "particle 3 (entry 'Geometry/Particles', item 3: centre 0.32, 0.5, radius 0.1) lies inside particle 1 (entry 'Geometry/Particles', item 1"
  ${BAD}/coincident_particles.prm)
bad_input_test(particle_inside_another
  "inside_particles.csv', line 4: centre 0.55, 0.5, radius 0.08) lies inside particle 2 (particle file"
  ${BAD}/inside_particle.prm)
bad_input_test(centres_closer_than_a_cell
  "have centres 0.01 apart, less than one cell of the interface band (0.03125)"
  ${BAD}/close_centres.prm)

# A particle smaller than 2 band cells is refused with the level that
# resolves it.
bad_input_test(particle_too_small "Maximum level 8 would resolve it"
  ${BAD}/small_particle.prm)

# Particle file headers: columns in any order, case and spaces ignored
# (the two particles of the scene read back reordered; measured: the same
# first metrics row as the inline particles, 11716 cells, solid area
# 0.246617672196); a header that does not name them is refused with the
# file and line.
add_test(NAME parameters_particle_header_order COMMAND levelsinter
  --set "Geometry/Particles=" --set
  "Geometry/Particle file=${CMAKE_CURRENT_SOURCE_DIR}/scenes/reordered_particles.csv"
  --set "Time/Maximum steps=1" --set "Output/Field formats=none"
  --overwrite --set "Output/Directory=parameters_particle_header_order"
  ${TWO_PARTICLES})
set_tests_properties(parameters_particle_header_order PROPERTIES
  PASS_REGULAR_EXPRESSION "done: 1 steps")
# A relative path given with --set is the shell's, relative to the working
# directory (here tests/scenes), not to the scene file's folder
# (parameter_files/, which holds no such file).
add_test(NAME parameters_set_path_relative_to_working_directory
  COMMAND levelsinter --set "Geometry/Particles="
  --set "Geometry/Particle file=reordered_particles.csv"
  --set "Time/Maximum steps=1" --set "Output/Field formats=none" --overwrite
  --set "Output/Directory=${CMAKE_CURRENT_BINARY_DIR}/parameters_set_path"
  ${TWO_PARTICLES}
  WORKING_DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/scenes)
set_tests_properties(parameters_set_path_relative_to_working_directory
  PROPERTIES PASS_REGULAR_EXPRESSION "done: 1 steps")
bad_input_test(particle_file_header
  "header_particles.csv', line 2: the header 'x,y,radius' must name"
  ${BAD}/bad_header.prm)

# Shape = hopper: the two circles must be equal and overlap, and Hopper's
# shape of them (longer than the circles) must fit the domain.
set(HOPPER_SCENE ${CMAKE_SOURCE_DIR}/parameter_files/two_cylinders_2d.prm)
# (The circles come from a file: a ';' would split the test's argument list.)
bad_input_test(hopper_shape_unequal_radii "exactly two particles of the same radius"
  --set "Geometry/Particles=" --set
  "Geometry/Particle file=${CMAKE_CURRENT_SOURCE_DIR}/hygiene/particles_2d.csv"
  ${HOPPER_SCENE})
bad_input_test(hopper_shape_outside "outside the domain"
  --set "Domain/Lower corner=-0.49, 0" --set "Domain/Upper corner=0.49, 0.8"
  ${HOPPER_SCENE})

# --- Errors first, noise never (issue 29) ----------------------------------
# bad_input.cmake requires every refusal to be one printable line on
# stderr: the elastic law under viscous flow (viscous_elastic_law) no
# longer prints deal.II's TimerOutput block first, a bad velocity
# expression (bad_expression) no muparser dump.
# A binary file as the scene (the program itself) is named, not echoed.
bad_input_test(binary_scene "is not a text file (a binary byte on line"
  $<TARGET_FILE:levelsinter>)
# A directory as the particle file is named as one.
bad_input_test(particle_file_directory "is a directory, not a file"
  --set "Geometry/Particles=" --set "Geometry/Particle file=${BAD}"
  ${TWO_PARTICLES})
# A rule across entries names the --set that broke it and the scene file
# that gave the entry it is about.
bad_input_test(set_named_across_entries
  "${TWO_PARTICLES}', --set 'Time/Time step=0': entry 'Time/CFL number'"
  --set "Time/Time step=0" ${TWO_PARTICLES})
# A malformed --set is echoed as given.
bad_input_test(set_without_entry
  "--set '=5': expected 'Section/entry=value'" --set "=5" ${TWO_PARTICLES})

# --- Quiet that is not silent (issue 29) -----------------------------------
# A step longer than the run is cut to the run, with a warning.
add_test(NAME parameters_time_step_longer_than_run COMMAND levelsinter
  --set "Time/Time step=100" --set "Time/Maximum steps=1"
  --set "Output/Field formats=none" --overwrite
  --set "Output/Directory=parameters_time_step_longer_than_run"
  ${TWO_PARTICLES})
set_tests_properties(parameters_time_step_longer_than_run PROPERTIES
  PASS_REGULAR_EXPRESSION
  "warning: 'Time/Time step' = 100 is longer than the run \\(End time - Start time = 0.1\\): the steps are at most 0.1.*done: 1 steps to t = 0.1")
# No mechanism: the run says that each step only reinitialises.
add_test(NAME parameters_no_mechanism COMMAND levelsinter
  --set "Time/End time=0" --set "Output/Field formats=none" --overwrite
  --set "Output/Directory=parameters_no_mechanism" ${TWO_PARTICLES})
set_tests_properties(parameters_no_mechanism PROPERTIES
  PASS_REGULAR_EXPRESSION
  "mechanisms: none \\(nothing moves the interface: each step only reinitialises the level set\\)")
# Viscous flow with surface diffusion: the velocities add, with a warning;
# in the reduced time of surface diffusion the flow is refused.
add_test(NAME parameters_viscous_and_surface_diffusion COMMAND levelsinter
  --set "Surface diffusion/Enabled=true"
  --set "Surface diffusion/Coefficient=1e-6" --set "Time/End time=0"
  --set "Output/Field formats=none" --overwrite
  --set "Output/Directory=parameters_viscous_and_surface_diffusion"
  ${CYLINDERS})
set_tests_properties(parameters_viscous_and_surface_diffusion PROPERTIES
  PASS_REGULAR_EXPRESSION
  "warning: viscous flow and surface diffusion are both enabled: the interface moves with the sum.*mechanisms: viscous flow, surface diffusion")
bad_input_test(viscous_reduced_time "entry 'Surface diffusion/Time unit': cannot be 'reduced' with viscous flow"
  --set "Surface diffusion/Enabled=true"
  --set "Surface diffusion/Coefficient=1e-6"
  --set "Surface diffusion/Time unit=reduced"
  --set "Surface diffusion/Reference radius=0.25" ${CYLINDERS})

# --- Materials (issue 29) --------------------------------------------------
# The surface tension and the atmosphere moved from Viscous flow to
# Materials; the old names still work with a warning.
add_test(NAME parameters_deprecated_materials COMMAND levelsinter
  --set "Viscous flow/Surface tension=1"
  --set "Viscous flow/Fluid viscosity=1e-3"
  --set "Viscous flow/Fluid compressibility=1" --set "Time/End time=0"
  --set "Output/Field formats=none" --overwrite
  --set "Output/Directory=parameters_deprecated_materials" ${CYLINDERS})
set_tests_properties(parameters_deprecated_materials PROPERTIES
  PASS_REGULAR_EXPRESSION
  "warning: 'Viscous flow/Surface tension' is deprecated, use 'Materials/Surface tension'.*warning: 'Viscous flow/Fluid viscosity' is deprecated, use 'Materials/Fluid viscosity'.*warning: 'Viscous flow/Fluid compressibility' is deprecated, use 'Materials/Fluid compressibility'.*done: 0 steps")
# Volume diffusion needs an atmosphere: a zero fluid viscosity is refused
# with viscous flow off.
bad_input_test(volume_diffusion_without_atmosphere
  "entry 'Materials/Fluid viscosity': must be positive with volume diffusion"
  --set "Materials/Fluid viscosity=0"
  ${CMAKE_SOURCE_DIR}/parameter_files/two_grains_volume_diffusion_2d.prm)

# --- Every shipped scene starts without an unexplained warning (issue 29) --
# Each scene for 0 steps (scene_start.cmake): a warning must say what it
# costs. The packings are left out (their start is checked by hand, 27 Nov
# 2026): packing_27_coupled_3d alone took 541 s wall, 117 s CPU and 2.8 GB
# at t = 0 (the elastic solve), and transport_benchmark_3d builds 1.4 M
# DoFs; the others start in 0.6-7 s CPU.
file(GLOB SHIPPED_SCENES ${CMAKE_SOURCE_DIR}/parameter_files/*.prm)
foreach(scene ${SHIPPED_SCENES})
  get_filename_component(name ${scene} NAME_WE)
  if(name MATCHES "packing|transport_benchmark")
    continue()
  endif()
  add_test(NAME scene_start_${name} COMMAND ${CMAKE_COMMAND}
    -DLEVELSINTER=$<TARGET_FILE:levelsinter> -DSCENE=${scene}
    -DWORK=${CMAKE_CURRENT_BINARY_DIR}/scene_start/${name}
    -P ${CMAKE_CURRENT_SOURCE_DIR}/scene_start.cmake)
endforeach()
