# An earlier run in the output directory is replaced when the user asks
# (OPTIONS: --overwrite, or --set Output/Overwrite=true): exactly that run's
# files go (the stale field files of a longer run too), others stay.
#   cmake -DLEVELSINTER=... -DSCENE=... -DOPTIONS="a;b" -DWORK=dir -P overwrite.cmake
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/out)
set(earlier metrics.csv parameters.prm fields.pvd fields.xdmf
  fields_00099.pvtu fields_00099.0.vtu fields_00099.h5)
foreach(name ${earlier} notes.txt)
  file(WRITE ${WORK}/out/${name} "earlier run\n")
endforeach()
execute_process(COMMAND ${LEVELSINTER} ${OPTIONS}
  --set "Output/Directory=out" --set "Time/Maximum steps=2" ${SCENE}
  WORKING_DIRECTORY ${WORK}
  RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "exit code ${code}:\n${out}\n${err}")
endif()
foreach(name fields_00099.pvtu fields_00099.0.vtu fields_00099.h5)
  if(EXISTS ${WORK}/out/${name})
    message(FATAL_ERROR "the earlier run's ${name} was not removed")
  endif()
endforeach()
file(READ ${WORK}/out/notes.txt notes)
if(NOT notes STREQUAL "earlier run\n")
  message(FATAL_ERROR "notes.txt, not a file of a run, was changed")
endif()
foreach(name metrics.csv parameters.prm fields.pvd fields.xdmf)
  file(READ ${WORK}/out/${name} text)
  if(text STREQUAL "earlier run\n")
    message(FATAL_ERROR "${name} is still the earlier run's")
  endif()
endforeach()
file(GLOB written RELATIVE ${WORK}/out ${WORK}/out/*)
message(STATUS "output directory after the run: ${written}")
