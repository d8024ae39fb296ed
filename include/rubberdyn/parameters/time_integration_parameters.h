#ifndef rubberdyn_parameters_time_integration_parameters_h
#define rubberdyn_parameters_time_integration_parameters_h

#include <string>

namespace dealii
{
  class ParameterHandler;
}

namespace rubberdyn
{
  /**
   * Parameter groups shared by several studies. Each is one struct per
   * subsection with declare_parameters() and parse_parameters() side by
   * side (step-44's Parameters namespace): the study registry declares
   * every group once, and every study that needs a group parses it with
   * the same code, so that an entry's name, default and documentation are
   * written once.
   */
  namespace parameters
  {
    /**
     * The `Time integration` subsection: the central-difference scheme's
     * step control, mass scaling, bulk viscosity and the F-bar
     * stabilisation.
     */
    struct TimeIntegration
    {
      /**
       * The most time steps a run may take: End time divided by the first
       * stable step (the smallest element step of the reference
       * configuration, with mass scaling, times the scale factor) must not
       * exceed it. It refuses an absurd End time (1e308 ms would run
       * forever) before anything runs, in `--check` too; the largest
       * shipped runs take about 5e4 steps, and 1e9 steps of even an 80-cell
       * model take days.
       */
      static constexpr double max_time_steps = 1e9;

      /** `Scheme`: only "explicit" for now. */
      std::string scheme = "explicit";
      /** Simulated time (ms). */
      double end_time = 30.;
      /** Factor on the stable step (-). */
      double time_step_scale = 0.9;
      /** The run stops below this step (ms). */
      double minimum_time_step = 1e-7;
      /** Mass scaling target step (ms); 0: off. */
      double mass_scaling_time_step = 0.;
      /** Bulk viscosity coefficients (-), LS-DYNA's Q2 and Q1. */
      double bulk_viscosity_linear = 0.06, bulk_viscosity_quadratic = 1.5;
      /** F-bar volumetric stabilisation beta (-). */
      double fbar_stabilization = 0.;

      /** Declare the entries in subsection `Time integration`. */
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      /**
       * Read them back (from the top level of @p prm).
       *
       * @throws InputError naming the entry if a value is out of range, or
       *   if the Mass scaling time step is larger than the End time.
       */
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };
  } // namespace parameters
} // namespace rubberdyn

#endif
