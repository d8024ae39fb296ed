# A drop test continued from a checkpoint writes exactly what the
# uninterrupted run writes: runs full.prm (0 -> 3 ms), part.prm (0 -> 2 ms,
# last checkpoint at 1.5 ms, rows written up to 1.9 ms), then
# resume_other_model.prm (another friction coefficient), which must be
# refused without touching part's results (a truncation of the rows after
# the checkpoint would show here), and resume.prm (restart part's
# checkpoint, to 3 ms); then compares the two time_history.csv files byte for
# byte and the step counts in the two run_summary.json.
# Called with -DEXECUTABLE=... -DSOURCE=<this directory>.
file(REMOVE_RECURSE results_full results_part)

function(run _name)
  execute_process(COMMAND ${EXECUTABLE} ${SOURCE}/${_name}.prm
    RESULT_VARIABLE _result OUTPUT_VARIABLE _out ERROR_VARIABLE _err)
  if(NOT _result EQUAL 0)
    message(FATAL_ERROR "${_name}.prm failed (${_result}):\n${_out}\n${_err}")
  endif()
  set(_out "${_out}" PARENT_SCOPE)
endfunction()

run(full)
run(part)

# A checkpoint is refused by a model whose parameters differ, and nothing
# is lost.
configure_file(results_part/time_history.csv part_before_refusal.csv COPYONLY)
execute_process(COMMAND ${EXECUTABLE} ${SOURCE}/resume_other_model.prm
  RESULT_VARIABLE _result OUTPUT_VARIABLE _out ERROR_VARIABLE _err)
if(_result EQUAL 0 OR NOT _err MATCHES "Friction coefficient = 0.31")
  message(FATAL_ERROR "a restart with another friction coefficient must be "
    "refused naming it (exit ${_result}):\n${_out}\n${_err}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files
  part_before_refusal.csv results_part/time_history.csv
  RESULT_VARIABLE _different)
if(_different)
  message(FATAL_ERROR "the refused restart changed time_history.csv")
endif()

run(resume)
if(NOT _out MATCHES "Restarted from the checkpoint at t = 1.5")
  message(FATAL_ERROR "resume.prm did not restart at t = 1.5 ms:\n${_out}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files
  results_full/time_history.csv results_part/time_history.csv
  RESULT_VARIABLE _different)
if(_different)
  file(READ results_full/time_history.csv _full)
  file(READ results_part/time_history.csv _part)
  message(FATAL_ERROR "the restarted run differs:\nfull:\n${_full}\nrestarted:\n${_part}")
endif()
file(STRINGS results_full/run_summary.json _full_steps REGEX "time_steps")
file(STRINGS results_part/run_summary.json _part_steps REGEX "time_steps")
if(NOT _full_steps STREQUAL _part_steps)
  message(FATAL_ERROR "step counts differ: ${_full_steps} vs ${_part_steps}")
endif()
# The continuation's wall time per step (ns per element-cycle, the log's
# time left) counts only its own steps: timed_steps is the total less the
# checkpoint's step (before, the steps before the restart were counted too).
string(REGEX MATCH "Restarted from the checkpoint at t = [^,]*, step ([0-9]+)"
  _restart_line "${_out}")
set(_restart_step "${CMAKE_MATCH_1}")
string(REGEX MATCH "\"time_steps\": *\"?([0-9]+)" _m "${_part_steps}")
set(_total_steps "${CMAKE_MATCH_1}")
file(STRINGS results_part/run_summary.json _timed REGEX "timed_steps")
string(REGEX MATCH "\"timed_steps\": *\"?([0-9]+)" _m "${_timed}")
set(_timed_steps "${CMAKE_MATCH_1}")
if(_restart_step STREQUAL "" OR _total_steps STREQUAL "" OR
   _timed_steps STREQUAL "")
  message(FATAL_ERROR "cannot read the restart step ('${_restart_line}'), "
    "time_steps ('${_part_steps}') or timed_steps ('${_timed}')")
endif()
math(EXPR _expected "${_total_steps} - ${_restart_step}")
if(NOT _timed_steps EQUAL _expected OR _restart_step EQUAL 0)
  message(FATAL_ERROR "timed_steps ${_timed_steps} after a restart at step "
    "${_restart_step} of ${_total_steps}; expected ${_expected}")
endif()
message(STATUS "restart continues identically: ${_full_steps}, timed "
  "${_timed_steps} = ${_total_steps} - ${_restart_step}")
