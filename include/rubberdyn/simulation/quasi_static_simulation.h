#ifndef rubberdyn_simulation_quasi_static_simulation_h
#define rubberdyn_simulation_quasi_static_simulation_h

#include <deal.II/base/types.h>

#include <rubberdyn/parameters/output_parameters.h>
#include <rubberdyn/parameters/time_integration_parameters.h>
#include <rubberdyn/postprocess/load_path_body_columns.h>
#include <rubberdyn/postprocess/postprocessor.h>
#include <rubberdyn/simulation/preload.h>
#include <rubberdyn/time_integration/quasi_static_solver.h>

#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

namespace rubberdyn
{
  namespace contact
  {
    class RigidSurfaceContact;
    class RigidSurfaceForces;
    class MortarContactPair;
  } // namespace contact
  namespace elements
  {
    class ImplicitElements;
    class SolidHexElements;
  } // namespace elements
  namespace postprocess
  {
    class HistoryNodes;
    class TimeHistory;
  } // namespace postprocess
  namespace time_integration
  {
    class KinematicConstraints;
    class QuasiStaticSolver;
  } // namespace time_integration

  namespace model
  {
    class Model;
    class SurfaceLoads;
    class GravityLoad;
  } // namespace model

  namespace simulation
  {
    using namespace dealii;
    /* The model layer's names, used here unqualified. */
    using model::Model;
    using model::SurfaceLoads;
    using model::GravityLoad;
    using model::RigidBody;


    /**
     * The quasi-static engine path (`Time integration/Scheme =
     * quasi-static`): takes a Model and brings it through the load path of
     * its boundary-condition functions, t from 0 to `Time integration/
     * Quasi-static end time`, by Newton-Raphson
     * (time_integration::QuasiStaticSolver). It builds the elements and the
     * kinematic constraints exactly as simulation::ExplicitSimulation does
     * (simulation::setup), and writes time_history.csv: time,
     * newton_iterations, then the columns of its postprocessors
     * (add_postprocessors(): they see the run through a QuasiStaticView):
     * internal_energy and per part `<part>_internal_energy`, per boundary
     * condition its reaction `<bc>_force_x/_y/_z` (kN) and
     * `<bc>_moment_x/_y/_z` (kN mm), the pretension sections, the rigid
     * surfaces and parts, the contact pairs and the `Output/History
     * nodes`' displacements: the plugins, columns and sign conventions of
     * the explicit run where the quantity is the same (the force the
     * condition exerts on the body; for a pressure or traction, the load's
     * resultant). Pressures and tractions
     * are the same model::SurfaceLoads contribution as in the explicit run,
     * evaluated at each load step's end time with the pressures' load
     * stiffness in the tangent.
     *
     * What the scheme cannot run yet is refused before anything is written
     * (check_supported()).
     */
    class QuasiStaticSimulation
    {
    public:
      /**
       * Set everything up (nothing is written yet).
       *
       * @throws InputError naming `Time integration/Scheme` and the entry
       *   of the model that the scheme cannot run (check_supported()).
       */
      QuasiStaticSimulation(Model                             &model,
                            const parameters::TimeIntegration &time_integration,
                            const parameters::Output          &output,
                            const std::string                 &title);

      ~QuasiStaticSimulation();

      /**
       * Refuse, with an InputError naming `Time integration/Scheme` and the
       * offending entry, a model or settings the quasi-static scheme
       * cannot run yet: velocity conditions,
       * initial velocities, gravity, mass scaling,
       * checkpoints and restarts.
       */
      static void
      check_supported(const Model                       &model,
                      const parameters::TimeIntegration &time_integration,
                      const parameters::Output          &output);

      /**
       * The converged state for the explicit run of `quasi-static then
       * explicit` (after run()): displacement, history, section
       * shortenings and forces.
       */
      PreloadState
      preload_state() const;

      /** Log the model and the solver settings without running: `--check`. */
      void
      check(std::ostream &log);

      /**
       * Run the load path to the Quasi-static end time.
       *
       * @throws std::runtime_error if a load step cannot converge, after
       *   writing the rows of every converged step.
       */
      void
      run(std::ostream &log);

      /** The solver (after construction). */
      const time_integration::QuasiStaticSolver &
      solver() const
      {
        return *newton;
      }

    private:
      void
      log_model(std::ostream &log) const;

      /**
       * The history's plugins, in the order of their columns: the
       * internal energies, the boundary conditions' reactions and loads,
       * the pretension sections, the rigid surfaces and parts, the contact
       * pairs and the history nodes. (End of the constructor: the rigid
       * parts' columns read the solver's poses.)
       */
      void
      add_postprocessors();

      /**
       * The columns of time_history.csv: time, newton_iterations and the
       * plugins'.
       */
      std::vector<std::string>
      history_columns() const;

      /**
       * Write the row of the last converged state to @p history (echoed to
       * @p log with Output/Echo history) and set the time of the next row
       * (collective: the plugins sum over the ranks).
       */
      void
      write_history_row(const postprocess::SimulationView &view,
                        postprocess::TimeHistory          &history,
                        std::ostream                      &log);

      /** The "Finished:" line of the log (rank 0). */
      void
      log_totals(std::ostream &log) const;

      /**
       * On rank 0: run_summary.json (sizes, load steps, Newton, linear and
       * cut-back iterations, wall time, and @p failure, empty for a run
       * that reached its end) and time_history.svg (the internal energy,
       * the reactions and forces, the Newton iterations per step over the
       * pseudo-time) from the written @p columns.
       */
      void
      write_summary_and_plot(const std::vector<std::string> &columns,
                             const double                    wall_seconds,
                             const std::string              &failure) const;

      /**
       * Whether the rigid surfaces follow their Velocity function over
       * the pseudo-time (Scheme = quasi-static), or stand still (the load
       * path of a preload: their motion is the explicit run's).
       */
      bool
      bodies_follow_load_path() const;

      /**
       * Refuse a rigid part @p p in equilibrium that shares no node with a
       * deformable part (nothing would hold it), naming its `Quasi-static
       * motion`. Collective.
       */
      void
      require_held_by_solid(const unsigned int p) const;

      /**
       * Let the model's pretension sections cut @p hexes and set
       * pretension_loads and cut_elements.
       *
       * @throws InputError naming `Pretension sections/<name>/Point` for a
       *   section that cuts no element, or `Pretension sections/Names` for
       *   an element cut by two.
       */
      void
      cut_pretension_sections(elements::SolidHexElements &hexes);

      /**
       * Set the solver's round-off floor (time_integration::
       * QuasiStaticSolver::set_roundoff_floor()) to
       * eps max_p (K_p + 4 G_p / 3) h_p^2 sqrt(N): eps the machine
       * epsilon, K_p and G_p the small-strain bulk and shear moduli of
       * deformable part p (GPa, kN/mm^2), h_p its mean cell size (the cube
       * root of its volume over its number of cells, mm), N the number of
       * dofs. The strain is computed from F = 1 + grad u, so it carries a
       * round-off of eps whatever the load, and an element's nodal forces
       * one of about eps (K + 4 G / 3) h^2 (the dilatational modulus: the
       * stiffest response); the residual's norm sums N such errors in
       * squares. No deformable part: 0. Collective.
       */
      void
      set_roundoff_floor();

      /**
       * The part that sets the round-off floor
       * (numbers::invalid_unsigned_int if none) and its mean cell size h
       * (mm).
       */
      unsigned int roundoff_part = numbers::invalid_unsigned_int;
      double       roundoff_size = 0.;

      Model                                                  &model;
      parameters::TimeIntegration                             time_integration;
      parameters::Output                                      output;
      std::string                                             title;
      std::unique_ptr<elements::ImplicitElements>             elements;
      std::unique_ptr<time_integration::KinematicConstraints> constraints;
      std::unique_ptr<SurfaceLoads>                           surface_loads;
      /** Gravity, ramped over the load path (null without gravity). */
      std::unique_ptr<GravityLoad> gravity_load;
      /** The rigid surfaces' bodies, contacts and their contributions. */
      std::vector<RigidBody>                                      bodies;
      std::vector<std::unique_ptr<contact::RigidSurfaceContact>> contacts;
      std::vector<std::unique_ptr<contact::RigidSurfaceForces>>  contact_forces;
      /** The mortar contact pairs (Contact pairs), in the model's order. */
      std::vector<std::unique_ptr<contact::MortarContactPair>>   contact_pairs;
      std::unique_ptr<postprocess::HistoryNodes>              history_nodes;
      std::unique_ptr<time_integration::QuasiStaticSolver>    newton;
      /** The plugins that write time_history.csv (add_postprocessors()). */
      std::vector<std::unique_ptr<postprocess::Postprocessor>> postprocessors;
      /** Pseudo-time of the next history row (write_history_row()). */
      double next_row = 0.;
      /** Boundary condition and direction of each constraint group. */
      std::vector<unsigned int> condition_of_group, direction_of_group;
      /** The constraint groups holding a rigid part in one direction. */
      std::vector<postprocess::LoadPathBodyColumns::HeldPartGroup>
        held_part_groups;
      /**
       * The rigid parts in equilibrium (Quasi-static motion =
       * equilibrium, with a free direction), in the solver's order, and
       * the part of each.
       */
      std::vector<unsigned int> equilibrium_parts;
      /** The body (in `bodies`) of each rigid surface. */
      std::vector<unsigned int> surface_body;
      /** Boundary condition of each of the surface loads. */
      std::vector<unsigned int> condition_of_load;
      /** How each pretension section is loaded, and its cut elements. */
      std::vector<time_integration::PretensionLoad> pretension_loads;
      std::vector<unsigned int>                     cut_elements;
    };
  } // namespace simulation
} // namespace rubberdyn

#endif
