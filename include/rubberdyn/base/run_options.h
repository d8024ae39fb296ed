#ifndef rubberdyn_base_run_options_h
#define rubberdyn_base_run_options_h

#include <limits>
#include <string>

namespace rubberdyn
{
  /**
   * Options of one run that are given on the command line, not in the
   * parameter file, because they change nothing in the model or its
   * results: diagnostics and testing aids. `rubberdyn --help` lists them;
   * the executable sets them once (app::run_command_line()) before the
   * study is built, and the layers that act on them read them here.
   */
  struct RunOptions
  {
    /**
     * `--simulate-crash-at T`: the time (ms) of the explicit run at which
     * every rank kills itself with SIGKILL; +inf: never. A testing aid
     * (doc/restarts.md): a machine that dies at a known moment, between
     * checkpoints, with rows still in the stream buffers, without the race
     * of killing the run from outside.
     */
    double simulate_crash_at = std::numeric_limits<double>::infinity();

    /**
     * `--trace-pair NAME[:EVERY]`: the contact pair (its name in
     * `Contact pairs/Names`) whose energy ledger is
     * written to the standard error stream (doc/contact.md, "Where a pair
     * makes or loses energy"); empty: none.
     */
    std::string traced_pair;

    /** The accepted steps between two lines of that trace (>= 1). */
    unsigned int trace_every = 1000;
  };

  /** The options of this run (defaults until set_run_options()). */
  const RunOptions &
  run_options();

  /** Set the options of this run (the executable, once, at its start). */
  void
  set_run_options(const RunOptions &options);
} // namespace rubberdyn

#endif
