# Shared by bad_input/check_bad_input.cmake and
# solver_failure/check_solver_failure.cmake: what every failure of rubberdyn
# must look like. require_clean_failure(STATUS ERR EXPECT) fails the test
# unless the exit code STATUS is a non-zero number below 100 (no crash), the
# standard error ERR matches EXPECT, holds no deal.II assertion banner and
# is a single line.
function(require_clean_failure _status _err _expect)
  message(STATUS "exit code ${_status}, stderr:\n${_err}")
  if(_status EQUAL 0 OR NOT _status MATCHES "^[0-9]+$")
    message(FATAL_ERROR "expected a non-zero exit code, got '${_status}'")
  endif()
  if(_status GREATER 100)
    message(FATAL_ERROR "crashed (exit code ${_status})")
  endif()
  if(NOT _err MATCHES "${_expect}")
    message(FATAL_ERROR "the message does not match '${_expect}'")
  endif()
  if(_err MATCHES "An error occurred in line" OR _err MATCHES "Stacktrace")
    message(FATAL_ERROR "a deal.II assertion banner instead of a message")
  endif()
  string(REGEX MATCHALL "\n" _lines "${_err}")
  list(LENGTH _lines _n_lines)
  if(_n_lines GREATER 1)
    message(FATAL_ERROR "expected a one-line message, got ${_n_lines} lines")
  endif()
endfunction()
