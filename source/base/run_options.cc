#include <rubberdyn/base/run_options.h>

namespace rubberdyn
{
  namespace
  {
    RunOptions options_of_this_run;
  }



  const RunOptions &
  run_options()
  {
    return options_of_this_run;
  }



  void
  set_run_options(const RunOptions &options)
  {
    options_of_this_run = options;
  }
} // namespace rubberdyn
