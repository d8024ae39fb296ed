#include <rubberdyn/base/exceptions.h>
#include <rubberdyn/base/parameter_tools.h>

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
    }
  } // namespace parameter_tools
} // namespace rubberdyn
