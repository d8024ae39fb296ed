#include <rubberdyn/postprocess/time_history.h>

#include <fstream>
#include <sstream>
#include <stdexcept>

#include <unistd.h>

namespace rubberdyn
{
  namespace postprocess
  {
    std::string
    TimeHistory::header(const std::vector<std::string> &columns)
    {
      std::string text;
      for (const std::string &column : columns)
        text += (text.empty() ? "" : ",") + column;
      return text;
    }



    TimeHistory::TimeHistory(const std::string &             path,
                             const std::vector<std::string> &columns,
                             const bool                      active)
      : path(path)
    {
      if (!active)
        return;
      file = std::fopen(path.c_str(), "w");
      if (file == nullptr)
        throw std::runtime_error("cannot write " + path);
      std::fprintf(file, "%s\n", header(columns).c_str());
    }



    TimeHistory::TimeHistory(const std::string &             path,
                             const std::vector<std::string> &columns,
                             const bool                      active,
                             const unsigned long             n_rows)
      : path(path)
      , rows(n_rows)
    {
      if (!active)
        return;
      std::string kept;
      {
        std::ifstream in(path);
        std::string   line;
        if (!std::getline(in, line))
          throw std::runtime_error("cannot read " + path);
        if (line != header(columns))
          throw std::runtime_error(path +
                                   " has other columns than this model writes");
        kept = line + '\n';
        for (unsigned long r = 0; r < n_rows; ++r)
          {
            if (!std::getline(in, line) || line.empty())
              throw std::runtime_error(
                path + " has " + std::to_string(r) +
                " rows, fewer than the " + std::to_string(n_rows) +
                " the checkpoint was written after");
            kept += line + '\n';
          }
      }
      file = std::fopen(path.c_str(), "w");
      if (file == nullptr)
        throw std::runtime_error("cannot write " + path);
      std::fputs(kept.c_str(), file);
    }



    TimeHistory::~TimeHistory()
    {
      if (file != nullptr)
        std::fclose(file);
    }



    std::string
    TimeHistory::write_row(const std::vector<double> &values)
    {
      std::ostringstream row;
      row.precision(9);
      for (unsigned int i = 0; i < values.size(); ++i)
        row << (i > 0 ? "," : "") << values[i];
      row << '\n';
      if (file != nullptr)
        std::fputs(row.str().c_str(), file);
      ++rows;
      return row.str();
    }



    void
    TimeHistory::make_durable()
    {
      if (file == nullptr)
        return;
      if (std::fflush(file) != 0 || ::fsync(::fileno(file)) != 0)
        throw std::runtime_error("cannot write " + path);
    }
  } // namespace postprocess
} // namespace rubberdyn
