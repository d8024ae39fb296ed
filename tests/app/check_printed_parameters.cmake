# Compare the output of 'rubberdyn --print-parameters' with the checked-in
# doc/parameters.prm, then run the printed file as a study.
execute_process(COMMAND ${EXECUTABLE} --print-parameters
  OUTPUT_FILE printed.prm RESULT_VARIABLE _status)
if(NOT _status EQUAL 0)
  message(FATAL_ERROR "rubberdyn --print-parameters failed (${_status})")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files printed.prm ${REFERENCE}
  RESULT_VARIABLE _differs)
if(_differs)
  message(FATAL_ERROR "doc/parameters.prm is stale: regenerate it with\n"
    "  build/rubberdyn --print-parameters > doc/parameters.prm")
endif()
file(REMOVE_RECURSE output)
execute_process(COMMAND ${EXECUTABLE} printed.prm
  RESULT_VARIABLE _status OUTPUT_VARIABLE _out ERROR_VARIABLE _err)
if(NOT _status EQUAL 0)
  message(FATAL_ERROR "the printed parameter file does not run:\n${_out}${_err}")
endif()
message(STATUS "doc/parameters.prm is current and runs")
