# --- Packing analysis: pores, density, necks, coordination ---------------
# Constructed level sets whose answer is known (doc/validation.md, "Packing
# analysis"): the interpolated signed distance on a mesh refined around
# the interface. Volumes are of the Q1 zero level set, second order in h;
# limits are 2x the values measured at the finest level unless said.
add_executable(pore_analysis pore_analysis.cc)
target_link_libraries(pore_analysis levelsinter_study)
deal_ii_setup_target(pore_analysis)
set(PORES $<TARGET_FILE:pore_analysis>)

add_test(NAME pores_tracking COMMAND ${PORES} tracking)

# NAME on 1 and 2 ranks (${PORES} ARGS --csv NAME_npN.csv), then the two
# tables compared: the rank merge of the pore labels must not change
# anything. Sums over cells in another order agree to rounding; the
# differences of nearly equal numbers (density_error) are compared
# through the values themselves, timings not at all.
function(pores_on_1_and_2_ranks name)
  ranks_test(${name} COMMAND ${PORES} ${ARGN} --csv ${name}_np@np@.csv
    AGREE ${name}_np@np@.csv 1e-9 density_error)
endfunction()

# A disc of radius 0.3 with no, one and two holes of radius 0.08. Two holes
# measured at levels 5-7: volume error 2.6e-2, 6.4e-3, 1.6e-3 (order 2.0).
add_test(NAME pores_no_hole_2d COMMAND ${PORES} holes 2 0 6
  --closed-pores 0 --open-pores 1)
add_test(NAME pores_one_hole_2d COMMAND ${PORES} holes 2 1 5,6,7
  --closed-pores 1 --open-pores 1 --max-volume-error 3.2e-3
  --min-volume-order 1.8)
pores_on_1_and_2_ranks(pores_two_holes_2d holes 2 2 5,6,7 --closed-pores 2
  --open-pores 1 --max-volume-error 3.2e-3 --min-volume-order 1.8)
# The particle and its holes cut by symmetry planes (the box a half or a
# quarter of the scene): closed pores in the box only, their sphericity
# that of the whole pore the mirrors make (it was nan). The 2D disc on one
# plane, measured at levels 5-7: volume error 2.6e-2, 6.4e-3, 1.6e-3,
# sphericity 0.9911, 0.9979, 0.9995; the 3D sphere on two, levels 4-5:
# 0.31, 7.6e-2 (order 2.0), sphericity 0.880, 0.973. Limits 2x the finest.
add_test(NAME pores_holes_on_symmetry_plane_2d COMMAND ${PORES} holes 2 2
  5,6,7 --planes 1 --closed-pores 2 --open-pores 1 --max-volume-error 3.2e-3
  --min-volume-order 1.8 --max-sphericity-error 1e-3)
add_test(NAME pores_holes_on_symmetry_planes_3d COMMAND ${PORES} holes 3 1
  4,5 --planes 2 --closed-pores 1 --open-pores 1 --max-volume-error 0.16
  --min-volume-order 1.8 --max-sphericity-error 0.055)

# A sphere of radius 0.3 with two holes of radius 0.08, 2 ranks; measured
# at levels 4-6: 0.31, 7.6e-2, 1.9e-2 (order 2.0).
add_test(NAME pores_two_holes_3d COMMAND ${MPIRUN} ${MPIRUN_FLAGS} -np 2
  ${PORES} holes 3 2 4,5,6 --closed-pores 2 --open-pores 1
  --max-volume-error 3.8e-2 --min-volume-order 1.8)

# Square lattice 3 x 3, spacing 0.25, R = 0.15 (a/2 < R < a/sqrt2: necks
# formed, throats closed): 4 closed pores at the cell centres, exact volume
# by a ray integral from the centre. Measured at levels 5-7: pore volume
# error 2.8e-3, 8.0e-3, 8.7e-6 (not monotone: the neck kinks fall on or
# between grid lines; limit 1e-2 covers the three levels), relative
# density error 1.4e-4, 4.1e-4, 4.5e-7 (same; limit 1e-3), neck error
# 4.2e-2, 2.4e-2, 1.2e-2 (first order: the neck is a concave kink of the
# distance, doc/numerics.md), 12 contacts, interior coordination 4.
pores_on_1_and_2_ranks(pores_square_lattice_2d lattice 2 3 0.25 0.15 5,6,7
  --closed-pores 4 --open-pores 1 --max-volume-error 1e-2
  --max-density-error 1e-3 --max-neck-error 2.4e-2 --contacts 12
  --interior-coordination 4)

# Near misses (neck.h: contacts overlap or touch at t = 0, near misses
# have a gap below one band cell): the square lattice above with its rows
# 0.304 apart along y, a gap of 0.004 = h/2 at level 7, so 6 near misses
# whatever the mesh makes of them. The packing's neck_radius (the smallest
# neck over the contacts) must be the contacts' neck along x, 0.0829, to
# the lattice's neck error; counting the near misses as necks gave 0 (or
# the radius of whatever neck the mesh made in the gap).
pores_on_1_and_2_ranks(pores_near_miss_2d lattice 2 3 0.25 0.15 7
  --spacing-y 0.304 --near-misses 6 --contacts 6 --max-neck-error 2.4e-2)

# Simple cubic 3 x 3 x 3, spacing 0.25. R = 0.55 a: necks formed, throats
# open: no closed pore, one open pore space, 54 contacts, coordination 6 of
# the centre sphere; measured at levels 5, 6: density error 1.5e-2, 3.8e-3
# (order 2.0), neck error 5.7e-2, 3.7e-2.
add_test(NAME pores_cubic_open_3d COMMAND ${PORES} lattice 3 3 0.25 0.1375
  5,6 --closed-pores 0 --open-pores 1 --contacts 54
  --interior-coordination 6 --max-density-error 7.6e-3
  --max-neck-error 7.4e-2)
# R = 0.74 a (a/sqrt2 < R < a sqrt3/2): the 8 cell-centre pores are closed
# (pore radius 0.03 = 2 cells at level 6); measured: pore volume error
# 3.3e-3, density error 5.4e-5; 1 and 2 ranks agree.
pores_on_1_and_2_ranks(pores_cubic_closed_3d lattice 3 3 0.25 0.185 6
  --closed-pores 8 --open-pores 1 --max-volume-error 6.6e-3
  --max-density-error 1.1e-4)

# The Analysis entries are checked.
bad_input_test(analysis_corner_count "Analysis/Control volume lower corner"
  --set "Analysis/Control volume lower corner=0.1"
  --set "Analysis/Control volume upper corner=0.9,0.9"
  ${CMAKE_SOURCE_DIR}/parameter_files/circle_translation_2d.prm)
