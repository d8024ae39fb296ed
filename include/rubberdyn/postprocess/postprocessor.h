#ifndef rubberdyn_postprocess_postprocessor_h
#define rubberdyn_postprocess_postprocessor_h

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
    class SolidHexElements;
  }

  namespace postprocess
  {
    /**
     * What a postprocessor sees of a running simulation: the model, the
     * solver that advances it (state, energies, reactions, bodies) and the
     * elements (for stresses).
     */
    struct SimulationView
    {
      const model::Model &                     model;
      const time_integration::ExplicitSolver &solver;
      const elements::SolidHexElements &       elements;
      /** The rigid bodies, in the order of the model's rigid surfaces. */
      const std::vector<model::RigidBody> &    bodies;
    };

    /** One entry of run_summary.json: a key and its JSON value as text. */
    using SummaryEntry = std::pair<std::string, std::string>;

    /**
     * A plugin that watches a run (ASPECT's postprocessors): it may add
     * columns to time_history.csv, look at every step, write files at
     * output times, add entries to run_summary.json and ask the run to
     * stop. Whatever it accumulates over the run (maxima, times, its next
     * output time) is its own checkpoint state, so that a restarted run
     * continues it exactly.
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
