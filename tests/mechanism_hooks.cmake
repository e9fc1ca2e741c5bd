# --- Mechanism hooks: state transfer and output fields (issue 14) --------
add_executable(mechanism_hooks mechanism_hooks.cc)
target_link_libraries(mechanism_hooks levelsinter_lib)
deal_ii_setup_target(mechanism_hooks)
set(HOOKS $<TARGET_FILE:mechanism_hooks>)
