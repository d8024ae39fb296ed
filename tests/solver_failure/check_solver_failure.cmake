# Run rubberdyn on INPUT and require a clean stop that keeps the last state
# (see CMakeLists.txt).
file(STRINGS ${INPUT} _header LIMIT_COUNT 2)
list(GET _header 0 _expect)
list(GET _header 1 _writes)
string(REGEX REPLACE "^# EXPECT: " "" EXPECT "${_expect}")
string(REGEX REPLACE "^# WRITES: " "" _writes "${_writes}")
separate_arguments(WRITES UNIX_COMMAND "${_writes}")

file(REMOVE_RECURSE results)
execute_process(COMMAND ${EXECUTABLE} ${INPUT}
  RESULT_VARIABLE _status OUTPUT_VARIABLE _out ERROR_VARIABLE _err)
include(${CMAKE_CURRENT_LIST_DIR}/../check_clean_failure.cmake)
require_clean_failure("${_status}" "${_err}" "${EXPECT}")
foreach(_file ${WRITES})
  if(NOT EXISTS ${_file})
    message(FATAL_ERROR "the last state was not written: no ${_file}")
  endif()
endforeach()

# Every state in the ParaView collection must exist, and the last one must
# be later than the start.
file(GLOB _collections results/*.pvd)
foreach(_pvd ${_collections})
  file(STRINGS ${_pvd} _datasets REGEX "<DataSet ")
  if(NOT _datasets)
    message(FATAL_ERROR "${_pvd} holds no state")
  endif()
  set(_last_time "")
  foreach(_dataset ${_datasets})
    string(REGEX REPLACE ".*timestep=\"([^\"]*)\".*" "\\1" _last_time
      "${_dataset}")
    string(REGEX REPLACE ".*file=\"([^\"]*)\".*" "\\1" _file "${_dataset}")
    if(NOT EXISTS results/${_file})
      message(FATAL_ERROR "${_pvd} names results/${_file}, which is missing")
    endif()
  endforeach()
  if(_last_time MATCHES "^[0.]+$")
    message(FATAL_ERROR "the last state in ${_pvd} is the initial one")
  endif()
  message(STATUS "last state in ${_pvd}: t = ${_last_time} ms")
endforeach()
