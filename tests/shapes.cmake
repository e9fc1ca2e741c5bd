# --- Shapes: holes, ellipses, superellipses, implicit functions ------------
# (issue 17; doc/validation.md, "Shapes: holes, ellipses, superellipses,
# implicit functions")
add_executable(shapes shapes.cc)
target_link_libraries(shapes levelsinter_study)
deal_ii_setup_target(shapes)
set(SHAPES $<TARGET_FILE:shapes>)
set(HOLLOW ${CMAKE_SOURCE_DIR}/parameter_files/hollow_cylinder_2d.prm)
set(SQUARISH ${CMAKE_SOURCE_DIR}/parameter_files/squarish_particle_2d.prm)
