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
     * The `Time integration/Quasi-static` subsection: load stepping, Newton
     * tolerances and the linear solver of the quasi-static scheme
     * (time_integration::QuasiStaticSolver, doc/quasi_static.md). Times are
     * in the pseudo-time t of the boundary-condition functions, which runs
     * from 0 to the Quasi-static end time.
     */
    struct QuasiStatic
    {
      /** The linear solver of each Newton iteration. */
      enum class LinearSolver
      {
        /** direct below direct_solver_limit dofs, AMG above. */
        automatic,
        /** Trilinos Amesos sparse LU (MUMPS or KLU: direct_solver). */
        direct,
        /** CG or GMRES with Trilinos ML AMG (six rigid-body modes). */
        amg
      };
      /** Pseudo-time of the first load step. */
      double initial_step = 0.1;
      /** Smallest load step before the run gives up. */
      double minimum_step = 1e-4;
      /** Largest load step (the growth after easy steps stops there). */
      double maximum_step = 0.1;
      /** Newton iterations allowed per load step. */
      unsigned int max_iterations = 15;
      /** Cut-backs (halvings) allowed in a row before the run gives up. */
      unsigned int max_cutbacks = 10;
      /**
       * ||residual of the free dofs|| <= this * max(||reactions||,
       * ||loads||) (-), or <= the residual's round-off (kN,
       * time_integration::QuasiStaticSolver::set_roundoff_floor()).
       */
      double residual_tolerance = 1e-8;
      /** |du . r| <= this * the step's first |du . r|. */
      double energy_tolerance = 1e-14;
      /**
       * Residual norm (kN) always counted as converged (an unloaded
       * model), the energy criterion waived.
       */
      double residual_floor = 1e-12;
      /** Whether Newton updates are damped by a backtracking line search. */
      bool         line_search   = true;
      LinearSolver linear_solver = LinearSolver::automatic;
      /** automatic: the direct solver up to this many dofs. */
      unsigned int direct_solver_limit = 20000;
      /**
       * The direct solver's Amesos package: "Amesos_Mumps" (multifrontal,
       * nested-dissection ordering, distributed) or "Amesos_Klu" (serial
       * left-looking LU: fine in 2D, slow in 3D).
       */
      std::string direct_solver = "Amesos_Mumps";
      /** Relative residual tolerance of the iterative solver. */
      double linear_tolerance = 1e-10;
    };

    /**
     * The `Time integration` subsection: the scheme; the central-difference
     * scheme's step control, mass scaling, bulk viscosity and the F-bar
     * stabilisation; the quasi-static scheme's end time and Newton settings.
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

      /**
       * `Scheme`: "explicit", "quasi-static" or "quasi-static then
       * explicit" (refused for now by the Model study).
       */
      std::string scheme = "explicit";
      /** Pseudo-time at the end of the quasi-static run (-). */
      double quasi_static_end_time = 1.;
      /** The quasi-static scheme's settings. */
      QuasiStatic quasi_static;
      /** Simulated time (ms). */
      double end_time = 30.;
      /** Factor on the stable step (-). */
      double time_step_scale = 0.9;
      /** The run stops below this step (ms). */
      double minimum_time_step = 1e-7;
      /** Mass scaling target step (ms); 0: off. */
      double mass_scaling_time_step = 0.;
      /**
       * Target step of selective mass scaling (ms) for the parts without
       * their own; 0: none.
       */
      double selective_mass_scaling_time_step = 0.;
      /** Relative residual of selective mass scaling's solve (-). */
      double selective_mass_scaling_tolerance = 1e-4;
      /** Bulk viscosity coefficients (-), LS-DYNA's Q2 and Q1. */
      double bulk_viscosity_linear = 0.06, bulk_viscosity_quadratic = 1.5;
      /** F-bar volumetric stabilisation beta (-). */
      double fbar_stabilization = 0.;
      /**
       * `Stable time step estimate`: false for "element" (the element
       * bound, doc/theory.md section 8.3), true for "assembled" (the
       * assembled model's largest frequency by Lanczos steps,
       * time_integration::AssembledStepEstimate).
       */
      bool assembled_step_estimate = false;
      /** Steps between two assembled estimates (-). */
      unsigned int stable_step_refresh_interval = 100;

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

      /**
       * Refuse a target time @p step (ms) of the entry @p entry that is
       * longer than the End time: no time step, and arbitrarily much mass
       * to take it (1e308 ms overflows the added mass to infinity). For the
       * model-wide targets here and the parts' own.
       *
       * @throws InputError naming @p entry.
       */
      void
      require_step_within_run(const std::string &entry,
                              const double       step) const;
    };
  } // namespace parameters
} // namespace rubberdyn

#endif
