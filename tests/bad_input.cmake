# Run levelsinter on a bad input and check that it fails the documented way:
# exit code != 0, one plain line on stderr, "levelsinter: error: ..." (or
# "levelsinter-pack: error: ..." for the packing generator),
# containing EXPECT (nothing before it: no library's dump, no raw bytes of
# the input), and an existing output directory left untouched.
#   cmake -DLEVELSINTER=... -DARGS="a;b" -DEXPECT="text" -DWORK=dir -P bad_input.cmake
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/out)
file(WRITE ${WORK}/out/metrics.csv "previous run\n")
execute_process(COMMAND ${LEVELSINTER} ${ARGS}
  WORKING_DIRECTORY ${WORK}
  RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(code EQUAL 0)
  message(FATAL_ERROR "expected a non-zero exit code; stdout:\n${out}")
endif()
string(FIND "${err}" "${EXPECT}" found)
if(found EQUAL -1)
  message(FATAL_ERROR "stderr lacks '${EXPECT}':\n${err}")
endif()
# One line of printable text.
if(NOT err MATCHES "^levelsinter(-pack)?: error: [ -~\t]*\n$")
  message(FATAL_ERROR
    "stderr is not one printable line 'levelsinter: error: ...':\n${err}")
endif()
file(READ ${WORK}/out/metrics.csv previous)
if(NOT previous STREQUAL "previous run\n")
  message(FATAL_ERROR "the existing output was modified")
endif()
file(GLOB left ${WORK}/out/*)
list(LENGTH left n)
if(NOT n EQUAL 1)
  message(FATAL_ERROR "files were written to the output directory: ${left}")
endif()
message(STATUS "exit code ${code}; message: ${err}")
