# Fails unless every group of test variants (names equal but for the
# mpirun=N and threads=N options, e.g. app/foo.release and
# app/foo.mpirun=2.release) shares a RESOURCE_LOCK, so that ctest -j never
# runs two of them at once. Reads the test list from
# 'ctest --show-only=json-v1' in BINARY_DIR.
cmake_minimum_required(VERSION 3.19) # string(JSON)
execute_process(COMMAND ${CTEST} --show-only=json-v1
  WORKING_DIRECTORY ${BINARY_DIR}
  RESULT_VARIABLE _result OUTPUT_VARIABLE _json ERROR_VARIABLE _error)
if(NOT _result EQUAL 0)
  message(FATAL_ERROR "ctest --show-only failed: ${_error}")
endif()

string(JSON _n_tests LENGTH "${_json}" tests)
math(EXPR _last "${_n_tests} - 1")
set(_groups "")
foreach(_i RANGE ${_last})
  string(JSON _name GET "${_json}" tests ${_i} name)
  set(_locks "")
  string(JSON _n_properties ERROR_VARIABLE _no_properties
    LENGTH "${_json}" tests ${_i} properties)
  if(NOT _no_properties AND _n_properties GREATER 0)
    math(EXPR _last_property "${_n_properties} - 1")
    foreach(_p RANGE ${_last_property})
      string(JSON _property GET "${_json}" tests ${_i} properties ${_p} name)
      if(_property STREQUAL "RESOURCE_LOCK")
        string(JSON _n_values LENGTH "${_json}" tests ${_i} properties ${_p}
          value)
        math(EXPR _last_value "${_n_values} - 1")
        foreach(_v RANGE ${_last_value})
          string(JSON _lock GET "${_json}" tests ${_i} properties ${_p}
            value ${_v})
          list(APPEND _locks "${_lock}")
        endforeach()
      endif()
    endforeach()
  endif()

  string(REGEX REPLACE "\\.(mpirun|threads)=[0-9]+" "" _group "${_name}")
  string(MD5 _key "${_group}")
  if(NOT _group IN_LIST _groups)
    list(APPEND _groups "${_group}")
    set(_members_${_key} "${_name}")
    set(_common_${_key} "${_locks}")
  else()
    list(APPEND _members_${_key} "${_name}")
    # The locks every member so far has.
    set(_common "")
    foreach(_lock IN LISTS _common_${_key})
      if(_lock IN_LIST _locks)
        list(APPEND _common "${_lock}")
      endif()
    endforeach()
    set(_common_${_key} "${_common}")
  endif()
endforeach()

set(_n_groups 0)
set(_unserialised "")
foreach(_group IN LISTS _groups)
  string(MD5 _key "${_group}")
  list(LENGTH _members_${_key} _n_members)
  if(_n_members GREATER 1)
    math(EXPR _n_groups "${_n_groups} + 1")
    if("${_common_${_key}}" STREQUAL "")
      string(REPLACE ";" ", " _members "${_members_${_key}}")
      string(APPEND _unserialised "\n  ${_members}")
    endif()
  endif()
endforeach()
message(STATUS "${_n_tests} tests, ${_n_groups} groups of variants")
if(_n_groups EQUAL 0)
  message(FATAL_ERROR "no test has variants: is the test list complete?")
endif()
if(NOT _unserialised STREQUAL "")
  message(FATAL_ERROR "these variants of one test share no RESOURCE_LOCK, "
    "so ctest -j may run them at once (one relinking the executable the "
    "other runs):${_unserialised}")
endif()
