#ifndef rubberdyn_parameters_output_parameters_h
#define rubberdyn_parameters_output_parameters_h

#include <rubberdyn/parameters/field_output_format.h>

#include <array>
#include <string>
#include <utility>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace rubberdyn
{
  namespace parameters
  {
    /**
     * The `Output` subsection: where results go, how often the time history,
     * the ParaView series and checkpoints are written, and restart.
     */
    struct Output
    {
      /** Directory for all results. */
      std::string directory = "output";
      /** Time between ParaView outputs (ms); 0: none. */
      double field_output_interval = 1.;
      /** vtu or hdf5. */
      FieldOutputFormat field_output_format = FieldOutputFormat::vtu;
      /** Time between rows of time_history.csv (ms); 0: every step. */
      double history_output_interval = 0.05;
      /** Print every history row to the log too. */
      bool echo_history = false;
      /** Wall-clock time between progress lines in the log (s); 0: none. */
      double progress_interval = 5.;
      /** Time between checkpoints (ms); 0: none. */
      double checkpoint_interval = 0.;
      /** Continue from the checkpoint in the output directory. */
      bool restart = false;

      /** A named mesh node whose displacement is a history column. */
      struct HistoryNode
      {
        /** Column prefix: `<name>_displacement_x/_y/_z`. */
        std::string name;
        /** Its position in the reference configuration (mm). */
        std::array<double, 3> point;
        /**
         * The part whose node it is ('x, y, z in part'), for a point where
         * touching parts have nodes of their own; empty: any part, and the
         * point must then be a node of one part only.
         */
        std::string part;
      };
      /** `History nodes`, in the order given. */
      std::vector<HistoryNode> history_nodes;

      /**
       * `History expressions`, in the order given: each a column name and
       * its expression (postprocess::HistoryExpressions).
       */
      std::vector<std::pair<std::string, std::string>> history_expressions;

      /**
       * Declare the entries in subsection `Output`. (`Output directory`
       * is declared here too: every study writes somewhere.)
       */
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      /**
       * The entries of `History nodes` ('name: x, y, z [in part]; ...').
       *
       * @throws InputError naming `Output/History nodes` for an entry that
       *   is not of that form, a name that is not letters, digits and '_' or
       *   is given twice, a coordinate that is not a finite number, or a
       *   part after 'in' that is not a name.
       */
      static std::vector<HistoryNode>
      parse_history_nodes(const std::string &text);

      /**
       * The entries of `History expressions` ('name: expression; ...'; the
       * expression is what follows the first ':').
       *
       * @throws InputError naming `Output/History expressions` for an entry
       *   without ':', a name that is not letters, digits and '_' or is
       *   given twice, or an empty expression.
       */
      static std::vector<std::pair<std::string, std::string>>
      parse_history_expressions(const std::string &text);

      /** Read them back (from the top level of @p prm). */
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };
  } // namespace parameters
} // namespace rubberdyn

#endif
