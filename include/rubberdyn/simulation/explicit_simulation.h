#ifndef rubberdyn_simulation_explicit_simulation_h
#define rubberdyn_simulation_explicit_simulation_h

#include <rubberdyn/model/force_contribution.h>
#include <rubberdyn/model/model.h>
#include <rubberdyn/simulation/preload.h>
#include <rubberdyn/parameters/contact_parameters.h>
#include <rubberdyn/parameters/output_parameters.h>
#include <rubberdyn/parameters/time_integration_parameters.h>
#include <rubberdyn/postprocess/postprocessor.h>
#include <rubberdyn/time_integration/explicit_solver.h>
#include <rubberdyn/time_integration/selective_mass_scaling.h>

#include <chrono>
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

namespace rubberdyn
{
  namespace elements
  {
    class SolidHexElements;
    class SolidHexForces;
  } // namespace elements
  namespace contact
  {
    class RigidSurfaceContact;
    class RigidSurfaceForces;
    class MortarContactPair;
  } // namespace contact
  namespace time_integration
  {
    class ExplicitSolver;
    class KinematicConstraints;
  } // namespace time_integration

  namespace postprocess
  {
    class TimeHistory;
    class HistoryExpressions;
    class FieldOutputWriter;
  } // namespace postprocess

  namespace model
  {
    class SurfaceLoads;
  } // namespace model

  namespace simulation
  {
    using namespace dealii;
    /* The model layer's names, used here unqualified. */
    using model::Model;
    using model::RigidBody;
    using model::ForceContribution;
    using model::SurfaceLoads;

    /**
     * The one engine path of explicit dynamics: takes any Model and runs
     * it. It builds the force contributions (elements with mass scaling,
     * one rigid-surface contact per rigid surface, one SurfaceLoads for all
     * pressure and traction conditions), the kinematic
     * constraints of the boundary conditions and the central-difference
     * solver, then advances in time while the postprocessors watch, writing
     * time_history.csv (time, time_step and the plugins' columns), the
     * checkpoints and run_summary.json. Studies (Model, Drop test) only
     * build the Model and choose the postprocessors.
     */
    class ExplicitSimulation
    {
    public:
      /**
       * Set everything up (nothing is written yet).
       *
       * @param title First word of the log's first line (e.g. "Drop test").
       * @param model_parameters The parameters that define the model, as
       *   text: a restart must find the same in its checkpoint.
       */
      ExplicitSimulation(Model &                             model,
                         const parameters::TimeIntegration &time_integration,
                         const parameters::Output &          output,
                         const std::string &                 title,
                         const std::string &                 model_parameters);

      ~ExplicitSimulation();

      /**
       * Add the Model study's columns: energies (with friction work), the
       * reactions of every boundary condition, the sums of every part and
       * the motion of every rigid surface.
       */
      void
      add_standard_postprocessors();

      /** Add a postprocessor; history columns follow the order of adding. */
      void
      add_postprocessor(std::unique_ptr<postprocess::Postprocessor> plugin);

      /**
       * Log the model (cells, dofs, ranks, the parts' constants, masses)
       * and the first stable time step, without running: `--check`.
       */
      void
      check(std::ostream &log);

      /**
       * Run to the end time (or until a postprocessor asks to stop).
       *
       * @throws std::runtime_error if the solver fails, after writing the
       *   last state.
       */
      void
      run(std::ostream &log);

      /**
       * Start from a preloaded state (before run()): its displacement, the
       * elements' history and the pretension sections' shortenings (held
       * for the whole run), with zero velocity apart from the parts'
       * initial velocities.
       */
      void
      start_from(const PreloadState &state);

      /**
       * Read the preload checkpoint in @p directory for this model
       * (simulation::read_preload() with the elements' sizes).
       */
      PreloadState
      read_preload(const std::string &directory,
                   const std::string &parameters) const;

      /**
       * The directory of the newest checkpoint that write_checkpoint() has
       * left in @p output_directory: checkpoint/, or checkpoint.old/ when a
       * run was killed between write_checkpoint()'s two renames (then the
       * previous checkpoint is complete under the old name). The one place
       * that knows this layout: the restart, the hand-off's decision whether
       * the impact continues, and the messages naming the checkpoint use it.
       */
      static std::string
      checkpoint_directory_of(const std::string &output_directory);

      /**
       * Whether an explicit run has left a checkpoint in @p
       * output_directory (checkpoint_directory_of() exists), complete or
       * not: a restart then reads it, and read_checkpoint_header() refuses
       * an incomplete one instead of starting over, which would overwrite
       * it. A run killed before its first checkpoint was complete leaves
       * only checkpoint.new/, which does not count. Not collective: the
       * caller decides which rank looks.
       */
      static bool
      has_checkpoint(const std::string &output_directory);

      /**
       * A sentence added to the refusal of a restart whose model differs
       * from its checkpoint's, saying how to start instead (a hand-off: from
       * the preload).
       */
      void
      set_restart_advice(const std::string &advice)
      {
        restart_advice = advice;
      }

      /** The solver (after construction). */
      const time_integration::ExplicitSolver &
      solver() const;

      /**
       * The rigid bodies: those of the rigid surfaces that have their own,
       * then one per rigid part (with its mass, centre and inertia).
       */
      const std::vector<RigidBody> &
      rigid_bodies() const
      {
        return bodies;
      }

      /**
       * The text of the model parameters of a ParameterHandler: every entry
       * except `Time integration/End time` and the `Output` subsection, one
       * per line (for the restart check).
       */
      static std::string
      model_parameters_text(const dealii::ParameterHandler &prm);

    private:
      /**
       * The elements: one group per part (its law and formulation), cut by
       * the pretension sections (locked: their shortenings come with the
       * preload, start_from()); every cross section must cut one.
       */
      void
      build_elements();

      /**
       * Mass scaling: the density factor of every element, (target step /
       * stable step)^2 where its stable step is below `Time integration/
       * Mass scaling time step`, else 1 (collective).
       *
       * @throws InputError naming the Mass scaling time step if the largest
       *   factor is not a usable number.
       */
      std::vector<double>
      mass_scaling_factors() const;

      /**
       * Refuse, before anything runs (also in `--check`), a Minimum time
       * step above the first stable step and an End time that would take
       * more than parameters::TimeIntegration::max_time_steps steps.
       */
      void
      check_number_of_steps() const;

      /** added_mass_by_part from the density factors (all ranks). */
      void
      set_added_mass(const std::vector<double> &density_scaling);

      /**
       * One model::RigidPartMass for the cells of all rigid parts (from
       * @p mass_of_part), appended to @p contributions; none without rigid
       * parts.
       */
      void
      add_rigid_part_mass(
        const std::vector<VectorType>           &mass_of_part,
        std::vector<model::ForceContribution *> &contributions);

      /**
       * The bodies: those of the rigid surfaces that have their own, in
       * their order, then one per rigid part (its free directions and
       * initial velocity; mass, centre and inertia come in
       * attach_rigid_parts()); sets body_of_part.
       */
      void
      build_bodies();

      /** The body (in `bodies`) that carries each rigid surface. */
      std::vector<unsigned int>
      body_of_surface() const;

      /**
       * The central-difference solver over @p contributions, the
       * constraints and the bodies, with the parts' masses for its sums per
       * part.
       */
      void
      build_solver(
        const std::vector<model::ForceContribution *> &contributions,
        const std::vector<VectorType>                 &mass_of_part);

      /**
       * The parts' initial velocities (a node shared by two parts takes
       * the velocity of the later one).
       */
      void
      set_initial_velocities();

      /**
       * The rigid parts' nodes follow their bodies, whose mass, centre and
       * inertia are set here from the solver's lumped mass.
       *
       * @throws InputError naming the boundary condition that holds a node
       *   of a rigid part (it would fight the body).
       */
      void
      attach_rigid_parts(const std::vector<VectorType> &mass_of_part);

      /**
       * The smallest stable step of the elements in the reference
       * configuration, with the mass scaling's added density, before the
       * scale factor (ms, the same on all ranks; collective). The largest
       * double if there are no deformable elements.
       */
      double
      smallest_element_time_step() const;

      /** Log the model's header lines. */
      void
      log_model(std::ostream &log) const;

      /**
       * time_history.svg beside time_history.csv: the energies, the forces
       * (columns ending in _force, _force_x/_y/_z) and the displacements
       * against time (rank 0).
       */
      void
      write_history_plot(const std::vector<std::string> &columns) const;

      /** The clock and the testing aid of a run (run()'s steps). */
      struct RunProgress
      {
        /** When run() started, and when it last wrote a progress line. */
        std::chrono::steady_clock::time_point wall_start, last_line;
        /** The time this run starts from (a restart's: its checkpoint's). */
        double first_time = 0.;
        /** RunOptions::simulate_crash_at. */
        double crash_time = 0.;
      };

      /**
       * A restart's first step (Output/Restart from checkpoint): read and
       * check the checkpoint's study.txt (read_checkpoint_header()).
       * Returns the number of history rows stored with it and the number
       * of this restart (0, 0 without a restart). Collective.
       */
      std::pair<unsigned long, unsigned int>
      begin_restart();

      /**
       * Put the ParaView output (postprocess::FieldOutputWriter, with the
       * contact pairs' pressure, gap and slip) first among the plugins: a
       * restart writes a series of its own, named after @p restarts.
       */
      void
      add_field_writer(const unsigned int restarts);

      /**
       * The columns of time_history.csv: time, time_step, the plugins'
       * and those of Output/History expressions (sets expressions).
       */
      std::vector<std::string>
      history_columns();

      /**
       * Open time_history.csv: a new one, or for a restart, after reading
       * every rank's checkpoint state (read_checkpoint_state()), the file
       * cut to the @p history_rows rows written before the checkpoint.
       */
      void
      open_history(const std::vector<std::string> &columns,
                   const unsigned long             history_rows,
                   std::ostream                   &log);

      /**
       * Write the row of the current state (collective: plugins sum over
       * the ranks), echoed to @p log with Output/Echo history.
       */
      void
      write_history_row(const postprocess::SimulationView &view,
                        std::ostream                      &log);

      /** Add the solver's energy error now to the run's records. */
      void
      record_energy_errors();

      /**
       * What ExplicitSolver::monitor_end_state() calls once at the end
       * time: the energy-error records, the last history row (unless the
       * interval wrote it), the plugins' after_step().
       */
      void
      monitor_end_state(const postprocess::SimulationView &view,
                        std::ostream                      &log);

      /**
       * What the solver calls after every step: the energy-error records,
       * a history row when due, the plugins' after_step(), a stop asked by
       * a plugin (throws StopRequested after the last row), the progress
       * line.
       */
      void
      monitor_step(const postprocess::SimulationView &view,
                   RunProgress                       &progress,
                   std::ostream                      &log);

      /**
       * Run the solver to the End time, in segments that end at the
       * checkpoint times, writing the checkpoints. Returns whether a
       * postprocessor stopped the run.
       *
       * @throws std::runtime_error if the solver fails, after writing the
       *   last state.
       */
      bool
      advance_to_end(const postprocess::SimulationView &view,
                     RunProgress                       &progress,
                     const unsigned int                 restarts,
                     std::ostream                      &log);

      /**
       * The run's own entries of run_summary.json (sizes, steps, wall time
       * and cost per element-cycle, energy errors, masses, initial
       * penetrations); the plugins' follow. Collective.
       */
      std::vector<postprocess::SummaryEntry>
      summary_entries(const bool          stopped,
                      const unsigned long first_step,
                      const double        wall) const;

      /** The end of the log: "Finished:", the plugins' lines, warnings. */
      void
      log_finish(std::ostream &log) const;

      /** Write a checkpoint of the current state (collective). */
      void
      write_checkpoint(const unsigned long history_rows,
                       const unsigned int  restarts);

      /**
       * Read and check study.txt of the checkpoint in the output directory
       * (model parameters, ranks); returns the number of history rows and
       * of restarts stored with it.
       */
      std::pair<unsigned long, unsigned int>
      read_checkpoint_header();

      /**
       * Load every rank's piece of the checkpoint (collective) and check
       * that all belong to the step study.txt names.
       */
      void
      read_checkpoint_state();

      Model &                             model;
      parameters::TimeIntegration         time_integration;
      parameters::Output                  output;
      std::string                         title;
      std::string                         model_parameters;
      /** set_restart_advice(). */
      std::string                                                restart_advice;
      std::unique_ptr<elements::SolidHexElements> elements;
      std::unique_ptr<elements::SolidHexForces>   element_forces;
      std::vector<std::unique_ptr<contact::RigidSurfaceContact>> contacts;
      std::vector<std::unique_ptr<contact::RigidSurfaceForces>>  contact_forces;
      /** One per `Contact pairs` entry of the model, in its order. */
      std::vector<std::unique_ptr<contact::MortarContactPair>>   contact_pairs;
      std::vector<RigidBody>                                     bodies;
      /** The lumped mass of the rigid parts' cells, or nullptr. */
      std::unique_ptr<ForceContribution> rigid_part_mass;
      /** Index among `bodies` of each part's body (rigid parts only). */
      std::vector<unsigned int> body_of_part;
      std::unique_ptr<time_integration::KinematicConstraints>    constraints;
      std::unique_ptr<time_integration::ExplicitSolver>          explicit_solver;
      std::vector<std::unique_ptr<postprocess::Postprocessor>>   postprocessors;
      /** The pressure and traction conditions, or nullptr if none. */
      std::unique_ptr<SurfaceLoads> surface_loads;
      /** Index of the boundary condition of each load of surface_loads. */
      std::vector<unsigned int> condition_of_load;
      /** Boundary condition and direction of each constraint group. */
      std::vector<unsigned int> condition_of_group, direction_of_group;
      /** Added mass of mass scaling per part (kg, all ranks). */
      std::vector<double> added_mass_by_part;
      /** What selective mass scaling did to each part. */
      std::vector<time_integration::PartMassScaling> mass_scaling_parts;
      /** time_history.csv (rows on rank 0). */
      std::unique_ptr<postprocess::TimeHistory> history;
      /** Output/History expressions, or nullptr (history_columns()). */
      std::unique_ptr<postprocess::HistoryExpressions> expressions;
      /** The ParaView output among the postprocessors (run()). */
      postprocess::FieldOutputWriter *field_writer = nullptr;
      /** Time of the last history row (ms; -1 before the first). */
      double last_row_time = -1.;
      /** Next history row and checkpoint times (ms). */
      double next_history = 0., next_checkpoint = 0.;
      /**
       * Largest absolute energy error so far (J); at the end of run(),
       * divided by the run's largest energy.
       */
      double max_energy_error = 0.;
      /**
       * The errors against the energy through the deformable parts; at
       * the end its value with the floor 1 % of the run's largest energy
       * (what the 1 % criterion judges) goes to max_deformable_error.
       */
      time_integration::DeformableErrorRecord deformable_errors;
      double                                  max_deformable_error = 0.;
      /** The checkpoint being read: its folder, step and time. */
      std::string   checkpoint_directory;
      unsigned long checkpoint_step = 0;
      double        checkpoint_time = 0.;
    };
  } // namespace simulation
} // namespace rubberdyn

#endif
