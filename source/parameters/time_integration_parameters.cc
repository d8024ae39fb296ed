#include <deal.II/base/parameter_handler.h>

#include <rubberdyn/base/exceptions.h>
#include <rubberdyn/base/parameter_tools.h>
#include <rubberdyn/parameters/time_integration_parameters.h>

namespace rubberdyn
{
  namespace parameters
  {
    using namespace dealii;

    void
    TimeIntegration::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Time integration");
      prm.declare_entry(
        "Scheme", "explicit",
        Patterns::Selection("explicit|quasi-static|quasi-static then explicit"),
        "Time integration scheme. 'explicit': central differences with "
        "lumped mass (reference study eqs. 2.7-2.10), to the End time (ms). "
        "'quasi-static': static equilibrium by Newton-Raphson (no inertia), "
        "with the boundary-condition functions of t as load paths, t running "
        "from 0 to the Quasi-static end time (doc/quasi_static.md). "
        "'quasi-static then explicit': the load path first (a bolt "
        "preload), then the explicit run to the End time from its "
        "converged state: displacements, material history, locked "
        "pretension sections and contact friction state, at rest but for "
        "the parts' initial velocities. A displacement, traction or "
        "pressure whose value at the Quasi-static end time differs from "
        "its value at t = 0 (a ramp) is a preload: held at its value at "
        "the Quasi-static end time in the explicit run; any other "
        "condition is evaluated at the explicit run's t "
        "(doc/quasi_static.md, \"The hand-off\").");
      prm.declare_entry("Quasi-static end time", "1", Patterns::Double(0.),
                        "Quasi-static scheme: the pseudo-time t at the end of "
                        "the load path (-; the t of the boundary-condition "
                        "functions, which then has no physical unit).");
      prm.declare_entry("End time", "30", Patterns::Double(0.),
                        "Simulated time (ms). At most 1e9 steps of the first "
                        "stable time step (the smallest element step, with "
                        "mass scaling, times the scale factor).");
      prm.declare_entry("Time step scale factor", "0.9",
                        Patterns::Double(0., 1.),
                        "Factor on the smallest stable element and contact "
                        "time step (reference study eq. 2.12).");
      prm.declare_entry("Minimum time step", "1e-7", Patterns::Double(0.),
                        "The run stops with an error if the time step falls "
                        "below this (ms). At most the first stable time step.");
      prm.declare_entry("Mass scaling time step", "0", Patterns::Double(0.),
                        "Target time step for mass scaling (ms): elements "
                        "whose stable step is smaller get added density; the "
                        "added mass is reported. 0 switches it off; at most "
                        "the End time.");
      prm.declare_entry(
        "Selective mass scaling time step", "0", Patterns::Double(0.),
        "Target time step of selective mass scaling (ms), for every "
        "deformable part without its own Parts/<name>/Selective mass scaling "
        "time step: elements whose stable step is smaller get mass on their "
        "deformation modes only (Olovsson, Simonsson & Unosson 2005; LS-DYNA "
        "IMSCL, OpenRadioss /DT/AMS), so that translation, total mass and "
        "momentum stay physical; each step then solves for the accelerations "
        "of their nodes (conjugate gradients). The added mass and the solve's "
        "iterations are reported per part (doc/theory.md, \"Selective mass "
        "scaling\"). 0 switches it off; at most the End time.");
      prm.declare_entry(
        "Selective mass scaling tolerance", "1e-4", Patterns::Double(0., 1.),
        "Relative residual of the accelerations' solve of selective mass "
        "scaling (-), in the norm of the inverse diagonal of the mass "
        "matrix; momentum is kept exactly whatever its value.");
      prm.declare_entry("Bulk viscosity linear", "0.06", Patterns::Double(0.),
                        "Linear bulk viscosity coefficient (-), LS-DYNA's Q2.");
      prm.declare_entry("Bulk viscosity quadratic", "1.5", Patterns::Double(0.),
                        "Quadratic bulk viscosity coefficient (-), LS-DYNA's "
                        "Q1.");
      prm.declare_entry("F-bar stabilization", "0", Patterns::Double(0., 1.),
                        "F-bar only: stiffness beta of the volumetric "
                        "stabilisation kappa/2 (r + 1/r - 2), r = J_q / J_0, "
                        "kappa = beta K (-): it resists Gauss-point volume "
                        "changes at a fixed element-centre volume, which F-bar "
                        "leaves to the shear stiffness alone (doc/theory.md "
                        "8.1). 0 switches it off.");
      prm.declare_entry(
        "Stable time step estimate", "element",
        Patterns::Selection("element|assembled"),
        "Explicit scheme: what sets the stable step before the scale "
        "factor. 'element': the element bound, the largest frequency of any "
        "element on its own, omega_e = 2 c / l_e (doc/theory.md 8.3): safe, "
        "and up to sqrt(3) times pessimistic inside a mesh of nearly "
        "incompressible hexahedra. 'assembled': the largest frequency of "
        "the assembled model, omega_max^2 the largest eigenvalue of "
        "M^-1 K (lumped mass, the elements' tangent at the current state), "
        "by Lanczos steps on finite differences of the elements' forces "
        "every Stable time step refresh interval steps, with the Ritz "
        "residual added as a margin (doc/theory.md 8.3, \"The assembled "
        "estimate\"); the step is 2/omega_max, never below the element "
        "bound's, combined with the contact springs as before. Costs a few "
        "element evaluations per refresh. Not with selective mass "
        "scaling.");
      prm.declare_entry(
        "Stable time step refresh interval", "100",
        Patterns::Integer(1, 1000000),
        "Stable time step estimate = assembled: steps between two "
        "estimates (-). In between, the estimate follows the element bound "
        "where that shrinks; each refresh costs about 3 to 40 element "
        "evaluations.");
      prm.enter_subsection("Quasi-static");
      {
        prm.declare_entry("Initial step", "0.1", Patterns::Double(0.),
                          "First load step (pseudo-time, -).");
        prm.declare_entry("Minimum step", "1e-4", Patterns::Double(0.),
                          "Smallest load step (pseudo-time, -): a step that "
                          "does not converge at this size ends the run with "
                          "an error.");
        prm.declare_entry("Maximum step", "0.1", Patterns::Double(0.),
                          "Largest load step (pseudo-time, -); steps grow "
                          "by 1.5 after a step that took at most 4 "
                          "iterations, up to this.");
        prm.declare_entry("Maximum iterations", "15", Patterns::Integer(1),
                          "Newton iterations per load step (-) before the "
                          "step is cut back (halved).");
        prm.declare_entry("Maximum cut-backs", "10", Patterns::Integer(0),
                          "Halvings of one load step in a row (-) before "
                          "the run ends with an error (which names this "
                          "limit, or the Minimum step, whichever was "
                          "hit).");
        prm.declare_entry("Residual tolerance", "1e-8", Patterns::Double(0.),
                          "Convergence: the norm of the out-of-balance "
                          "force on the free dofs (kN) at most this times "
                          "the larger of the norms of the reactions and of "
                          "the loads (-), or at most the residual's "
                          "round-off eps (K + 4G/3) h^2 sqrt(dofs) (kN, of "
                          "the stiffest deformable part: K + 4G/3 in GPa, "
                          "its mean element size h in mm; the log prints "
                          "it), which the relative demand falls below "
                          "where the reactions are nearly zero (a gap that "
                          "has just closed).");
        prm.declare_entry("Energy tolerance", "1e-14", Patterns::Double(0.),
                          "Convergence, also required: |du . r| of the last "
                          "Newton correction at most this times the step's "
                          "first |du . r| (-; the energy norm, J).");
        prm.declare_entry("Residual floor", "1e-12", Patterns::Double(0.),
                          "A residual norm below this (kN) counts as "
                          "converged whatever the reactions (an unloaded "
                          "model), with the energy criterion waived.");
        prm.declare_entry("Line search", "true", Patterns::Bool(),
                          "Damp each Newton correction by backtracking "
                          "(halving, at most 6 times) until the residual "
                          "norm decreases and no element inverts.");
        prm.declare_entry("Linear solver", "automatic",
                          Patterns::Selection("automatic|direct|AMG"),
                          "'direct': sparse LU (Trilinos Amesos, Direct solver); "
                          "'AMG': CG (hyperelastic laws) or GMRES (laws "
                          "with a history) preconditioned by Trilinos ML "
                          "algebraic multigrid with the six rigid-body "
                          "modes; 'automatic': direct up to the Direct "
                          "solver limit, AMG above.");
        prm.declare_entry("Direct solver limit", "20000", Patterns::Integer(0),
                          "'automatic' uses the direct solver up to this "
                          "many dofs (-).");
        prm.declare_entry("Direct solver", "MUMPS",
                          Patterns::Selection("MUMPS|KLU"),
                          "The sparse LU of 'direct' (Trilinos Amesos): "
                          "'MUMPS' (multifrontal, distributed over the "
                          "ranks) or 'KLU' (serial; 10 to 30 times slower "
                          "in 3D, see benchmarks/README.md).");
        prm.declare_entry("Linear tolerance", "1e-10", Patterns::Double(0.),
                          "AMG: relative residual of the CG or GMRES solve "
                          "(-).");
      }
      prm.leave_subsection();
      prm.leave_subsection();
    }



    void
    TimeIntegration::parse_parameters(ParameterHandler &prm)
    {
      using parameter_tools::require_positive;
      prm.enter_subsection("Time integration");
      scheme                   = prm.get("Scheme");
      end_time                 = prm.get_double("End time");
      time_step_scale          = prm.get_double("Time step scale factor");
      minimum_time_step        = prm.get_double("Minimum time step");
      mass_scaling_time_step   = prm.get_double("Mass scaling time step");
      selective_mass_scaling_time_step =
        prm.get_double("Selective mass scaling time step");
      selective_mass_scaling_tolerance =
        prm.get_double("Selective mass scaling tolerance");
      bulk_viscosity_linear    = prm.get_double("Bulk viscosity linear");
      bulk_viscosity_quadratic = prm.get_double("Bulk viscosity quadratic");
      fbar_stabilization       = prm.get_double("F-bar stabilization");
      assembled_step_estimate =
        prm.get("Stable time step estimate") == "assembled";
      stable_step_refresh_interval =
        prm.get_integer("Stable time step refresh interval");
      quasi_static_end_time    = prm.get_double("Quasi-static end time");
      prm.enter_subsection("Quasi-static");
      {
        QuasiStatic &q        = quasi_static;
        q.initial_step        = prm.get_double("Initial step");
        q.minimum_step        = prm.get_double("Minimum step");
        q.maximum_step        = prm.get_double("Maximum step");
        q.max_iterations      = prm.get_integer("Maximum iterations");
        q.max_cutbacks        = prm.get_integer("Maximum cut-backs");
        q.residual_tolerance  = prm.get_double("Residual tolerance");
        q.energy_tolerance    = prm.get_double("Energy tolerance");
        q.residual_floor      = prm.get_double("Residual floor");
        q.line_search         = prm.get_bool("Line search");
        const std::string solver = prm.get("Linear solver");
        q.linear_solver =
          solver == "direct" ? QuasiStatic::LinearSolver::direct :
          solver == "AMG"    ? QuasiStatic::LinearSolver::amg :
                               QuasiStatic::LinearSolver::automatic;
        q.direct_solver_limit = prm.get_integer("Direct solver limit");
        q.direct_solver =
          prm.get("Direct solver") == "KLU" ? "Amesos_Klu" : "Amesos_Mumps";
        q.linear_tolerance    = prm.get_double("Linear tolerance");
      }
      prm.leave_subsection();
      prm.leave_subsection();
      {
        const std::string path = "Time integration/Quasi-static/";
        require_positive(quasi_static_end_time,
                         "Time integration/Quasi-static end time");
        require_positive(quasi_static.initial_step, path + "Initial step");
        require_positive(quasi_static.minimum_step, path + "Minimum step");
        require_positive(quasi_static.maximum_step, path + "Maximum step");
        require_positive(quasi_static.residual_tolerance,
                         path + "Residual tolerance");
        require_positive(quasi_static.energy_tolerance,
                         path + "Energy tolerance");
        require_positive(quasi_static.linear_tolerance,
                         path + "Linear tolerance");
        if (quasi_static.minimum_step > quasi_static.initial_step)
          throw InputError(path + "Minimum step",
                           "is " +
                             parameter_tools::format_short(
                               quasi_static.minimum_step) +
                             ", larger than the Initial step " +
                             parameter_tools::format_short(
                               quasi_static.initial_step));
        if (quasi_static.initial_step > quasi_static.maximum_step)
          throw InputError(path + "Initial step",
                           "is " +
                             parameter_tools::format_short(
                               quasi_static.initial_step) +
                             ", larger than the Maximum step " +
                             parameter_tools::format_short(
                               quasi_static.maximum_step));
      }
      require_positive(end_time, "Time integration/End time");
      require_positive(time_step_scale,
                       "Time integration/Time step scale factor");
      require_step_within_run("Time integration/Mass scaling time step",
                              mass_scaling_time_step);
      require_step_within_run(
        "Time integration/Selective mass scaling time step",
        selective_mass_scaling_time_step);
      require_positive(selective_mass_scaling_tolerance,
                       "Time integration/Selective mass scaling tolerance");
      if (assembled_step_estimate && selective_mass_scaling_time_step > 0.)
        throw InputError(
          "Time integration/Stable time step estimate",
          "is 'assembled', which needs a lumped mass matrix, and the "
          "Selective mass scaling time step " +
            parameter_tools::format_short(selective_mass_scaling_time_step) +
            " ms makes it a full one; use 'element' with selective mass "
            "scaling");
    }



    void
    TimeIntegration::require_step_within_run(const std::string &entry,
                                             const double       step) const
    {
      if (step > end_time)
        throw InputError(entry,
                         "is " + parameter_tools::format_short(step) +
                           " ms, longer than the End time " +
                           parameter_tools::format_short(end_time) +
                           " ms; a time step cannot be longer than the run");
    }
  } // namespace parameters
} // namespace rubberdyn
