# Run COMMAND (a list); it must succeed and print a line matching OUTPUT,
# and the TimerOutput section SECTION of DIRECTORY/timing.csv must have
# been entered CALLS times (what a run computed, not only what it says).
#   cmake "-DCOMMAND=levelsinter;scene.prm" -DOUTPUT=regex -DDIRECTORY=dir
#     "-DSECTION=volume diffusion: elastic solve" -DCALLS=15
#     -P timer_calls.cmake
execute_process(COMMAND ${COMMAND} RESULT_VARIABLE code
  OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "exit code ${code}:\n${out}\n${err}")
endif()
if(NOT out MATCHES "${OUTPUT}")
  message(FATAL_ERROR "no line matches '${OUTPUT}' in the output:\n${out}")
endif()
file(STRINGS ${DIRECTORY}/timing.csv rows REGEX "^\"${SECTION}\",")
if(NOT rows MATCHES "^\"${SECTION}\",${CALLS},")
  message(FATAL_ERROR "timing.csv: '${rows}', expected ${CALLS} calls of "
    "'${SECTION}'")
endif()
message("${SECTION}: ${CALLS} calls, as expected")
