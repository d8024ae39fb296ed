# A drop test continued from a checkpoint writes exactly what the
# uninterrupted run writes: runs full.prm (0 -> 3 ms), part.prm (0 -> 2 ms,
# checkpoint at 2 ms) and resume.prm (restart part's checkpoint, to 3 ms),
# then compares the two time_history.csv files byte for byte and the step
# counts in the two run_summary.json; then resume_other_model.prm (another
# friction coefficient) must be refused.
# Called with -DEXECUTABLE=... -DSOURCE=<this directory>.
file(REMOVE_RECURSE results_full results_part)
foreach(_run full part resume)
  execute_process(COMMAND ${EXECUTABLE} ${SOURCE}/${_run}.prm
    RESULT_VARIABLE _result OUTPUT_VARIABLE _out ERROR_VARIABLE _err)
  if(NOT _result EQUAL 0)
    message(FATAL_ERROR "${_run}.prm failed (${_result}):\n${_out}\n${_err}")
  endif()
endforeach()
if(NOT _out MATCHES "Restarted from the checkpoint at t = 2")
  message(FATAL_ERROR "resume.prm did not restart at t = 2 ms:\n${_out}")
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

# A checkpoint is refused by a model whose parameters differ.
execute_process(COMMAND ${EXECUTABLE} ${SOURCE}/resume_other_model.prm
  RESULT_VARIABLE _result OUTPUT_VARIABLE _out ERROR_VARIABLE _err)
if(_result EQUAL 0 OR NOT _err MATCHES "Friction coefficient = 0.31")
  message(FATAL_ERROR "a restart with another friction coefficient must be "
    "refused naming it (exit ${_result}):\n${_out}\n${_err}")
endif()
message(STATUS "restart continues identically: ${_full_steps}")
