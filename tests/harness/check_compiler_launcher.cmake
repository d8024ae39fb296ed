# The compiler launcher: one given on the command line is used, an empty one
# means none, and only without either is ccache used (if installed).
# Configures SOURCE_DIR afresh in WORK_DIR/given and WORK_DIR/none and reads
# the compile command of one source file from the generated makefiles; the
# case without a launcher is read from the main build MAIN_BUILD_DIR when it
# was configured without one.

cmake_minimum_required(VERSION 3.18) # find_program(REQUIRED)

# The first line of the first compile command of the core library (a
# source of its own or, in a unity build, a batch of sources: the launcher
# is the same for all).
function(compile_command _build_dir _result)
  file(STRINGS ${_build_dir}/CMakeFiles/rubberdyn_core.dir/build.make _lines
    REGEX "\\.o -c ")
  list(GET _lines 0 _line)
  string(STRIP "${_line}" _line)
  set(${_result} "${_line}" PARENT_SCOPE)
endfunction()

function(configure _name)
  file(REMOVE_RECURSE ${WORK_DIR}/${_name})
  execute_process(COMMAND ${CMAKE_COMMAND}
      -S ${SOURCE_DIR} -B ${WORK_DIR}/${_name}
      -DCMAKE_BUILD_TYPE=Release -DDEAL_II_DIR=${DEAL_II_DIR} ${ARGN}
    RESULT_VARIABLE _result OUTPUT_VARIABLE _out ERROR_VARIABLE _err)
  if(NOT _result EQUAL 0)
    message(FATAL_ERROR "configure ${_name} failed:\n${_out}\n${_err}")
  endif()
endfunction()

find_program(ENV_PROGRAM env REQUIRED)
find_program(CCACHE_PROGRAM ccache)

# Given: a wrapper (env runs its arguments, like a timing wrapper would).
configure(given -DCMAKE_CXX_COMPILER_LAUNCHER=${ENV_PROGRAM})
compile_command(${WORK_DIR}/given _command)
message(STATUS "launcher given: ${_command}")
if(NOT _command MATCHES "^${ENV_PROGRAM} ")
  message(FATAL_ERROR "the launcher ${ENV_PROGRAM} given on the command line "
    "is not used: ${_command}")
endif()

# Given as empty: no launcher at all.
configure(none "-DCMAKE_CXX_COMPILER_LAUNCHER=")
compile_command(${WORK_DIR}/none _command)
message(STATUS "empty launcher: ${_command}")
if(CCACHE_PROGRAM AND _command MATCHES "^${CCACHE_PROGRAM} ")
  message(FATAL_ERROR "an empty launcher must switch ccache off: ${_command}")
endif()
file(REMOVE_RECURSE ${WORK_DIR})

# Not given (the main build, if configured so): ccache.
file(STRINGS ${MAIN_BUILD_DIR}/CMakeCache.txt _cached
  REGEX "^CMAKE_CXX_COMPILER_LAUNCHER:")
if(CCACHE_PROGRAM AND _cached STREQUAL "" AND
   NOT DEFINED ENV{CMAKE_CXX_COMPILER_LAUNCHER})
  compile_command(${MAIN_BUILD_DIR} _command)
  message(STATUS "no launcher given: ${_command}")
  if(NOT _command MATCHES "^${CCACHE_PROGRAM} ")
    message(FATAL_ERROR "without a launcher ccache must be used: ${_command}")
  endif()
endif()
