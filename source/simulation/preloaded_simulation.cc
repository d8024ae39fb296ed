#include <deal.II/base/mpi.h>

#include <rubberdyn/simulation/explicit_simulation.h>
#include <rubberdyn/model/model.h>
#include <rubberdyn/simulation/preload.h>
#include <rubberdyn/simulation/preloaded_simulation.h>
#include <rubberdyn/simulation/quasi_static_simulation.h>

#include <algorithm>
#include <cmath>
#include <ostream>
#include <vector>

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



    std::vector<unsigned int>
    PreloadedSimulation::hold_preloads(Model &model, const double end_time)
    {
      // Whether a function of @p bc has another value at t = end_time than
      // at t = 0 at a vertex or the centre of one of this rank's faces
      // (the nodes where a displacement acts, and a point inside the face
      // for a load that depends on the position).
      const auto changes = [&](const BoundaryCondition &bc) -> bool {
        for (const auto &cell : model.triangulation.active_cell_iterators())
          if (cell->is_locally_owned())
            for (const auto face : cell->face_indices())
              if (cell->face(face)->at_boundary() &&
                  bc.boundary_ids.count(cell->face(face)->boundary_id()))
                {
                  std::vector<Point<3>> points = {cell->face(face)->center()};
                  for (const auto v : cell->face(face)->vertex_indices())
                    points.push_back(cell->face(face)->vertex(v));
                  for (const auto &function : bc.functions)
                    for (const Point<3> &X : points)
                      {
                        const double end   = function(X, end_time);
                        const double start = function(X, 0.);
                        if (std::abs(end - start) >
                            1e-12 *
                              std::max({1., std::abs(end), std::abs(start)}))
                          return true;
                      }
                }
        return false;
      };
      std::vector<unsigned int> held;
      for (unsigned int c = 0; c < model.boundary_conditions.size(); ++c)
        {
          BoundaryCondition &bc = model.boundary_conditions[c];
          if (bc.type != BoundaryCondition::Type::displacement &&
              bc.type != BoundaryCondition::Type::traction &&
              bc.type != BoundaryCondition::Type::pressure)
            continue;
          // (Collective: every rank holds the same conditions.)
          if (!Utilities::MPI::logical_or(changes(bc), model.comm))
            continue;
          // Ramped on the load path, then held at the value it reached:
          // the explicit run starts at rest in the preloaded equilibrium
          // (zero prescribed velocity, an unchanged load).
          for (auto &function : bc.functions)
            function = [ramp = function, end_time](const Point<3> &X,
                                                   const double) {
              return ramp(X, end_time);
            };
          held.push_back(c);
        }
      return held;
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
      , end_time(time_integration.quasi_static_end_time)
    {
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
      // The load path has taken its copies of the conditions' functions;
      // the explicit run takes the held ones (also when it starts from
      // the preload checkpoint, whose load path ran with the same rule).
      held_conditions =
        hold_preloads(model, time_integration.quasi_static_end_time);
      explicit_run = std::make_unique<ExplicitSimulation>(
        model, time_integration, explicit_output, title, model_parameters);
      explicit_run->set_restart_advice(
        "; to run the impact again from the preload, delete " +
        ExplicitSimulation::checkpoint_directory_of(output.directory));
      explicit_run->add_standard_postprocessors();
    }



    PreloadedSimulation::~PreloadedSimulation() = default;



    void
    PreloadedSimulation::log_held_conditions(std::ostream &log) const
    {
      if (Utilities::MPI::this_mpi_process(model.comm) != 0)
        return;
      for (const unsigned int c : held_conditions)
        log << "  Boundary conditions/" << model.boundary_conditions[c].name
            << ": a preload (its value at t = " << end_time
            << " differs from t = 0): ramped on the load path, held at its "
               "value at t = "
            << end_time << " in the explicit run" << std::endl;
    }



    void
    PreloadedSimulation::check(std::ostream &log)
    {
      if (quasi_static)
        quasi_static->check(log);
      log_held_conditions(log);
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
      log_held_conditions(log);
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
