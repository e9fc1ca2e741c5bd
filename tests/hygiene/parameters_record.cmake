# parameters.prm records the run (version, MPI ranks, command line, every
# effective value with the --set overrides) and, run as a scene from
# another working directory, reproduces the run's metrics.csv.
#   cmake -DLEVELSINTER=... -DCOMPARE=... -DSCENE=... -DWORK=dir -P parameters_record.cmake
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/first ${WORK}/again)
execute_process(COMMAND ${LEVELSINTER} --set "Velocity/Constant=0.4, 0.2"
  ${SCENE} WORKING_DIRECTORY ${WORK}/first
  RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "first run, exit code ${code}:\n${out}\n${err}")
endif()
set(record ${WORK}/first/particle_file_run/parameters.prm)
file(READ ${record} text)
foreach(expected
    "# version: levelsinter [^\n]+ \\(commit ([0-9a-f]+|unknown)\\)\n"
    "# date: [0-9-]+ [0-9:]+ UTC\n"
    "# MPI ranks: 1\n"
    "# command line: [^\n]*levelsinter --set 'Velocity/Constant=0.4, 0.2' "
    "set Constant +=  ?0.4, 0.2"
    "set Particle file += /[^\n]*/particles_2d.csv"
    "set Maximum steps +=  ?8")
  if(NOT text MATCHES "${expected}")
    message(FATAL_ERROR "${record} lacks '${expected}':\n${text}")
  endif()
endforeach()
execute_process(COMMAND ${LEVELSINTER} --set "Output/Directory=rerun" ${record}
  WORKING_DIRECTORY ${WORK}/again
  RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "run of parameters.prm, exit code ${code}:\n${out}\n${err}")
endif()
# The same program on one rank repeats the same arithmetic: only the
# printed digits may differ (12 significant).
execute_process(COMMAND ${COMPARE}
  ${WORK}/first/particle_file_run/metrics.csv ${WORK}/again/rerun/metrics.csv
  1e-11 wall_time RESULT_VARIABLE code)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "the run of parameters.prm differs from the run")
endif()
