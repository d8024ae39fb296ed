#include <rubberdyn/postprocess/run_summary.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace rubberdyn
{
  namespace postprocess
  {
    std::string
    json_number(const double value)
    {
      if (!std::isfinite(value))
        return "null";
      std::ostringstream s;
      s << std::setprecision(9) << value;
      return s.str();
    }



    std::string
    json_string(const std::string &text)
    {
      std::string result = "\"";
      for (const char c : text)
        if (c == '"' || c == '\\')
          result += std::string("\\") + c;
        else if (static_cast<unsigned char>(c) < 0x20)
          {
            char escaped[8];
            std::snprintf(escaped, sizeof(escaped), "\\u%04x", c);
            result += escaped;
          }
        else
          result += c;
      return result + "\"";
    }



    void
    write_run_summary(const std::string               &path,
                      const std::vector<SummaryEntry> &entries)
    {
      std::ofstream summary(path);
      summary << "{";
      for (unsigned int i = 0; i < entries.size(); ++i)
        summary << (i > 0 ? "," : "") << "\n  \"" << entries[i].first
                << "\": " << entries[i].second;
      summary << "\n}\n";
      summary.close();
      if (!summary)
        throw std::runtime_error(path + ": cannot write this file");
    }
  } // namespace postprocess
} // namespace rubberdyn
