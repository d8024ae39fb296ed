#include <deal.II/base/exceptions.h>

#include <rubberdyn/base/exceptions.h>
#include <rubberdyn/postprocess/history_expressions.h>

#include <muParser.h>

#include <algorithm>
#include <cmath>

namespace rubberdyn
{
  namespace postprocess
  {
    /** One muparser per expression, over one array of variables. */
    struct HistoryExpressions::Parsers
    {
      std::vector<std::string> names;
      /**
       * The row's values followed by the expressions' (the variables'
       * storage: muparser keeps pointers into it, so it is sized once).
       */
      std::vector<double>         variables;
      std::size_t                 n_columns = 0;
      std::vector<mu::Parser>     parsers;
    };



    HistoryExpressions::HistoryExpressions(
      const std::vector<std::string> &columns,
      const std::vector<Definition>  &definitions)
      : parsers(std::make_unique<Parsers>())
    {
      const std::string path = "Output/History expressions";
      Parsers          &p    = *parsers;
      p.n_columns            = columns.size();
      p.variables.assign(columns.size() + definitions.size(), 0.);
      p.parsers.resize(definitions.size());
      std::vector<std::string> known = columns;
      for (unsigned int e = 0; e < definitions.size(); ++e)
        {
          const std::string &name = definitions[e].first;
          for (const std::string &column : known)
            if (column == name)
              throw InputError(path,
                               "the name '" + name +
                                 "' is already a column of time_history.csv");
          mu::Parser &parser = p.parsers[e];
          try
            {
              for (unsigned int v = 0; v < known.size(); ++v)
                parser.DefineVar(known[v], &p.variables[v]);
              parser.SetExpr(definitions[e].second);
              // Evaluating finds unknown variables and syntax errors.
              parser.Eval();
            }
          catch (const mu::Parser::exception_type &error)
            {
              throw InputError(path,
                               "the expression of '" + name + "' ('" +
                                 definitions[e].second.substr(0, 80) +
                                 "'): " + error.GetMsg());
            }
          known.push_back(name);
          p.names.push_back(name);
        }
    }



    HistoryExpressions::~HistoryExpressions() = default;



    std::vector<std::string>
    HistoryExpressions::names() const
    {
      return parsers->names;
    }



    void
    HistoryExpressions::append_values(std::vector<double> &row) const
    {
      Parsers &p = *parsers;
      AssertThrow(row.size() == p.n_columns,
                  dealii::ExcDimensionMismatch(row.size(), p.n_columns));
      std::copy(row.begin(), row.end(), p.variables.begin());
      for (unsigned int e = 0; e < p.parsers.size(); ++e)
        {
          double value;
          try
            {
              value = p.parsers[e].Eval();
            }
          catch (const mu::Parser::exception_type &)
            {
              value = std::nan("");
            }
          p.variables[p.n_columns + e] = value;
          row.push_back(value);
        }
    }
  } // namespace postprocess
} // namespace rubberdyn
