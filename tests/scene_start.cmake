# Start a shipped scene for 0 steps (Start time = End time = 0: the mesh,
# the initial level set and the first metrics row) and fail on a warning
# that does not explain itself: a warning at the start must be fixed in the
# scene, or say in its own words what it costs ("measured") and what to do.
#   cmake -DLEVELSINTER=... -DSCENE=... -DWORK=dir [-DLAUNCH="mpirun;-np;2"]
#         -P scene_start.cmake
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
execute_process(COMMAND ${LAUNCH} ${LEVELSINTER} --overwrite
  --set "Time/Start time=0" --set "Time/End time=0"
  --set "Output/Field formats=none" --set "Output/Directory=${WORK}/out"
  ${SCENE}
  WORKING_DIRECTORY ${WORK}
  RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "exit code ${code}:\n${out}\n${err}")
endif()
string(REGEX REPLACE "warning:[^\n]*[Mm]easured[^\n]*" "" rest "${out}${err}")
string(FIND "${rest}" "warning:" found)
if(NOT found EQUAL -1)
  message(FATAL_ERROR "a warning without its cost:\n${out}\n${err}")
endif()
message(STATUS "${out}")
