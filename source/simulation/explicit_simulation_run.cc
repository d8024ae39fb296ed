// The run loop, output and checkpoints of simulation::ExplicitSimulation (the
// set-up is in explicit_simulation.cc).
#include <deal.II/base/mpi.h>

#include <rubberdyn/base/binary_io.h>
#include <rubberdyn/base/durable_files.h>
#include <rubberdyn/base/exceptions.h>
#include <rubberdyn/base/parameter_tools.h>
#include <rubberdyn/base/run_options.h>
#include <rubberdyn/elements/solid_hex_forces.h>
#include <rubberdyn/contact/mortar_contact_pair.h>
#include <rubberdyn/simulation/explicit_simulation.h>
#include <rubberdyn/simulation/explicit_view.h>
#include <rubberdyn/simulation/simulation_setup.h>
#include <rubberdyn/postprocess/field_output_writer.h>
#include <rubberdyn/postprocess/history_expressions.h>
#include <rubberdyn/postprocess/run_summary.h>
#include <rubberdyn/postprocess/time_history.h>
#include <rubberdyn/postprocess/time_history_plot.h>
#include <rubberdyn/time_integration/explicit_solver.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <ostream>
#include <sstream>

#include <fcntl.h>
#include <unistd.h>

namespace rubberdyn
{
  namespace simulation
  {
    using namespace model;

    namespace
    {
      /** Thrown by the monitor when a postprocessor asks to stop. */
      struct StopRequested
      {};

      // (3: the material history in blocks of 8 elements, internal::lanes,
      // instead of 4: an older file would be read in the wrong order.)
      constexpr char rank_file_magic[8] = "RDYNRK3";

      using durable_files::sync_directory;
      using durable_files::throw_if_any;
      /** Write @p data to @p path and fsync it. */
      inline void
      write_durably(const std::string &path, const std::string &data)
      {
        durable_files::write(path, data);
      }

      using postprocess::json_number;
    } // namespace



    void
    ExplicitSimulation::write_history_plot(
      const std::vector<std::string> &columns) const
    {
      postprocess::PlotPanel energies{"Energy balance",
                                      "energy (J)",
                                      {"kinetic_energy", "internal_energy",
                                       "external_work", "contact_work",
                                       "bulk_viscosity_work",
                                       "friction_work"}};
      const postprocess::PlotPanel forces{
        "Reactions and contact forces",
        "force (kN)",
        postprocess::columns_ending_with(columns, postprocess::force_suffixes)};
      const postprocess::PlotPanel displacements{
        "Displacements",
        "displacement (mm)",
        postprocess::columns_ending_with(columns, {"_displacement"})};
      // The nodes of Output/History nodes (LS-DYNA's history nodes).
      postprocess::PlotPanel history_nodes{"History nodes",
                                           "displacement (mm)",
                                           {}};
      for (const parameters::Output::HistoryNode &node : output.history_nodes)
        for (const char *d : {"_x", "_y", "_z"})
          history_nodes.columns.push_back(node.name + "_displacement" + d);
      std::vector<postprocess::PlotPanel> panels = {energies};
      for (const postprocess::PlotPanel &panel :
           {forces, displacements, history_nodes})
        if (!panel.columns.empty())
          panels.push_back(panel);
      postprocess::write_time_history_plot(output.directory +
                                             "/time_history.csv",
                                           output.directory +
                                             "/time_history.svg",
                                           panels);
    }



    double
    ExplicitSimulation::smallest_element_time_step() const
    {
      const std::vector<double> steps = elements->reference_time_steps();
      double smallest = std::numeric_limits<double>::max();
      for (unsigned int e = 0; e < steps.size(); ++e)
        smallest = std::min(smallest,
                            steps[e] *
                              std::sqrt(element_forces->density_scaling()[e]));
      return Utilities::MPI::min(smallest, model.comm);
    }



    void
    ExplicitSimulation::check(std::ostream &log)
    {
      log_model(log);
      // The first stable step: the solver's first evaluation, without
      // advancing (a run to t = 0 evaluates nothing), so estimate it by
      // one step on a copy is not possible; report the elements' reference
      // steps instead.
      const double smallest = smallest_element_time_step();
      if (Utilities::MPI::this_mpi_process(model.comm) == 0)
        log << "  Smallest element time step " << smallest
            << " ms (reference configuration, before the scale factor "
            << time_integration.time_step_scale << ")" << std::endl;
    }



    void
    ExplicitSimulation::write_checkpoint(const unsigned long history_rows,
                                         const unsigned int  restarts)
    {
      namespace fs            = std::filesystem;
      const MPI_Comm     comm = model.comm;
      const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
      const std::string  directory     = output.directory + "/checkpoint";
      const std::string  new_directory = directory + ".new";
      const std::string  old_directory = directory + ".old";
      std::string        error;
      durable_files::create_empty_directory(new_directory,
                                            comm,
                                            "Output/Checkpoint interval");

      // Every rank: its state with the step and time it belongs to.
      const time_integration::ExplicitSolver &s = *explicit_solver;
      try
        {
          std::ostringstream out;
          out.write(rank_file_magic, sizeof(rank_file_magic));
          const std::vector<double> record = deformable_errors.state();
          const double header[6] = {double(s.step()), s.time(),
                                    next_history,      next_checkpoint,
                                    max_energy_error,  double(record.size())};
          binary_io::write_doubles(out, header, 6);
          binary_io::write_doubles(out, record.data(), record.size());
          s.save(out);
          for (const auto &plugin : postprocessors)
            plugin->save(out);
          write_durably(new_directory + "/rank_" + std::to_string(rank) +
                          ".bin",
                        out.str());
        }
      catch (const std::exception &e)
        {
          error = e.what();
        }
      throw_if_any(comm, "Output/Checkpoint interval", error);

      // Rank 0: the rows written so far made durable, then study.txt, then
      // the switch: the checkpoint becomes current only once all its
      // pieces are on disk.
      if (rank == 0)
        try
          {
            history->make_durable();
            std::ostringstream study;
            study << std::setprecision(17) << "time " << s.time() << '\n'
                  << "step " << s.step() << '\n'
                  << "ranks " << Utilities::MPI::n_mpi_processes(comm) << '\n'
                  << "history_rows " << history_rows << '\n'
                  << "restarts " << restarts << '\n'
                  << "model parameters\n"
                  << model_parameters;
            write_durably(new_directory + "/study.txt", study.str());
            sync_directory(new_directory);
            fs::remove_all(old_directory);
            if (fs::exists(directory))
              fs::rename(directory, old_directory);
            fs::rename(new_directory, directory);
            sync_directory(output.directory);
            fs::remove_all(old_directory);
          }
        catch (const std::exception &e)
          {
            error = e.what();
          }
      throw_if_any(comm, "Output/Checkpoint interval", error);
    }



    std::string
    ExplicitSimulation::checkpoint_directory_of(
      const std::string &output_directory)
    {
      // write_checkpoint(): checkpoint.new/ complete, checkpoint/ renamed to
      // checkpoint.old/, checkpoint.new/ renamed to checkpoint/, .old
      // removed. Between the two renames only the old name holds one.
      const std::string current = output_directory + "/checkpoint";
      const std::string old     = current + ".old";
      if (!std::filesystem::exists(current) && std::filesystem::exists(old))
        return old;
      return current;
    }



    bool
    ExplicitSimulation::has_checkpoint(const std::string &output_directory)
    {
      return std::filesystem::exists(checkpoint_directory_of(output_directory));
    }



    std::pair<unsigned long, unsigned int>
    ExplicitSimulation::read_checkpoint_header()
    {
      const std::string entry = "Output/Restart from checkpoint";
      checkpoint_directory    = checkpoint_directory_of(output.directory);
      const std::string path  = checkpoint_directory + "/study.txt";
      std::ifstream     study(path);
      if (!study)
        throw InputError(entry,
                         "there is no complete checkpoint in " +
                           checkpoint_directory);
      std::string   key[5];
      double        time_value;
      unsigned long step, ranks, rows;
      unsigned int  restarts;
      study >> key[0] >> time_value >> key[1] >> step >> key[2] >> ranks >>
        key[3] >> rows >> key[4] >> restarts;
      if (!study || key[0] != "time" || key[1] != "step" ||
          key[2] != "ranks" || key[3] != "history_rows" || key[4] != "restarts")
        throw InputError(entry, path + " is damaged");
      std::string line, stored_parameters;
      std::getline(study, line); // the end of the last number's line
      std::getline(study, line);
      if (line != "model parameters")
        throw InputError(entry, path + " is damaged");
      while (std::getline(study, line))
        stored_parameters += line + '\n';
      if (stored_parameters != model_parameters)
        {
          // Name the first entry that differs.
          const auto [here, there] =
            parameter_tools::first_difference(model_parameters,
                                              stored_parameters);
          throw InputError(entry,
                           "the model differs from the checkpoint's ('" + here +
                             "' here, '" + there +
                             "' there); only End time and the Output "
                             "settings may change on a restart" +
                             restart_advice);
        }
      if (ranks != Utilities::MPI::n_mpi_processes(model.comm))
        throw InputError(entry, "the checkpoint was written by " +
                                  std::to_string(ranks) +
                                  " ranks; restart with as many");
      checkpoint_step = step;
      checkpoint_time = time_value;
      return {rows, restarts};
    }



    void
    ExplicitSimulation::read_checkpoint_state()
    {
      const MPI_Comm     comm  = model.comm;
      const std::string  entry = "Output/Restart from checkpoint";
      const std::string  path =
        checkpoint_directory + "/rank_" +
        std::to_string(Utilities::MPI::this_mpi_process(comm)) + ".bin";
      std::string   error;
      double        header[6] = {-1., 0., 0., 0., 0., 0.};
      std::ifstream in(path, std::ios::binary);
      try
        {
          if (!in)
            throw std::runtime_error("cannot read");
          char magic[sizeof(rank_file_magic)] = {};
          in.read(magic, sizeof(magic));
          if (!in || std::string(magic) != rank_file_magic)
            throw std::runtime_error("not a rubberdyn checkpoint");
          binary_io::read_doubles(in, header, 6, "step and time");
          if (!(header[5] >= 0. && header[5] <= 1e7))
            throw std::runtime_error("corrupt energy-error record");
          std::vector<double> record(static_cast<std::size_t>(header[5]));
          binary_io::read_doubles(in, record.data(), record.size(),
                                  "energy-error record");
          deformable_errors.set_state(record);
        }
      catch (const std::exception &e)
        {
          error = path + ": " + e.what();
          in.setstate(std::ios::failbit);
        }
      // Collective on every rank, also where the header failed (the
      // failed stream makes it fail there): it tells every rank which
      // rank's piece is bad.
      try
        {
          explicit_solver->load(in);
        }
      catch (const time_integration::SolverFailure &failure)
        {
          if (error.empty())
            {
              // "rank R: what" from the solver: name R's file.
              const std::string text = failure.what();
              unsigned int      rank = 0;
              if (std::sscanf(text.c_str(), "rank %u:", &rank) == 1)
                error = checkpoint_directory + "/rank_" +
                        std::to_string(rank) + ".bin: " +
                        text.substr(text.find(':') + 2);
              else
                error = path + ": " + text;
            }
        }
      if (error.empty())
        try
          {
            for (const auto &plugin : postprocessors)
              plugin->load(in);
            if (in.peek() != std::char_traits<char>::eof())
              throw std::runtime_error(
                "it holds more data than this model has");
          }
        catch (const std::exception &e)
          {
            error = path + ": " + e.what();
          }
      throw_if_any(comm, entry, error);
      // All pieces must belong to one step, the one study.txt names.
      const double lowest  = Utilities::MPI::min(header[0], comm);
      const double highest = Utilities::MPI::max(header[0], comm);
      if (lowest != highest || lowest != double(checkpoint_step) ||
          explicit_solver->step() != checkpoint_step ||
          explicit_solver->time() != checkpoint_time)
        throw InputError(entry,
                         "the pieces of the checkpoint in " +
                           checkpoint_directory +
                           " belong to different steps (" +
                           std::to_string(static_cast<long>(lowest)) + " to " +
                           std::to_string(static_cast<long>(highest)) +
                           ", study.txt: " + std::to_string(checkpoint_step) +
                           "); it is torn and cannot be used");
      next_history     = header[2];
      next_checkpoint  = header[3];
      max_energy_error = header[4];
    }



    std::pair<unsigned long, unsigned int>
    ExplicitSimulation::begin_restart()
    {
      // The restart's header first: it names the ParaView series.
      unsigned long history_rows = 0;
      unsigned int  restarts     = 0;
      if (output.restart)
        {
          std::string message;
          try
            {
              std::tie(history_rows, restarts) = read_checkpoint_header();
            }
          catch (const InputError &e)
            {
              message = e.message;
            }
          throw_if_any(model.comm, "Output/Restart from checkpoint", message);
          ++restarts;
        }
      return {history_rows, restarts};
    }



    void
    ExplicitSimulation::add_field_writer(const unsigned int restarts)
    {
      auto writer = std::make_unique<postprocess::FieldOutputWriter>(
        output.directory,
        restarts == 0 ? "solution" :
                        "solution_restart_" + std::to_string(restarts),
        output.field_output_format,
        output.field_output_interval,
        model.comm);
      if (!contact_pairs.empty())
        writer->add_nodal_scalars(
          {{"contact_pressure", "contact_gap", "contact_slip"}},
          [this](VectorType &values) {
            for (const auto &pair : contact_pairs)
              pair->add_surface_fields(values);
          });
      field_writer = writer.get();
      // (First: its state leads every checkpoint's plugin states.)
      postprocessors.insert(postprocessors.begin(), std::move(writer));
    }



    std::vector<std::string>
    ExplicitSimulation::history_columns()
    {
      std::vector<std::string> columns = {"time", "time_step"};
      for (const auto &plugin : postprocessors)
        for (const std::string &column : plugin->history_columns())
          columns.push_back(column);
      // Output/History expressions: columns of the others of their row.
      expressions.reset();
      if (!output.history_expressions.empty())
        {
          expressions = std::make_unique<postprocess::HistoryExpressions>(
            columns, output.history_expressions);
          for (const std::string &name : expressions->names())
            columns.push_back(name);
        }
      return columns;
    }



    void
    ExplicitSimulation::open_history(const std::vector<std::string> &columns,
                                     const unsigned long history_rows,
                                     std::ostream       &log)
    {
      const MPI_Comm    comm = model.comm;
      const bool        root = Utilities::MPI::this_mpi_process(comm) == 0;
      const std::string history_path = output.directory + "/time_history.csv";
      if (!output.restart)
        {
          history = std::make_unique<postprocess::TimeHistory>(history_path,
                                                               columns,
                                                               root);
          return;
        }
      read_checkpoint_state();
      // Only now, with the checkpoint accepted, the history is cut to the
      // rows written before it.
      std::string message;
      try
        {
          history = std::make_unique<postprocess::TimeHistory>(history_path,
                                                               columns,
                                                               root,
                                                               history_rows);
        }
      catch (const std::exception &e)
        {
          message = e.what();
        }
      throw_if_any(comm, "Output/Restart from checkpoint", message);
      if (root)
        log << "  Restarted from the checkpoint at t = "
            << explicit_solver->time() << " ms, step "
            << explicit_solver->step() << std::endl;
    }



    void
    ExplicitSimulation::write_history_row(
      const postprocess::SimulationView &view,
      std::ostream                      &log)
    {
      const time_integration::ExplicitSolver &s = *explicit_solver;
      std::vector<double> values = {s.time(), s.time_step()};
      for (const auto &plugin : postprocessors)
        plugin->history_values(view, values);
      if (expressions)
        expressions->append_values(values);
      const std::string row = history->write_row(values);
      if (Utilities::MPI::this_mpi_process(model.comm) == 0 &&
          output.echo_history)
        log << row;
      last_row_time = s.time();
    }



    void
    ExplicitSimulation::monitor_step(const postprocess::SimulationView &view,
                                     RunProgress  &progress,
                                     std::ostream &log)
    {
      const time_integration::ExplicitSolver &s = *explicit_solver;
      const double                            t = s.time();
      // --simulate-crash-at (RunOptions): a testing aid, doc/restarts.md.
      if (t >= progress.crash_time)
        std::raise(SIGKILL);
      record_energy_errors();
      if (t >= next_history * (1. - 1e-12))
        {
          write_history_row(view, log);
          next_history += output.history_output_interval;
        }
      for (const auto &plugin : postprocessors)
        plugin->after_step(view);
      for (const auto &plugin : postprocessors)
        if (plugin->stop_requested())
          {
            if (last_row_time < t)
              write_history_row(view, log);
            throw StopRequested();
          }
      // The progress line: this run's (a restart's continuation) speed.
      const auto now = std::chrono::steady_clock::now();
      if (Utilities::MPI::this_mpi_process(model.comm) == 0 &&
          output.progress_interval > 0. &&
          now - progress.last_line >
            std::chrono::duration<double>(output.progress_interval))
        {
          const double elapsed =
            std::chrono::duration<double>(now - progress.wall_start).count();
          log << "  step " << s.step() << ", t = " << t
              << " ms, dt = " << s.time_step() << " ms, about "
              << static_cast<int>(elapsed * (time_integration.end_time - t) /
                                  std::max(t - progress.first_time, 1e-12))
              << " s left" << std::endl;
          progress.last_line = now;
        }
    }



    void
    ExplicitSimulation::record_energy_errors()
    {
      const time_integration::EnergyBalance &energies =
        explicit_solver->energies();
      max_energy_error =
        std::max(max_energy_error, energies.absolute_error());
      deformable_errors.add(energies.absolute_error(),
                            energies.largest_deformable);
    }



    void
    ExplicitSimulation::monitor_end_state(
      const postprocess::SimulationView &view,
      std::ostream                      &log)
    {
      const time_integration::ExplicitSolver &s = *explicit_solver;
      record_energy_errors();
      if (last_row_time < s.time())
        write_history_row(view, log);
      for (const auto &plugin : postprocessors)
        plugin->after_step(view);
    }



    bool
    ExplicitSimulation::advance_to_end(const postprocess::SimulationView &view,
                                       RunProgress       &progress,
                                       const unsigned int restarts,
                                       std::ostream      &log)
    {
      time_integration::ExplicitSolver &s = *explicit_solver;
      try
        {
          // Run in segments that end at the checkpoint times (a segmented
          // run is the same arithmetic as an unsegmented one).
          const double end_time = time_integration.end_time;
          while (s.time() < end_time * (1. - 1e-12))
            {
              const double stop = output.checkpoint_interval > 0. ?
                                    std::min(end_time, next_checkpoint) :
                                    end_time;
              s.run(stop, [&]() { monitor_step(view, progress, log); });
              if (output.checkpoint_interval > 0. &&
                  s.time() >= next_checkpoint * (1. - 1e-12))
                {
                  next_checkpoint += output.checkpoint_interval;
                  write_checkpoint(history->n_rows(), restarts);
                }
            }
          // The state at the end time has its row too (after the last
          // checkpoint: a continuation writes it again as its first).
          s.monitor_end_state([&]() { monitor_end_state(view, log); });
        }
      catch (const StopRequested &)
        {
          return true;
        }
      catch (const time_integration::SolverFailure &failure)
        {
          field_writer->write(view);
          history->make_durable();
          throw std::runtime_error(title + " stopped: " + failure.what() +
                                   "; the last state is in " +
                                   field_writer->index_file());
        }
      return false;
    }



    void
    ExplicitSimulation::run(std::ostream &log)
    {
      const MPI_Comm comm = model.comm;
      RunProgress    progress;
      progress.wall_start = std::chrono::steady_clock::now();
      progress.last_line  = progress.wall_start;
      progress.crash_time = run_options().simulate_crash_at;
      time_integration::ExplicitSolver &s = *explicit_solver;

      log_model(log);
      std::filesystem::create_directories(output.directory);

      const auto [history_rows, restarts] = begin_restart();
      add_field_writer(restarts);
      next_history      = 0.;
      next_checkpoint   = output.checkpoint_interval;
      max_energy_error  = 0.;
      deformable_errors = time_integration::DeformableErrorRecord();
      const std::vector<std::string> columns = history_columns();
      open_history(columns, history_rows, log);

      // Where this run (a restart: its continuation) starts: the wall time,
      // the progress estimate and the cost per element-cycle are this
      // run's.
      const unsigned long first_step = s.step();
      progress.first_time             = s.time();
      const ExplicitView view(model, s, *elements, bodies);
      last_row_time = -1.;

      const bool stopped = advance_to_end(view, progress, restarts, log);
      for (const auto &plugin : postprocessors)
        plugin->finish(view);
      // The largest error of the run relative to its largest energy, and
      // relative to the energy through the deformable parts.
      max_deformable_error =
        deformable_errors.value(0.01 * s.energies().largest_energy);
      max_energy_error =
        s.energies().largest_energy > 0. ?
          max_energy_error / s.energies().largest_energy :
          0.;
      const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                      progress.wall_start)
          .count();
      std::vector<postprocess::SummaryEntry> entries =
        summary_entries(stopped, first_step, wall);
      for (const auto &plugin : postprocessors)
        plugin->summary(view, entries);
      if (Utilities::MPI::this_mpi_process(comm) == 0)
        {
          postprocess::write_run_summary(output.directory + "/run_summary.json",
                                         entries);
          // A picture of the main columns beside the table.
          history->make_durable();
          write_history_plot(columns);
          log_finish(log);
        }
    }



    std::vector<postprocess::SummaryEntry>
    ExplicitSimulation::summary_entries(const bool          stopped,
                                        const unsigned long first_step,
                                        const double        wall) const
    {
      const MPI_Comm                          comm = model.comm;
      const time_integration::ExplicitSolver &s    = *explicit_solver;
      // The cells whose forces the elements compute: a rigid part's cells
      // only give its mass (the bushing's rounded drop weight and support
      // have 1200 at its default mesh).
      const unsigned int deformable_cells =
        Utilities::MPI::sum(elements->n_elements(), comm);
      const double element_cycles =
        double(deformable_cells) * std::max<double>(s.step() - first_step, 1);
      time_integration::StepTimings timings = s.timings();
      const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
      // Each rank's element forces and contact (ns per element-cycle, as
      // the breakdown): where the ranks' loads differ, the faster waits.
      const auto by_rank = [&](const double seconds) {
        std::string list = "[";
        for (const double t : Utilities::MPI::all_gather(comm, seconds))
          list += (list.size() > 1 ? ", " : "") +
                  json_number(1e9 * t * n_ranks / element_cycles);
        return list + "]";
      };
      const std::string element_forces_by_rank =
                          by_rank(timings.element_forces),
                        contact_by_rank = by_rank(timings.contact);
      for (double *t : {&timings.element_forces, &timings.contact,
                        &timings.vector_updates, &timings.communication,
                        &timings.output})
        *t = Utilities::MPI::max(*t, comm);
      const auto per_cycle = [&](const double seconds) {
        return json_number(1e9 * seconds * n_ranks / element_cycles);
      };
      std::vector<postprocess::SummaryEntry> entries = {
        {"cells", std::to_string(model.triangulation.n_global_active_cells())},
        {"deformable_cells", std::to_string(deformable_cells)},
        {"dofs", std::to_string(model.dof_handler.n_dofs())},
        {"ranks", std::to_string(n_ranks)},
        {"time_steps", std::to_string(s.step())},
        {"timed_steps", std::to_string(s.step() - first_step)},
        {"end_time", json_number(s.time())},
        {"stopped_by_postprocessor", stopped ? "true" : "false"},
        {"wall_seconds", json_number(wall)},
        {"ns_per_element_cycle",
         json_number(1e9 * wall * n_ranks / element_cycles)},
        {"ns_per_element_cycle_breakdown",
         "{\"element_forces\": " + per_cycle(timings.element_forces) +
           ", \"contact\": " + per_cycle(timings.contact) +
           ", \"vector_updates\": " + per_cycle(timings.vector_updates) +
           ", \"communication\": " + per_cycle(timings.communication) +
           ", \"output\": " + per_cycle(timings.output) + "}"},
        {"ns_per_element_cycle_by_rank",
         "{\"element_forces\": " + element_forces_by_rank +
           ", \"contact\": " + contact_by_rank + "}"},
        {"max_energy_error", json_number(max_energy_error)},
        {"max_energy_error_of_deformable_energy",
         json_number(max_deformable_error)},
        {"added_mass_fraction",
         json_number(s.added_mass() / s.physical_mass())},
        {"friction_work", json_number(s.energies().friction_work)},
        {"physical_mass", json_number(s.physical_mass())}};
      std::string by_part = "{";
      for (unsigned int p = 0; p < model.parts.size(); ++p)
        by_part += (p > 0 ? ", \"" : "\"") + model.parts[p].name +
                   "\": " + json_number(added_mass_by_part[p]);
      entries.emplace_back("added_mass_by_part", by_part + "}");
      entries.emplace_back("initial_penetrations",
                           setup::initial_penetrations_json(model));
      // Stable time step estimate = assembled: its estimates, their cost
      // and the step's gain over the element bound.
      if (const time_integration::AssembledStepEstimate *estimate =
            s.assembled_step_estimate())
        {
          const auto &stats = estimate->statistics();
          entries.emplace_back(
            "assembled_step_estimate",
            "{\"refreshes\": " + std::to_string(stats.refreshes) +
              ", \"unconverged\": " + std::to_string(stats.unconverged) +
              ", \"stiffness_products\": " + std::to_string(stats.products) +
              ", \"seconds\": " +
              json_number(Utilities::MPI::max(stats.seconds, comm)) +
              ", \"last_gain\": " + json_number(stats.last_gain) +
              ", \"smallest_gain\": " + json_number(stats.smallest_gain) +
              ", \"largest_gain\": " + json_number(stats.largest_gain) +
              "}");
        }
      return entries;
    }



    void
    ExplicitSimulation::log_finish(std::ostream &log) const
    {
      const time_integration::ExplicitSolver &s = *explicit_solver;
      // Wall time and speed are in run_summary.json only, so that the log
      // of a run is reproducible.
      log << "Finished: " << s.step() << " steps to t = " << s.time()
          << " ms; largest energy error " << max_energy_error * 100.
          << " % of the largest energy, " << max_deformable_error * 100.
          << " % of the energy through the deformable parts" << std::endl;
      for (const auto &plugin : postprocessors)
        plugin->final_log(log);
      // The pairs whose Penalty time step lowered their penalty.
      for (unsigned int p = 0; p < contact_pairs.size(); ++p)
        if (model.contact_pairs[p].penalty_time_step > 0.)
          log << "Contact pair " << model.contact_pairs[p].name
              << ": penalty times " << contact_pairs[p]->penalty_factor()
              << " at the end (Penalty time step "
              << model.contact_pairs[p].penalty_time_step << " ms)"
              << std::endl;
      if (max_deformable_error > 0.01)
        log << "WARNING: the energy error exceeded 1 % of the energy "
               "through the deformable parts"
            << std::endl;
    }
  } // namespace simulation
} // namespace rubberdyn
