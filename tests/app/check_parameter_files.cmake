# 'rubberdyn --check FILE.prm' on every shipped parameter file (SOURCE_DIR/
# parameter_files/*.prm): exit code 0, stdout ending in one line saying the
# study is valid (a study with a model reports it first: cells, parts,
# masses, the smallest element step), the valid-line printed once,
# nothing on stderr, nothing written (the working directory,
# emptied first, stays empty; the files' output directories are relative).
# The first file also on two MPI ranks (MPIEXEC, NUMPROC_FLAG), which must
# print the line once.
file(GLOB _files ${SOURCE_DIR}/parameter_files/*.prm)
list(SORT _files)
if(NOT _files)
  message(FATAL_ERROR "no parameter files in ${SOURCE_DIR}/parameter_files")
endif()
list(GET _files 0 _first)

# It empties its working directory before each case: refuse to run anywhere
# but the directory ctest gives it (run by hand elsewhere, it would delete
# that directory's contents).
get_filename_component(_here "${CMAKE_CURRENT_BINARY_DIR}" NAME)
if(NOT _here STREQUAL "check_parameter_files")
  message(FATAL_ERROR "run this script only in its own directory "
    "'check_parameter_files' (it empties the directory it runs in), not in "
    "${CMAKE_CURRENT_BINARY_DIR}")
endif()

function(check_file _file)
  file(GLOB _old "*")
  if(_old)
    file(REMOVE_RECURSE ${_old})
  endif()
  execute_process(COMMAND ${ARGN} ${EXECUTABLE} --check ${_file}
    RESULT_VARIABLE _status OUTPUT_VARIABLE _out ERROR_VARIABLE _err)
  message(STATUS "${ARGN} rubberdyn --check ${_file}: exit code ${_status}\n"
    "${_out}${_err}")
  if(NOT _status EQUAL 0)
    message(FATAL_ERROR "--check failed on a shipped parameter file")
  endif()
  if(NOT _err STREQUAL "")
    message(FATAL_ERROR "--check wrote to stderr")
  endif()
  if(NOT _out MATCHES "(^|\n)rubberdyn: '[^\n]*' is a valid '[^\n]*' study [^\n]*\n$")
    message(FATAL_ERROR "--check must end with one line saying the study "
      "is valid")
  endif()
  string(REGEX MATCHALL "is a valid '" _valid_lines "${_out}")
  list(LENGTH _valid_lines _n_valid)
  if(NOT _n_valid EQUAL 1)
    message(FATAL_ERROR "--check must say once that the study is valid")
  endif()
  file(GLOB _written "*")
  if(_written)
    message(FATAL_ERROR "--check wrote files: ${_written}")
  endif()
endfunction()

foreach(_file ${_files})
  check_file(${_file})
endforeach()
check_file(${_first} ${MPIEXEC} ${NUMPROC_FLAG} 2)
