#ifndef rubberdyn_base_parameter_tools_h
#define rubberdyn_base_parameter_tools_h

#include <string>

namespace rubberdyn
{
  /**
   * Small helpers for declaring and checking parameters.
   */
  namespace parameter_tools
  {
    /**
     * A double as the shortest text that reads back to the same value
     * (for parameter defaults: std::to_string would print 1.1e-6 as
     * 0.000001).
     */
    std::string
    format_number(const double value);

    /** A double with six significant digits, for logs. */
    std::string
    format_short(const double value);

    /**
     * Throw an InputError naming @p path if @p value is not strictly
     * positive.
     */
    void
    require_positive(const double value, const std::string &path);
  } // namespace parameter_tools
} // namespace rubberdyn

#endif
