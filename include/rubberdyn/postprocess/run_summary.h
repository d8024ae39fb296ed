#ifndef rubberdyn_postprocess_run_summary_h
#define rubberdyn_postprocess_run_summary_h

#include <rubberdyn/postprocess/postprocessor.h>

#include <string>
#include <vector>

namespace rubberdyn
{
  namespace postprocess
  {
    /**
     * A number as JSON text: nine significant digits, `null` for NaN and
     * infinity (which JSON cannot hold).
     */
    std::string
    json_number(const double value);

    /** A string as JSON text: quoted, with `"`, `\` and control characters
     * escaped. */
    std::string
    json_string(const std::string &text);

    /**
     * Write run_summary.json at @p path: one JSON object of @p entries in
     * their order, one a line (the same layout for every scheme, so that
     * scripts read them alike). Call on one rank.
     */
    void
    write_run_summary(const std::string               &path,
                      const std::vector<SummaryEntry> &entries);
  } // namespace postprocess
} // namespace rubberdyn

#endif
