#ifndef rubberdyn_postprocess_history_expressions_h
#define rubberdyn_postprocess_history_expressions_h

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace rubberdyn
{
  namespace postprocess
  {
    /**
     * Columns of time_history.csv computed from the other columns of the
     * same row (`Output/History expressions`): each a name and a muparser
     * expression (`sqrt`, `abs`, `a < b ? c : d`, ...) whose variables are
     * the names of the columns before it, `time` and `time_step` included,
     * and of the expressions before it. A model names what it measures in
     * its own terms this way: the bushing's `drop_weight_force` is its
     * contact pair's normal force, `inner_sleeve_slip` the distance between
     * two history nodes (doc/model.md, "What it writes").
     *
     * The expressions are parsed, and evaluated once on a row of zeros, at
     * construction, so that a bad one is refused before the run starts.
     */
    class HistoryExpressions
    {
    public:
      /** A named expression, as given. */
      using Definition = std::pair<std::string, std::string>;

      /**
       * @param columns The names of the row's columns before the
       *   expressions', in order.
       * @param definitions The expressions, in order.
       * @throws InputError naming `Output/History expressions` and the
       *   expression's name: a name that is already a column, or an
       *   expression muparser refuses (an unknown column, a syntax error),
       *   with muparser's message.
       */
      HistoryExpressions(const std::vector<std::string> &columns,
                         const std::vector<Definition>  &definitions);
      ~HistoryExpressions();

      /** The expressions' names: their columns, in order. */
      std::vector<std::string>
      names() const;

      /**
       * Append the expressions' values to @p row, which holds the values of
       * the constructor's @p columns.
       */
      void
      append_values(std::vector<double> &row) const;

    private:
      struct Parsers;
      std::unique_ptr<Parsers> parsers;
    };
  } // namespace postprocess
} // namespace rubberdyn

#endif
