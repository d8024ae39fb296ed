#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <rubberdyn/base/exceptions.h>
#include <rubberdyn/parameters/output_parameters.h>

#include <cmath>
#include <stdexcept>

namespace rubberdyn
{
  namespace parameters
  {
    using namespace dealii;

    std::string
    field_output_format_names()
    {
      return "vtu|hdf5";
    }



    FieldOutputFormat
    parse_field_output_format(const std::string &name)
    {
      if (name == "vtu")
        return FieldOutputFormat::vtu;
      if (name == "hdf5")
        return FieldOutputFormat::hdf5;
      throw std::invalid_argument("unknown field output format '" + name +
                                  "' (valid: " + field_output_format_names() +
                                  ")");
    }



    void
    Output::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      prm.declare_entry("Output directory",
                        "output",
                        Patterns::DirectoryName(),
                        "Directory for all results; created if missing. "
                        "A relative path is relative to the working "
                        "directory the run starts in (the results go where "
                        "you run), unlike Mesh/Mesh file, which is relative "
                        "to the parameter file's folder (the inputs are "
                        "found where they are).");
      prm.declare_entry("Field output interval",
                        "1",
                        Patterns::Double(0.),
                        "Time between ParaView outputs (ms; in the "
                        "quasi-static scheme, pseudo-time of the load "
                        "path); 0: only the last state (also of a run that "
                        "fails).");
      prm.declare_entry(
        "Field output format",
        "vtu",
        Patterns::Selection(field_output_format_names()),
        "'vtu': per output time a solution_NNNN.pvtu with one .vtu per rank, "
        "indexed by solution.pvd. 'hdf5' (for large runs): per output time "
        "one solution_NNNN.h5 written by all ranks in parallel (MPI-IO), "
        "holding the mesh, the nodal vectors and the cell fields, indexed by "
        "solution.xdmf. Both open in ParaView as a time series: reference "
        "mesh with displacement, velocity (nodal), Cauchy stress "
        "components, von Mises stress, pressure (GPa), J, MPI rank, part "
        "id and material id (cell values).");
      prm.declare_entry("Echo time history",
                        "false",
                        Patterns::Bool(),
                        "Also print every row of time_history.csv to the "
                        "terminal (for regression tests).");
      prm.declare_entry("Progress interval",
                        "5",
                        Patterns::Double(0.),
                        "Wall-clock time between the progress lines of an "
                        "explicit run in the log (s): step, time, step size "
                        "and the estimated time left. 0 prints none (for "
                        "logs compared in regression tests: the lines depend "
                        "on the machine's speed).");
      prm.declare_entry("History output interval",
                        "0.05",
                        Patterns::Double(0.),
                        "Time between rows of time_history.csv (ms), from "
                        "t = 0; the run's end state has a row too (at or "
                        "just past the End time: the last step is not "
                        "shortened). 0 writes every step.");
      prm.declare_entry(
        "History nodes",
        "",
        Patterns::Anything(),
        "Mesh nodes whose displacement goes to time_history.csv (LS-DYNA's "
        "*DATABASE_HISTORY_NODE): 'name: x, y, z' entries separated by ';', "
        "the point in the reference configuration (mm); each adds the "
        "columns <name>_displacement_x, _y, _z (mm). A node of the mesh must "
        "lie at the point (within 1e-6 of the mesh's size); where touching "
        "parts have nodes of their own at the same point, 'name: x, y, z in "
        "part' names the part whose node is meant (a point that is a node of "
        "two parts is refused without it). Names are letters, digits and "
        "'_'. Empty: none.");
      prm.declare_entry(
        "History expressions",
        "",
        Patterns::Anything(),
        "Columns of time_history.csv computed from the other columns of the "
        "same row: 'name: expression' entries separated by ';' (the "
        "expression is what follows the first ':'), in muparser's syntax "
        "(+ - * / ^, sqrt, abs, sin, exp, min, max, a < b ? c : d, ...) of "
        "the names of the columns, 'time' and 'time_step' included, and of "
        "the expressions before it; the value in the unit that follows from "
        "the columns'. E.g. 'drop_weight_force: drop_plate_normal_force; "
        "slip: sqrt((a_displacement_x - b_displacement_x)^2 + "
        "(a_displacement_y - b_displacement_y)^2)'. Explicit runs (and the "
        "explicit part of 'quasi-static then explicit'). Empty: none.");
      prm.declare_entry("Checkpoint interval",
                        "0",
                        Patterns::Double(0.),
                        "Time between checkpoints (ms), written to the "
                        "directory 'checkpoint' in the output directory (one "
                        "binary file per rank plus study.txt, each replacing "
                        "the previous one); 0 writes none.");
      prm.declare_entry("Restart from checkpoint",
                        "false",
                        Patterns::Bool(),
                        "Continue from the checkpoint in the output "
                        "directory instead of starting at t = 0, with the "
                        "same number of ranks and the same model parameters "
                        "(End time and the output settings may differ). The "
                        "run continues exactly as the original would have; "
                        "time_history.csv keeps its rows before the "
                        "checkpoint, the ParaView series goes on in "
                        "solution_restart_<k>.pvd (.xdmf) for the k-th restart "
                        "(doc/restarts.md). 'quasi-static then explicit': the "
                        "explicit run continues from its own checkpoint if "
                        "there is one, else starts from the preload in "
                        "preload/checkpoint (doc/quasi_static.md).");
      prm.leave_subsection();
    }



    namespace
    {
      /**
       * Whether @p word is a name of a column or a part: letters, digits
       * and '_', not empty.
       */
      bool
      is_name(const std::string &word)
      {
        return !word.empty() &&
               word.find_first_not_of(
                 "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                 "0123456789_") == std::string::npos;
      }



      /**
       * The 'name: rest' entries of @p text, separated by ';', as pairs
       * of the trimmed name and the trimmed rest (what follows the first
       * ':'), for `History nodes` and `History expressions` alike.
       *
       * @throws InputError naming @p path for an entry without ':' (the
       *   message shows @p form), a name that is not letters, digits and
       *   '_', or a name given twice.
       */
      std::vector<std::pair<std::string, std::string>>
      named_entries(const std::string &text,
                    const std::string &path,
                    const std::string &form)
      {
        std::vector<std::pair<std::string, std::string>> entries;
        for (const std::string &entry : Utilities::split_string_list(text, ';'))
          {
            const std::size_t colon = entry.find(':');
            if (colon == std::string::npos)
              throw InputError(path,
                               "the entry '" + entry +
                                 "' is not of the form '" + form + "'");
            const std::string name = Utilities::trim(entry.substr(0, colon));
            if (!is_name(name))
              throw InputError(path,
                               "the name '" + name + "' of the entry '" +
                                 entry +
                                 "' must be letters, digits and '_' only");
            for (const auto &other : entries)
              if (other.first == name)
                throw InputError(path,
                                 "the name '" + name + "' is given twice");
            entries.emplace_back(name,
                                 Utilities::trim(entry.substr(colon + 1)));
          }
        return entries;
      }
    } // namespace



    std::vector<Output::HistoryNode>
    Output::parse_history_nodes(const std::string &text)
    {
      const std::string        path = "Output/History nodes";
      std::vector<HistoryNode> nodes;
      for (const auto &[name, entry] :
           named_entries(text, path, "name: x, y, z [in part]"))
        {
          HistoryNode node;
          node.name = name;
          // 'x, y, z in part': the part is the word after " in ".
          std::string       point = entry;
          const std::size_t in    = entry.find(" in ");
          if (in != std::string::npos)
            {
              point     = Utilities::trim(entry.substr(0, in));
              node.part = Utilities::trim(entry.substr(in + 4));
              if (!is_name(node.part))
                throw InputError(path,
                                 "what follows 'in' in the entry of '" +
                                   node.name + "' ('" + node.part +
                                   "') must be the name of a part");
            }
          const std::vector<std::string> coordinates =
            Utilities::split_string_list(point, ',');
          if (coordinates.size() != 3)
            throw InputError(path,
                             "the point of '" + node.name +
                               "' needs three coordinates x, y, z (mm), not '" +
                               point + "'");
          for (unsigned int d = 0; d < 3; ++d)
            {
              try
                {
                  std::size_t used = 0;
                  node.point[d]    = std::stod(coordinates[d], &used);
                  if (used != coordinates[d].size() ||
                      !std::isfinite(node.point[d]))
                    throw std::invalid_argument("");
                }
              catch (const std::exception &)
                {
                  throw InputError(path,
                                   "the coordinate '" + coordinates[d] +
                                     "' of '" + node.name +
                                     "' is not a finite number");
                }
            }
          nodes.push_back(node);
        }
      return nodes;
    }



    std::vector<std::pair<std::string, std::string>>
    Output::parse_history_expressions(const std::string &text)
    {
      const std::string path = "Output/History expressions";
      const std::vector<std::pair<std::string, std::string>> expressions =
        named_entries(text, path, "name: expression");
      for (const auto &[name, expression] : expressions)
        if (expression.empty())
          throw InputError(path, "the expression of '" + name + "' is empty");
      return expressions;
    }



    void
    Output::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      directory             = prm.get("Output directory");
      field_output_interval = prm.get_double("Field output interval");
      field_output_format =
        parse_field_output_format(prm.get("Field output format"));
      history_output_interval = prm.get_double("History output interval");
      echo_history            = prm.get_bool("Echo time history");
      progress_interval       = prm.get_double("Progress interval");
      checkpoint_interval     = prm.get_double("Checkpoint interval");
      restart                 = prm.get_bool("Restart from checkpoint");
      history_nodes           = parse_history_nodes(prm.get("History nodes"));
      history_expressions =
        parse_history_expressions(prm.get("History expressions"));
      prm.leave_subsection();
    }
  } // namespace parameters
} // namespace rubberdyn
