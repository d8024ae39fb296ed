# Run rubberdyn [ARGUMENTS] INPUT and require a clean failure (see
# CMakeLists.txt).
if(NOT DEFINED EXPECT)
  file(STRINGS ${INPUT} _first LIMIT_COUNT 1)
  string(REGEX REPLACE "^# EXPECT: " "" EXPECT "${_first}")
endif()
# The test's own directory, emptied first: it must stay empty. Refuse to
# empty any other directory (run by hand elsewhere, this would delete it).
if(NOT CMAKE_CURRENT_BINARY_DIR MATCHES "/tests/bad_input/[^/]+$")
  message(FATAL_ERROR "run this script only in a test directory "
    "build/tests/bad_input/<case> (it empties the directory it runs in), "
    "not in ${CMAKE_CURRENT_BINARY_DIR}")
endif()
file(GLOB _old_files "*")
if(_old_files)
  file(REMOVE_RECURSE ${_old_files})
endif()
if(NOT DEFINED ARGUMENTS)
  set(ARGUMENTS "")
endif()
execute_process(COMMAND ${EXECUTABLE} ${ARGUMENTS} ${INPUT}
  RESULT_VARIABLE _status OUTPUT_VARIABLE _out ERROR_VARIABLE _err)
include(${CMAKE_CURRENT_LIST_DIR}/../check_clean_failure.cmake)
require_clean_failure("${_status}" "${_err}" "${EXPECT}")
if(NOT _err MATCHES "${INPUT}")
  message(FATAL_ERROR "the message does not name the input file")
endif()
file(GLOB _written "*")
if(EXISTS results_should_not_exist OR _written)
  message(FATAL_ERROR "results were written despite the bad input: "
    "${_written}")
endif()
