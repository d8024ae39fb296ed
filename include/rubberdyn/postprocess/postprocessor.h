#ifndef rubberdyn_postprocess_postprocessor_h
#define rubberdyn_postprocess_postprocessor_h

#include <deal.II/base/tensor.h>

#include <rubberdyn/base/vector.h>

#include <iosfwd>
#include <string>
#include <utility>
#include <vector>

namespace rubberdyn
{
  namespace model
  {
    class Model;
    struct RigidBody;
  }
  namespace time_integration
  {
    class ExplicitSolver;
  }
  namespace elements
  {
    class ImplicitElements;
  }

  namespace postprocess
  {
    /**
     * What a postprocessor sees of a running simulation, whatever its
     * scheme (explicit dynamics, a quasi-static load path): the model, the
     * time, the displacement, the reactions of the kinematic constraints,
     * the internal energy, the pretension sections, the rigid bodies and
     * the elements. A column that reads only these means the same in both
     * schemes (postprocess::ReactionAndLoadColumns, PretensionSectionColumns,
     * HistoryNodeColumns, ContactPairColumns, InternalEnergyColumns).
     *
     * What only explicit dynamics has (velocities, kinetic energy, the
     * works and momenta, added mass, the time step) comes through
     * explicit_solver(), which is nullptr in a quasi-static run: a plugin
     * that reads it (EnergyColumns, PartColumns, RigidBodyColumns,
     * InteractionEnergyColumns, FieldOutputWriter, DropTestMonitor) is an
     * explicit-only plugin and says so through explicit_solver_of().
     *
     * The simulations implement it over their solvers
     * (simulation::ExplicitView, simulation::QuasiStaticView); a plugin never
     * sees the simulation that made it.
     */
    class SimulationView
    {
    public:
      virtual ~SimulationView() = default;

      /** The model that runs. */
      virtual const model::Model &
      model() const = 0;

      /** Time of the current state (ms; the pseudo-time of a load path). */
      virtual double
      time() const = 0;

      /** Displacement of the current state (ghosted, mm). */
      virtual const VectorType &
      displacement() const = 0;

      /**
       * Reaction of every constraint group (kN, summed over the ranks): the
       * force the constraint exerts on the solid in its direction.
       */
      virtual const std::vector<double> &
      reactions() const = 0;

      /**
       * Moment of each group's reactions about its moment point (kN mm,
       * with the nodes' current positions).
       */
      virtual const std::vector<dealii::Tensor<1, 3>> &
      reaction_moments() const = 0;

      /** Stored energy of the elements (J, summed over the ranks). */
      virtual double
      internal_energy() const = 0;

      /** The same per element group, i.e. per part (J). */
      virtual const std::vector<double> &
      internal_energy_by_group() const = 0;

      /**
       * Axial force through each pretension section (kN, tension positive,
       * summed over the ranks; collective).
       */
      virtual std::vector<double>
      section_forces() const = 0;

      /** Shortening of each pretension section (mm). */
      virtual const std::vector<double> &
      section_shortenings() const = 0;

      /** The rigid bodies, in the scheme's order (of its solver). */
      virtual const std::vector<model::RigidBody> &
      bodies() const = 0;

      /** The elements (stresses for the field output). */
      virtual const elements::ImplicitElements &
      elements() const = 0;

      /**
       * The explicit solver, for the quantities only explicit dynamics has;
       * nullptr in a quasi-static run.
       */
      virtual const time_integration::ExplicitSolver *
      explicit_solver() const
      {
        return nullptr;
      }
    };

    /**
     * The explicit solver of @p view, for an explicit-only plugin named
     * @p plugin.
     *
     * @throws std::logic_error naming @p plugin if the run is not explicit
     *   (a simulation gave an explicit-only plugin to another scheme).
     */
    const time_integration::ExplicitSolver &
    explicit_solver_of(const SimulationView &view, const std::string &plugin);


    /** One entry of run_summary.json: a key and its JSON value as text. */
    using SummaryEntry = std::pair<std::string, std::string>;

    /**
     * A plugin that watches a run (ASPECT's postprocessors): it may add
     * columns to time_history.csv, look at every step, write files at
     * output times, add entries to run_summary.json and ask the run to
     * stop. Whatever it accumulates over the run (maxima, times, its next
     * output time) is its own checkpoint state, so that a restarted run
     * continues it exactly.
     *
     * An explicit run calls all of these; a quasi-static run calls
     * history_columns(), history_values() (at its rows' converged states),
     * after_step() (after every converged load step) and finish(): its
     * run_summary.json and log are its own, and it has no checkpoints.
     */
    class Postprocessor
    {
    public:
      virtual ~Postprocessor() = default;

      /** A name for checkpoints and messages. */
      virtual std::string
      name() const = 0;

      /** The columns this plugin adds to time_history.csv, in order. */
      virtual std::vector<std::string>
      history_columns() const
      {
        return {};
      }

      /**
       * Append the values of history_columns() at the current time.
       * Called on all ranks at every history row (may be collective);
       * only rank 0's values are written.
       */
      virtual void
      history_values(const SimulationView &view, std::vector<double> &values)
      {
        (void)view;
        (void)values;
      }

      /**
       * After every step, on all ranks (no collectives: cheap bookkeeping,
       * or work on the plugin's own output times, which are the same on
       * every rank).
       */
      virtual void
      after_step(const SimulationView &view)
      {
        (void)view;
      }

      /** At the end of the run (collective). */
      virtual void
      finish(const SimulationView &view)
      {
        (void)view;
      }

      /** Whether the run should end now (same answer on every rank). */
      virtual bool
      stop_requested() const
      {
        return false;
      }

      /** Entries for run_summary.json (called on all ranks). */
      virtual void
      summary(const SimulationView &view, std::vector<SummaryEntry> &entries)
      {
        (void)view;
        (void)entries;
      }

      /** Lines for the end of the log (rank 0). */
      virtual void
      final_log(std::ostream &log) const
      {
        (void)log;
      }

      /** Write the plugin's state for a checkpoint. */
      virtual void
      save(std::ostream &out) const
      {
        (void)out;
      }

      /** Read what save() wrote. */
      virtual void
      load(std::istream &in)
      {
        (void)in;
      }
    };
  } // namespace postprocess
} // namespace rubberdyn

#endif
