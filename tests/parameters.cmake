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
  "entry 'Viscous flow/Surface tension': must be positive"
  --set "Viscous flow/Surface tension=0" ${CYLINDERS})

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
