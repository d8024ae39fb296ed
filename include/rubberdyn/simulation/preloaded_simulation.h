#ifndef rubberdyn_simulation_preloaded_simulation_h
#define rubberdyn_simulation_preloaded_simulation_h

#include <rubberdyn/parameters/output_parameters.h>
#include <rubberdyn/parameters/time_integration_parameters.h>

#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

namespace rubberdyn
{
  namespace model
  {
    class Model;
  } // namespace model

  namespace simulation
  {
    using namespace dealii;
    /* The model layer's names, used here unqualified. */
    using model::Model;

    class ExplicitSimulation;
    class QuasiStaticSimulation;

    /**
     * `Time integration/Scheme = quasi-static then explicit`: the preload on
     * the quasi-static load path (simulation::QuasiStaticSimulation, its
     * time_history.csv in `<Output directory>/preload/`), its converged
     * state kept as the preload checkpoint `<Output directory>/preload/
     * checkpoint/` (simulation::write_preload()), then the explicit run
     * (simulation::ExplicitSimulation, `<Output directory>/time_history.csv`)
     * from that state: displacement, material history and locked
     * pretension sections, zero velocity except the parts' initial
     * velocities. The explicit element force is the quasi-static
     * residual's, so the handed-over state is in equilibrium to the Newton
     * tolerance and the explicit run starts quietly.
     *
     * With `Output/Restart from checkpoint = true` the quasi-static part is
     * skipped and the explicit run starts from the preload checkpoint in
     * the output directory, if the model's preload entries are the same
     * (simulation::preload_parameters_text()): several impact runs (another end
     * time, initial velocity, density) share one preload. If the explicit
     * run has written a checkpoint of its own (`Output/Checkpoint
     * interval`, in `<Output directory>/checkpoint/`), a restart continues
     * from that instead, exactly as the run would have gone on; delete it
     * to start again from the preload.
     *
     * The same boundary conditions act in both runs, with t the pseudo-time
     * of the load path in the first and the time (ms) in the second. A
     * displacement, traction or pressure whose value at the end of the
     * load path, t = T (the Quasi-static end time), differs from its value
     * at t = 0 (at a vertex or the centre of one of its faces) is a
     * preload: ramped on the load path as its function says, then held at
     * its value at t = T for the whole explicit run (a displacement with
     * zero velocity, a constant load), as a crash code holds a preload
     * after its dynamic relaxation. Any other condition is one function of
     * both runs, which the explicit run evaluates at its own t (e.g. a
     * motion that is zero on the load path, 0 <= t <= T, and starts after
     * t = T ms). doc/quasi_static.md, "The hand-off".
     */
    class PreloadedSimulation
    {
    public:
      /**
       * Set both runs up (nothing is written yet).
       *
       * The preloads' functions in @p model become their held values
       * (hold_preloads()) once the load path is set up: from then on the
       * model's conditions are the explicit run's.
       *
       * @param model_parameters ExplicitSimulation::model_parameters_text().
       * @throws InputError naming the entry: what either scheme cannot run.
       */
      PreloadedSimulation(Model                             &model,
                          const parameters::TimeIntegration &time_integration,
                          const parameters::Output          &output,
                          const std::string                 &title,
                          const std::string                 &model_parameters);

      ~PreloadedSimulation();

      /** Log both models without running: `--check`. */
      void
      check(std::ostream &log);

      /**
       * Preload (or read the preload checkpoint), write it, run the
       * explicit part.
       */
      void
      run(std::ostream &log);

    private:
      /**
       * Find the preloads of @p model: the displacement, traction and
       * pressure conditions with a function whose value at t = @p end_time
       * (the Quasi-static end time) differs from its value at t = 0, by
       * more than 1e-12 relative, at a vertex or the centre of one of
       * their faces on any rank. Replace each function f(X, t) of these by
       * f(X, @p end_time) for every t: held. Returns their indices in
       * `model.boundary_conditions`. Collective.
       */
      static std::vector<unsigned int>
      hold_preloads(Model &model, const double end_time);

      /** One log line per held preload (rank 0). */
      void
      log_held_conditions(std::ostream &log) const;

      Model                                 &model;
      parameters::Output                     output;
      std::string                            preload_parameters;
      std::string                            checkpoint_directory;
      /** The Quasi-static end time: the load path's t at the hand-off. */
      double                                 end_time;
      /** The preloads (hold_preloads()), by condition index. */
      std::vector<unsigned int>              held_conditions;
      /** Whether the explicit run continues from its own checkpoint. */
      bool                                   continues = false;
      std::unique_ptr<QuasiStaticSimulation> quasi_static;
      std::unique_ptr<ExplicitSimulation>    explicit_run;
    };
  } // namespace simulation
} // namespace rubberdyn

#endif
