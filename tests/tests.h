// Shared set-up of the unit tests: each test writes its results to the file
// "output" in its working directory, which the deal.II test machinery
// compares with the checked-in <test>.output using numdiff (absolute
// tolerance 1e-6, relative 1e-8). Quantities that must hold to a stated
// tolerance are also checked with check(), which makes the test fail
// outright, whatever is printed.
#ifndef rubberdyn_tests_h
#define rubberdyn_tests_h

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <string>

namespace testing
{
  /** The stream every test writes to. */
  inline std::ofstream &
  out()
  {
    static std::ofstream stream("output");
    return stream;
  }

  /**
   * Fail the test (non-zero exit) with a message if @p condition is false.
   */
  inline void
  check(const bool condition, const std::string &what)
  {
    if (!condition)
      {
        out() << "CHECK FAILED: " << what << std::endl;
        std::cerr << "CHECK FAILED: " << what << std::endl;
        std::exit(1);
      }
  }

  /** A number in scientific notation with two digits, for error values. */
  inline std::string
  sci(const double value)
  {
    char buffer[32];
    std::snprintf(buffer, sizeof(buffer), "%.2e", value);
    return buffer;
  }
} // namespace testing

#endif
