# SIG${SIGNAL} (default TERM; sent by SENDER, a command that runs the
# rest) stops a long run after the current step: exit code CODE (default
# 143), a final message naming the signal and the step, metrics.csv
# complete up to that step (every row whole, the last one that step) and
# a checkpoint of that step.
#   cmake -DSENDER="timeout;--preserve-status;-s;TERM;10"
#     [-DSIGNAL=USR1 -DCODE=138]
#     -DLEVELSINTER=... -DSCENE=... -DWORK=dir -P stop_signal.cmake
if(NOT DEFINED SIGNAL)
  set(SIGNAL TERM)
endif()
if(NOT DEFINED CODE)
  set(CODE 143)
endif()
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
execute_process(COMMAND ${SENDER} ${LEVELSINTER} --set "Output/Directory=out"
  --set "Output/Field formats=none" --set "Mesh refinement/Maximum level=7"
  ${SCENE} WORKING_DIRECTORY ${WORK}
  RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL CODE)
  message(FATAL_ERROR "exit code ${code}, expected ${CODE}:\n${out}\n${err}")
endif()
if(NOT out MATCHES "stopped by SIG${SIGNAL} at step ([0-9]+), t = [^;]+; metrics.csv is complete up to that step")
  message(FATAL_ERROR "no stop message:\n${out}\n${err}")
endif()
set(step ${CMAKE_MATCH_1})
file(STRINGS ${WORK}/out/metrics.csv lines)
list(GET lines 0 header)
string(REGEX MATCHALL "," commas "${header}")
list(LENGTH commas columns)
foreach(line ${lines})
  string(REGEX MATCHALL "," row_commas "${line}")
  list(LENGTH row_commas row_columns)
  if(NOT row_columns EQUAL columns)
    message(FATAL_ERROR "metrics.csv has an incomplete row: '${line}'")
  endif()
endforeach()
list(GET lines -1 last)
string(REGEX MATCH "^[0-9]+" last_step "${last}")
if(NOT last_step EQUAL step)
  message(FATAL_ERROR "metrics.csv ends at step ${last_step}, the message says ${step}")
endif()
string(PREPEND step "000000")
string(REGEX MATCH "......$" step6 "${step}")
if(NOT IS_DIRECTORY ${WORK}/out/checkpoints/step_${step6})
  message(FATAL_ERROR "no checkpoint of step ${step}")
endif()
message(STATUS "stopped by SIG${SIGNAL} at step ${last_step} (exit code ${code}); metrics.csv rows to that step; checkpoint step_${step6}")
