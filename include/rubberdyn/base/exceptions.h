#ifndef rubberdyn_base_exceptions_h
#define rubberdyn_base_exceptions_h

#include <stdexcept>
#include <string>

namespace rubberdyn
{
  /**
   * Invalid user input: a parameter value out of range, two parameters that
   * contradict each other, a data file that cannot be read. Thrown while
   * parameters are parsed, before any result is written.
   *
   * The exception names the parameter by its full path, e.g.
   * `Materials/Rubber/C10`, so that the executable can report one readable
   * line that names the input file, the entry and what is wrong.
   */
  class InputError : public std::runtime_error
  {
  public:
    /**
     * @param entry_path Full path of the offending entry, subsections
     *   separated by '/', or the name of the offending file.
     * @param message What is wrong, as a sentence.
     */
    InputError(const std::string &entry_path, const std::string &message)
      : std::runtime_error(entry_path + ": " + message)
      , entry_path(entry_path)
      , message(message)
    {}

    /** Full path of the offending entry. */
    const std::string entry_path;

    /** What is wrong with it. */
    const std::string message;
  };


  /**
   * A material point was asked to evaluate a deformation gradient with
   * $J = \det F \le 0$ (an inverted element). Solvers catch this exception
   * and report which cell, where and when; a constitutive law never returns
   * NaNs instead.
   */
  class InvertedMaterialError : public std::runtime_error
  {
  public:
    explicit InvertedMaterialError(const double J)
      : std::runtime_error("deformation gradient with det F = " +
                           std::to_string(J) +
                           " <= 0 (the material is inverted)")
      , J(J)
    {}

    /** The offending Jacobian determinant. */
    const double J;
  };
} // namespace rubberdyn

#endif
