#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <rubberdyn/app/command_line.h>
#include <rubberdyn/base/exceptions.h>
#include <rubberdyn/base/parameter_tools.h>
#include <rubberdyn/base/run_options.h>
#include <rubberdyn/io/parameter_file.h>
#include <rubberdyn/materials/yeoh_fit.h>
#include <rubberdyn/postprocess/time_history_plot.h>
#include <rubberdyn/studies/study.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

namespace rubberdyn
{
  namespace app
  {
    namespace
    {
      const char *usage_text =
        "Usage:\n"
        "  rubberdyn FILE.prm            run the study described by FILE.prm\n"
        "  rubberdyn --check FILE.prm    read and validate FILE.prm and build its\n"
        "                                study without running it or writing\n"
        "                                anything; prints one line and exits 0\n"
        "                                if it would run, or the error\n"
        "  rubberdyn --default           run the default study: every parameter\n"
        "                                at its default (doc/parameters.prm)\n"
        "  rubberdyn --print-parameters  print every parameter with its\n"
        "                                documentation, allowed values and\n"
        "                                default, as a valid .prm file\n"
        "  rubberdyn --fit-yeoh MODE=FILE.csv [MODE=FILE.csv ...]\n"
        "            [--curves OUT.csv]  least-squares fit of the Yeoh\n"
        "                                constants C10, C20, C30 to test data;\n"
        "                                MODE is uniaxial, equibiaxial or\n"
        "                                pure_shear; each FILE.csv has a\n"
        "                                header 'stretch,nominal_stress [MPa]'\n"
        "                                (Pa, kPa, MPa or GPa); --curves writes\n"
        "                                measured and fitted stresses\n"
        "  rubberdyn --plot FILE.csv OUT.svg COLUMNS [COLUMNS ...]\n"
        "                                plot columns of a time history (e.g.\n"
        "                                time_history.csv) against its first\n"
        "                                column, as SVG; each COLUMNS is a\n"
        "                                comma-separated list of column names\n"
        "                                drawn in one panel\n"
        "  rubberdyn --help              this text\n"
        "\n"
        "Options of a run, before FILE.prm (testing and diagnostics; they change\n"
        "nothing in the model or its results):\n"
        "  --simulate-crash-at T         every rank kills itself (SIGKILL) when the\n"
        "                                explicit run reaches T ms: a machine that\n"
        "                                dies between checkpoints, to test a\n"
        "                                restart (doc/restarts.md)\n"
        "  --trace-pair NAME[:EVERY]     write the energy ledger of contact pair\n"
        "                                NAME to the error stream, summed over\n"
        "                                EVERY accepted steps (default 1000;\n"
        "                                doc/contact.md, \"Where a pair makes or\n"
        "                                loses energy\")\n"
        "\n"
        "Units everywhere: mm, ms, kg, kN, GPa (energy J = kN mm, density\n"
        "kg/mm^3, velocity mm/ms = m/s). Example parameter files are in\n"
        "parameter_files/; doc/parameters.prm documents every parameter.\n";

      bool
      is_root()
      {
        return dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
      }

      void
      report_error(const std::string &message)
      {
        // Every rank reads the same input and fails the same way; one
        // message is enough.
        if (is_root())
          std::cerr << "rubberdyn: error: " << message << std::endl;
      }

      int
      print_parameters()
      {
        dealii::ParameterHandler prm;
        studies::registry::declare_parameters(prm);
        if (is_root())
          io::print_documented_parameters(prm, std::cout);
        return 0;
      }

      /**
       * Run the study of @p filename, or with every parameter at its
       * default if @p filename is empty; with @p check_only, only construct
       * and check() it.
       */
      int
      run_study(const std::string &filename, const bool check_only = false)
      {
        dealii::ParameterHandler prm;
        std::unique_ptr<studies::Study> study;
        try
          {
            // The names listed in the file first: they name subsections.
            studies::registry::declare_parameters(
              prm,
              filename.empty() ? studies::registry::ListedNames() :
                                 io::read_listed_names(filename));
            if (!filename.empty())
              io::read_parameter_file(prm, filename);
            study = studies::registry::create(prm, filename);
            if (check_only)
              {
                study->check(std::cout);
                if (is_root())
                  std::cout << "rubberdyn: '" << filename << "' is a valid '"
                            << prm.get("Study")
                            << "' study (checked; nothing was run or "
                               "written)"
                            << std::endl;
                return 0;
              }
            // A study may find bad input only while it runs (before it
            // writes anything); that error names the file too, and so does
            // a run that stops (an element failure, a step that cannot
            // converge): the user sees which of their runs it was.
            try
              {
                study->run(std::cout);
              }
            catch (const InputError &)
              {
                throw;
              }
            catch (const InvertedMaterialError &error)
              {
                report_error("in the run of parameter file '" + filename +
                             "': " + error.what());
                return 3;
              }
            catch (const std::exception &error)
              {
                report_error("in the run of parameter file '" + filename +
                             "': " + error.what());
                return 1;
              }
          }
        catch (const InputError &error)
          {
            // InputErrors from the reader name the file already; those of a
            // study name the entry.
            if (!filename.empty() && error.entry_path.rfind(filename, 0) == 0)
              report_error(error.what());
            else
              report_error("in parameter file '" + filename + "', entry '" +
                           error.entry_path + "': " + error.message);
            return 2;
          }
        return 0;
      }

      int
      fit_yeoh(const std::vector<std::string> &arguments)
      {
        using namespace materials::yeoh_fit;
        std::vector<DataSet> data;
        std::string          curves_file;
        for (unsigned int i = 0; i < arguments.size(); ++i)
          {
            if (arguments[i] == "--curves")
              {
                if (i + 1 >= arguments.size())
                  throw InputError("--curves", "needs a file name");
                curves_file = arguments[++i];
                continue;
              }
            const auto equals = arguments[i].find('=');
            if (equals == std::string::npos)
              throw InputError(arguments[i],
                               "expected MODE=FILE.csv with MODE one of "
                               "uniaxial, equibiaxial, pure_shear");
            const TestMode mode =
              mode_from_name(arguments[i].substr(0, equals), arguments[i]);
            data.push_back(read_csv(arguments[i].substr(equals + 1), mode));
          }
        if (data.empty())
          throw InputError("--fit-yeoh", "needs at least one MODE=FILE.csv");

        const Result result = fit(data);
        std::cout << std::setprecision(6);
        std::cout << "Yeoh least-squares fit (incompressible, absolute "
                     "nominal-stress residuals)\n";
        const char *names[3] = {"C10", "C20", "C30"};
        for (unsigned int j = 0; j < 3; ++j)
          std::cout << "  " << names[j] << " = " << result.C[j] * 1e3
                    << " MPa\n";
        std::cout << "Error per data set:\n";
        for (unsigned int k = 0; k < data.size(); ++k)
          std::cout << "  " << std::setw(12) << std::left
                    << mode_name(data[k].mode) << std::right
                    << " points " << std::setw(3) << data[k].stretch.size()
                    << "  rms " << result.errors[k].rms_error * 1e3
                    << " MPa  mean relative "
                    << 100. * result.errors[k].mean_relative_error
                    << " %  max relative "
                    << 100. * result.errors[k].max_relative_error << " %  ("
                    << data[k].source << ")\n";
        std::cout << "For a parameter file (GPa):\n"
                  << "  set Constants from = coefficients\n";
        for (unsigned int j = 0; j < 3; ++j)
          std::cout << "  set " << names[j] << " = "
                    << parameter_tools::format_number(result.C[j]) << "\n";

        if (!curves_file.empty())
          {
            std::ofstream out(curves_file);
            if (!out)
              throw InputError(curves_file, "cannot write this file");
            out << "mode,stretch,measured_nominal_stress_MPa,"
                   "fitted_nominal_stress_MPa\n";
            out << std::setprecision(8);
            for (const DataSet &set : data)
              for (unsigned int i = 0; i < set.stretch.size(); ++i)
                out << mode_name(set.mode) << ',' << set.stretch[i] << ','
                    << set.nominal_stress[i] * 1e3 << ','
                    << nominal_stress(set.mode, set.stretch[i], result.C) *
                         1e3
                    << '\n';
            std::cout << "Wrote measured and fitted stresses to "
                      << curves_file << "\n";
          }
        return 0;
      }



      /**
       * --plot FILE.csv OUT.svg COLUMNS [COLUMNS ...]: one panel per
       * comma-separated list of column names.
       */
      int
      plot(const std::vector<std::string> &arguments)
      {
        if (arguments.size() < 3)
          throw InputError("--plot",
                           "expected FILE.csv OUT.svg COLUMNS [COLUMNS ...]");
        std::vector<postprocess::PlotPanel> panels;
        for (unsigned int i = 2; i < arguments.size(); ++i)
          {
            postprocess::PlotPanel panel;
            const std::string     &list = arguments[i];
            for (std::size_t start = 0; start <= list.size();)
              {
                std::size_t comma = list.find(',', start);
                if (comma == std::string::npos)
                  comma = list.size();
                if (comma > start)
                  panel.columns.push_back(list.substr(start, comma - start));
                start = comma + 1;
              }
            panels.push_back(panel);
          }
        if (is_root())
          {
            postprocess::write_time_history_plot(arguments[0],
                                                 arguments[1],
                                                 panels);
            std::cout << "Wrote " << arguments[1] << "\n";
          }
        return 0;
      }

      /** The value of `--simulate-crash-at T`: a time in ms, >= 0. */
      double
      parse_crash_time(const std::string &option, const std::string &value)
      {
        char        *end  = nullptr;
        const double time = std::strtod(value.c_str(), &end);
        if (value.empty() || *end != '\0' || !(time >= 0.) ||
            !std::isfinite(time))
          throw InputError(option,
                           "needs a time in ms (a number >= 0), not '" +
                             value.substr(0, 40) + "'");
        return time;
      }



      /** The value of `--trace-pair NAME[:EVERY]`, into @p options. */
      void
      parse_traced_pair(const std::string &option,
                        const std::string &value,
                        RunOptions        &options)
      {
        const std::size_t colon = value.find(':');
        options.traced_pair     = value.substr(0, colon);
        if (options.traced_pair.empty())
          throw InputError(option,
                           "needs the name of a contact pair "
                           "(NAME or NAME:EVERY), not '" +
                             value.substr(0, 40) + "'");
        if (colon == std::string::npos)
          return;
        const std::string every = value.substr(colon + 1);
        char             *end   = nullptr;
        const long        n     = std::strtol(every.c_str(), &end, 10);
        if (every.empty() || *end != '\0' || n < 1 || n > 1000000000)
          throw InputError(option,
                           "EVERY in NAME:EVERY must be a whole number of "
                           "steps from 1 to 1e9, not '" +
                             every.substr(0, 40) + "'");
        options.trace_every = static_cast<unsigned int>(n);
      }
    } // namespace



    int
    run_command_line(int argc, char *argv[])
    {
      const std::vector<std::string> arguments(argv + 1, argv + argc);
      try
        {
          if (arguments.empty())
            {
              report_error("no parameter file given\n" +
                           std::string(usage_text));
              return 1;
            }
          if (arguments[0] == "--help" || arguments[0] == "-h")
            {
              if (is_root())
                std::cout << usage_text;
              return 0;
            }
          if (arguments[0] == "--default" && arguments.size() == 1)
            return run_study("");
          if (arguments[0] == "--check" && arguments.size() == 2)
            return run_study(arguments[1], true);
          if (arguments[0] == "--print-parameters")
            return print_parameters();
          if (arguments[0] == "--fit-yeoh")
            return fit_yeoh({arguments.begin() + 1, arguments.end()});
          if (arguments[0] == "--plot")
            return plot({arguments.begin() + 1, arguments.end()});
          // The options of a run, then the one parameter file.
          RunOptions   options;
          unsigned int i = 0;
          for (; i + 1 < arguments.size(); i += 2)
            if (arguments[i] == "--simulate-crash-at")
              options.simulate_crash_at =
                parse_crash_time(arguments[i], arguments[i + 1]);
            else if (arguments[i] == "--trace-pair")
              parse_traced_pair(arguments[i], arguments[i + 1], options);
            else
              break;
          if (i == arguments.size())
            {
              report_error("no parameter file given after the options\n" +
                           std::string(usage_text));
              return 1;
            }
          if (i + 1 != arguments.size() || arguments[i].rfind("-", 0) == 0)
            {
              report_error("unknown option or extra argument in '" +
                           arguments[i] +
                           "'\n" + usage_text);
              return 1;
            }
          set_run_options(options);
          return run_study(arguments[i]);
        }
      catch (const InputError &error)
        {
          report_error(error.what());
          return 2;
        }
      catch (const InvertedMaterialError &error)
        {
          report_error(error.what());
          return 3;
        }
      catch (const std::exception &error)
        {
          report_error(error.what());
          return 1;
        }
    }
  } // namespace app
} // namespace rubberdyn
