# Run COMMAND (a list) and keep its standard output in LOG, for the
# scripts that read a run's rejected steps and timer table from it
# (scripts/topology_history.py); fails with the output if COMMAND does.
#   cmake "-DCOMMAND=mpirun;-np;2;levelsinter;scene.prm" -DLOG=run.log
#     -P logged_run.cmake
execute_process(COMMAND ${COMMAND} OUTPUT_FILE ${LOG} ERROR_VARIABLE err
  RESULT_VARIABLE code)
if(NOT code EQUAL 0)
  file(READ ${LOG} out)
  message(FATAL_ERROR "exit code ${code}:\n${out}\n${err}")
endif()
