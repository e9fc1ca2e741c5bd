# --- Mechanics: elastic inclusion (issue 15) ----------------------------
add_executable(levelsinter_elastic_inclusion elastic_inclusion.cc)
target_link_libraries(levelsinter_elastic_inclusion levelsinter_lib)
deal_ii_setup_target(levelsinter_elastic_inclusion)
set(INCLUSION $<TARGET_FILE:levelsinter_elastic_inclusion>)
