#include <rubberdyn/base/exceptions.h>
#include <rubberdyn/base/parameter_tools.h>

#include <cmath>
#include <cstdlib>
#include <sstream>

namespace rubberdyn
{
  namespace parameter_tools
  {
    std::string
    format_number(const double value)
    {
      for (int digits = 1; digits <= 17; ++digits)
        {
          std::ostringstream s;
          s.precision(digits);
          s << value;
          if (std::strtod(s.str().c_str(), nullptr) == value)
            return s.str();
        }
      std::ostringstream s;
      s.precision(17);
      s << value;
      return s.str();
    }



    std::string
    format_short(const double value)
    {
      std::ostringstream s;
      s.precision(6);
      s << value;
      return s.str();
    }



    void
    require_positive(const double value, const std::string &path)
    {
      if (!(value > 0.))
        throw InputError(path,
                         "must be positive, but is " + format_number(value));
      if (!is_usable_number(value))
        throw InputError(path,
                         "must be a finite positive number, but is " +
                           format_number(value));
    }



    bool
    is_usable_number(const double value)
    {
      return std::isfinite(value) && (value == 0. || std::isnormal(value));
    }



    void
    require_usable(const double       value,
                   const std::string &path,
                   const std::string &what,
                   const std::string &unit,
                   const Sign         sign,
                   const std::string &also_from)
    {
      const bool sign_ok = (sign == Sign::positive     ? value > 0. :
                            sign == Sign::non_negative ? value >= 0. :
                                                         true);
      if (is_usable_number(value) && sign_ok)
        return;
      const char *required =
        (sign == Sign::positive     ? "finite positive" :
         sign == Sign::non_negative ? "finite non-negative" :
                                      "finite");
      throw InputError(path,
                       (also_from.empty() ? "" : "with " + also_from + ", ") +
                         "gives " + what + " = " + format_number(value) +
                         (unit.empty() ? "" : " " + unit) +
                         ", which is not a " + required + " number" +
                         (std::isfinite(value) && value != 0. &&
                              !std::isnormal(value) ?
                            " (a denormal, below 2.2e-308 in magnitude)" :
                            ""));
    }



    std::pair<std::string, std::string>
    first_difference(const std::string &present, const std::string &stored)
    {
      std::istringstream a_lines(present), b_lines(stored);
      std::string        a, b;
      while (true)
        {
          const bool more_a = static_cast<bool>(std::getline(a_lines, a));
          const bool more_b = static_cast<bool>(std::getline(b_lines, b));
          if (!more_a)
            a.clear();
          if (!more_b)
            b.clear();
          if ((!more_a && !more_b) || a != b)
            return {a, b};
        }
    }
  } // namespace parameter_tools
} // namespace rubberdyn
