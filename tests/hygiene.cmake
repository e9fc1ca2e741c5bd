# --- Run hygiene: output directory, run record, stop signals, plots -------
set(HYGIENE ${CMAKE_CURRENT_SOURCE_DIR}/hygiene)

# An earlier run is refused, untouched (bad_input.cmake leaves a
# metrics.csv in out/); --overwrite or Output/Overwrite replaces it.
bad_input_test(earlier_run "holds an earlier run (metrics.csv)"
  --set "Output/Directory=out" ${SCENE})
foreach(option overwrite set_overwrite)
  if(option STREQUAL "overwrite")
    set(options --overwrite)
  else()
    set(options --set "Output/Overwrite=true")
  endif()
  add_test(NAME ${option}_earlier_run COMMAND ${CMAKE_COMMAND}
    -DLEVELSINTER=$<TARGET_FILE:levelsinter> -DSCENE=${SCENE}
    "-DOPTIONS=${options}" -DWORK=${CMAKE_CURRENT_BINARY_DIR}/${option}_earlier_run
    -P ${HYGIENE}/overwrite.cmake)
endforeach()

# parameters.prm: the run's record, runnable again.
add_test(NAME parameters_record COMMAND ${CMAKE_COMMAND}
  -DLEVELSINTER=$<TARGET_FILE:levelsinter>
  -DCOMPARE=$<TARGET_FILE:compare_metrics>
  -DSCENE=${HYGIENE}/particle_file_2d.prm
  -DWORK=${CMAKE_CURRENT_BINARY_DIR}/parameters_record
  -P ${HYGIENE}/parameters_record.cmake)

add_test(NAME version COMMAND levelsinter --version)
set_tests_properties(version PROPERTIES PASS_REGULAR_EXPRESSION
  "^levelsinter [^ ]+ \\(commit ([0-9a-f]+|unknown)\\)")
# A scene's effective values: the file's (Output/Directory) with the
# --set applied (Maximum level 6; the scene has 5, the default is 4).
add_test(NAME print_scene_parameters COMMAND levelsinter --print-parameters
  --set "Mesh refinement/Maximum level=6" ${SCENE})
set_tests_properties(print_scene_parameters PROPERTIES PASS_REGULAR_EXPRESSION
  "set Maximum level += 6 +# default: 4.*set Directory += output/circle_translation_2d")

# Messages name the --set that gave the value, and a directory as a scene.
bad_input_test(set_named "--set 'Mesh refinement/Band width=0.05': entry"
  --set "Mesh refinement/Band width=0.05"
  ${CMAKE_SOURCE_DIR}/parameter_files/closed_pore_2d.prm)
bad_input_test(set_named_mechanism
  "--set 'Velocity/Expression constants=U': entry"
  --set "Velocity/Expression constants=U" ${SCENE})
bad_input_test(scene_is_directory "is a directory, not a file"
  ${HYGIENE})

# A signal ends a long run (level 7: ~1000 steps) after the current step
# with a checkpoint (doc/user_guide.md, "Exit codes"); 10 to 15 s leave
# time for the start under load. On 2 ranks with the signal to one rank,
# both stop at the same step. SIGTERM directly: 143; SIGUSR1, which Open
# MPI's mpirun passes on to every rank and then reports their code: 138
# whether mpirun or one rank gets it. SIGTERM to mpirun: Open MPI's mpirun
# exits 1 whatever the ranks return and kills them 1 s after passing the
# signal on (odls_base_sigkill_timeout, raised to 10 s here so that a step
# under load is not cut; mpirun then waits that long twice even when the
# ranks are done: 134 s measured with 60 s); the ranks still stop cleanly.
# stop_signal_test(NAME SIGNAL CODE SENDER...)
function(stop_signal_test name signal code)
  add_test(NAME ${name} COMMAND ${CMAKE_COMMAND} "-DSENDER=${ARGN}"
    -DSIGNAL=${signal} -DCODE=${code}
    -DLEVELSINTER=$<TARGET_FILE:levelsinter> -DSCENE=${SCENE}
    -DWORK=${CMAKE_CURRENT_BINARY_DIR}/${name}
    -P ${HYGIENE}/stop_signal.cmake)
endfunction()
set(SEND ${HYGIENE}/send_signal.sh)
stop_signal_test(stop_signal TERM 143 timeout --preserve-status -s TERM 10)
stop_signal_test(stop_signal_usr1_mpirun_np1 USR1 138
  ${SEND} 10 USR1 launcher ${MPIRUN} ${MPIRUN_FLAGS} -np 1)
stop_signal_test(stop_signal_one_rank_np2 TERM 143
  ${SEND} 15 TERM rank ${MPIRUN} ${MPIRUN_FLAGS} -np 2)
stop_signal_test(stop_signal_usr1_one_rank_np2 USR1 138
  ${SEND} 15 USR1 rank ${MPIRUN} ${MPIRUN_FLAGS} -np 2)
stop_signal_test(stop_signal_usr1_mpirun_np2 USR1 138
  ${SEND} 15 USR1 launcher ${MPIRUN} ${MPIRUN_FLAGS} -np 2)
stop_signal_test(stop_signal_term_mpirun_np2 TERM 1
  ${SEND} 15 TERM launcher ${MPIRUN} ${MPIRUN_FLAGS}
  --mca odls_base_sigkill_timeout 10 -np 2)

# scripts/plot_metrics.py on the metrics of the 1- and 2-rank runs (run
# as its #! says: Debian's python3 has matplotlib).
add_test(NAME plot_metrics COMMAND sh -c
  "rm -f plot_metrics.png && ${CMAKE_SOURCE_DIR}/scripts/plot_metrics.py mpi_np1 mpi_np2 --y solid_volume interface_area cells -o plot_metrics.png && test -s plot_metrics.png")
set_tests_properties(plot_metrics PROPERTIES
  FIXTURES_REQUIRED "mpi_run_np1;mpi_run_np2")
# scripts/plot_field.py on the last fields of the 2-rank run (step 40): the PVTU (two
# pieces joined) and the HDF5 file give the same nodes and alpha, and a PNG.
add_test(NAME plot_field COMMAND ${HYGIENE}/plot_field_check.py
  ${CMAKE_SOURCE_DIR}/scripts/plot_field.py mpi_np2/fields_00002)
set_tests_properties(plot_field PROPERTIES FIXTURES_REQUIRED mpi_run_np2)

# The ETA for fixed and growing steps and a rising cost per step against
# the exact time left, and on the default scene's steps replayed.
add_executable(remaining_time_test remaining_time_test.cc)
target_link_libraries(remaining_time_test levelsinter_lib)
deal_ii_setup_target(remaining_time_test)
add_test(NAME remaining_time COMMAND remaining_time_test
  ${CMAKE_CURRENT_SOURCE_DIR}/scenes/two_cylinders_2d_steps.csv)

# The done line counts the steps whose velocity was computed again with a
# shorter step. tests/scenes/translation_2d.prm with a speed that jumps
# from U to 10 U at t = 0.02: the first step after the jump finds the
# velocity 10x faster than its CFL step (from U) allows, so it is computed
# again with the step of 10 U, once; the steps after it start from 10 U.
# Measured: 3 + 26 steps to t = 0.04, one computed again.
add_test(NAME done_line_counts_shortened_steps
  COMMAND $<TARGET_FILE:levelsinter> --overwrite
    --set "Velocity/Expression=U*(t < 0.02 ? 1 : 10); 0"
    --set "Velocity/Expression constants=U=1" --set "Time/End time=0.04"
    --set "Output/Directory=done_line_counts_shortened_steps"
    ${CMAKE_CURRENT_SOURCE_DIR}/scenes/translation_2d.prm)
set_tests_properties(done_line_counts_shortened_steps PROPERTIES
  PASS_REGULAR_EXPRESSION
  "done: 29 steps to t = 0.04 .*; 1 step\\(s\\) computed again")
