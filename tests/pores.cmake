# --- Packing analysis: pores, density, necks, coordination ---------------
add_executable(pore_analysis pore_analysis.cc)
target_link_libraries(pore_analysis levelsinter_lib)
deal_ii_setup_target(pore_analysis)
set(PORES $<TARGET_FILE:pore_analysis>)
add_test(NAME pores_tracking COMMAND ${PORES} tracking)
