#ifndef rubberdyn_simulation_preloaded_simulation_h
#define rubberdyn_simulation_preloaded_simulation_h

#include <rubberdyn/parameters/output_parameters.h>
#include <rubberdyn/parameters/time_integration_parameters.h>

#include <iosfwd>
#include <memory>
#include <string>

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
     * of the load path in the first and the time (ms) in the second: a
     * displacement, traction or pressure must have the same value at the
     * end of the load path and at t = 0 (checked at the faces' centres).
     */
    class PreloadedSimulation
    {
    public:
      /**
       * Set both runs up (nothing is written yet).
       *
       * @param model_parameters ExplicitSimulation::model_parameters_text().
       * @throws InputError naming the entry: what either scheme cannot run,
       *   a condition that differs between the end of the load path and
       *   t = 0.
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
       * Refuse a displacement, traction or pressure condition whose
       * functions differ between t = @p end_time and t = 0 at the centre of
       * one of its faces.
       */
      static void
      check_continuity(const Model &model, const double end_time);

      Model                                 &model;
      parameters::Output                     output;
      std::string                            preload_parameters;
      std::string                            checkpoint_directory;
      /** Whether the explicit run continues from its own checkpoint. */
      bool                                   continues = false;
      std::unique_ptr<QuasiStaticSimulation> quasi_static;
      std::unique_ptr<ExplicitSimulation>    explicit_run;
    };
  } // namespace simulation
} // namespace rubberdyn

#endif
