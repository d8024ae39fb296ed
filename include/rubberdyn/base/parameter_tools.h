#ifndef rubberdyn_base_parameter_tools_h
#define rubberdyn_base_parameter_tools_h

#include <string>
#include <utility>

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
     * positive, or not a usable number (see is_usable_number()).
     */
    void
    require_positive(const double value, const std::string &path);

    /**
     * Whether @p value can be computed with: finite and, unless zero, a
     * normal double. NaN, infinity and denormals (magnitude below
     * 2.2e-308, e.g. 1e-320, which have lost precision and turn into
     * infinity when inverted) are not.
     */
    bool
    is_usable_number(const double value);

    /** The sign a quantity must have. */
    enum class Sign
    {
      positive,
      non_negative,
      any
    };

    /**
     * Throw an InputError naming @p path unless @p value is a usable number
     * (is_usable_number()) of sign @p sign. For quantities derived from the
     * input, so that an overflow (G = 2 C10 = inf for C10 = 1e308) or an
     * underflow is refused before anything runs.
     *
     * @param value The derived quantity.
     * @param path Full path of the entry it is derived from.
     * @param what The quantity and how it is derived, for the message,
     *   e.g. "the shear modulus G = 2 C10".
     * @param unit Its unit, e.g. "GPa", or empty.
     * @param sign The sign it must have.
     * @param also_from Other entries it is computed from, for the
     *   message, e.g. "'Poisson's ratio' and 'Density'".
     */
    void
    require_usable(const double       value,
                   const std::string &path,
                   const std::string &what,
                   const std::string &unit,
                   const Sign         sign      = Sign::positive,
                   const std::string &also_from = "");

    /**
     * The first line in which two parameter texts (one entry per line, as
     * simulation::ExplicitSimulation::model_parameters_text() writes them)
     * differ: {line of @p present, line of @p stored} (empty where one text
     * ends), for a message that names the entry that changed.
     */
    std::pair<std::string, std::string>
    first_difference(const std::string &present, const std::string &stored);
  } // namespace parameter_tools
} // namespace rubberdyn

#endif
