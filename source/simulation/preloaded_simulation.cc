#include <deal.II/base/mpi.h>

#include <rubberdyn/base/durable_files.h>
#include <rubberdyn/base/exceptions.h>
#include <rubberdyn/simulation/explicit_simulation.h>
#include <rubberdyn/model/model.h>
#include <rubberdyn/simulation/preload.h>
#include <rubberdyn/simulation/preloaded_simulation.h>
#include <rubberdyn/simulation/quasi_static_simulation.h>

#include <cmath>
#include <ostream>
#include <sstream>

namespace rubberdyn
{
  namespace simulation
  {
    using namespace model;

    namespace
    {
      /** Whether @p directory holds a complete checkpoint of an explicit run
       * (collective). */
      bool
      has_explicit_checkpoint(const std::string &directory, const MPI_Comm comm)
      {
        const bool found = Utilities::MPI::this_mpi_process(comm) == 0 &&
                           ExplicitSimulation::has_checkpoint(directory);
        return Utilities::MPI::logical_or(found, comm);
      }
    } // namespace



    void
    PreloadedSimulation::check_continuity(const Model &model,
                                          const double end_time)
    {
      // The first face centre of @p bc where the value jumps, as a message.
      const auto jump = [&](const BoundaryCondition &bc) -> std::string {
        for (const auto &cell : model.triangulation.active_cell_iterators())
          if (cell->is_locally_owned())
            for (const auto face : cell->face_indices())
              if (cell->face(face)->at_boundary() &&
                  bc.boundary_ids.count(cell->face(face)->boundary_id()))
                for (const auto &function : bc.functions)
                  {
                    const Point<3> X     = cell->face(face)->center();
                    const double   end   = function(X, end_time);
                    const double   start = function(X, 0.);
                    if (std::abs(end - start) <=
                        1e-12 * std::max({1., std::abs(end), std::abs(start)}))
                      continue;
                    std::ostringstream text;
                    text << "'quasi-static then explicit' starts the "
                            "explicit run (t = 0) from the end of the "
                            "load path (t = "
                         << end_time << "), so the condition must have "
                         << "the same value at both; at (" << X << ") it is "
                         << end << " at t = " << end_time << " and " << start
                         << " at t = 0 (e.g. hold it constant, or write it "
                            "for the explicit run only)";
                    return text.str();
                  }
        return "";
      };
      for (const BoundaryCondition &bc : model.boundary_conditions)
        if (bc.type == BoundaryCondition::Type::displacement ||
            bc.type == BoundaryCondition::Type::traction ||
            bc.type == BoundaryCondition::Type::pressure)
          durable_files::throw_if_any(model.comm,
                                      "Boundary conditions/" + bc.name +
                                        "/Function expression",
                                      jump(bc));
    }



    PreloadedSimulation::PreloadedSimulation(
      Model                             &model,
      const parameters::TimeIntegration &time_integration,
      const parameters::Output          &output,
      const std::string                 &title,
      const std::string                 &model_parameters)
      : model(model)
      , output(output)
      , preload_parameters(
          preload_parameters_text(model_parameters, model.gravity.norm() != 0.))
      , checkpoint_directory(output.directory + "/preload/checkpoint")
    {
      check_continuity(model, time_integration.quasi_static_end_time);
      // The preload's rows go to preload/, the explicit run's to the
      // output directory. The preload is a checkpoint by itself; a restart
      // continues the explicit run from its own checkpoint (Output/
      // Checkpoint interval) if there is one, else starts it from the
      // preload.
      parameters::Output preload_output  = output;
      preload_output.directory           = output.directory + "/preload";
      preload_output.restart             = false;
      preload_output.checkpoint_interval = 0.;
      QuasiStaticSimulation::check_supported(model,
                                             time_integration,
                                             preload_output);
      parameters::Output explicit_output = output;
      explicit_output.restart            = continues =
        output.restart && has_explicit_checkpoint(output.directory, model.comm);
      if (!output.restart)
        quasi_static = std::make_unique<QuasiStaticSimulation>(
          model, time_integration, preload_output, title + " preload");
      explicit_run = std::make_unique<ExplicitSimulation>(
        model, time_integration, explicit_output, title, model_parameters);
      explicit_run->set_restart_advice(
        "; to run the impact again from the preload, delete " +
        ExplicitSimulation::checkpoint_directory_of(output.directory));
      explicit_run->add_standard_postprocessors();
    }



    PreloadedSimulation::~PreloadedSimulation() = default;



    void
    PreloadedSimulation::check(std::ostream &log)
    {
      if (quasi_static)
        quasi_static->check(log);
      explicit_run->check(log);
    }



    void
    PreloadedSimulation::run(std::ostream &log)
    {
      const bool   root = Utilities::MPI::this_mpi_process(model.comm) == 0;
      PreloadState state;
      if (quasi_static)
        {
          quasi_static->run(log);
          state = quasi_static->preload_state();
          write_preload(state,
                        checkpoint_directory,
                        preload_parameters,
                        model.comm);
          if (root)
            log << "Preload written to " << checkpoint_directory << std::endl;
        }
      else
        {
          // Also under the explicit run's own checkpoint: the preload sets
          // what that does not hold (the locked sections' shortenings).
          state = explicit_run->read_preload(checkpoint_directory,
                                             preload_parameters);
          if (root)
            log << "Starting from the preload in " << checkpoint_directory
                << " (t = " << state.time << ")"
                << (continues ? ", continuing from the explicit run's "
                                "checkpoint in " +
                                  ExplicitSimulation::checkpoint_directory_of(
                                    output.directory) :
                                "")
                << std::endl;
        }
      if (root)
        for (unsigned int s = 0; s < state.shortenings.size(); ++s)
          log << "  Pretension section "
              << model.pretension_sections[s].name << " locked: force "
              << state.section_forces[s] << " kN, shortening "
              << state.shortenings[s] << " mm" << std::endl;
      explicit_run->start_from(state);
      explicit_run->run(log);
    }
  } // namespace simulation
} // namespace rubberdyn
