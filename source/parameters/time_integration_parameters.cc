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
      prm.declare_entry("Scheme", "explicit", Patterns::Selection("explicit"),
                        "Time integration scheme. 'explicit': central "
                        "differences with lumped mass (reference study eqs. "
                        "2.7-2.10). A quasi-static Newton solver will add "
                        "its values here.");
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
      bulk_viscosity_linear    = prm.get_double("Bulk viscosity linear");
      bulk_viscosity_quadratic = prm.get_double("Bulk viscosity quadratic");
      fbar_stabilization       = prm.get_double("F-bar stabilization");
      prm.leave_subsection();
      require_positive(end_time, "Time integration/End time");
      require_positive(time_step_scale,
                       "Time integration/Time step scale factor");
      // A target step longer than the whole run is no time step: it would
      // make the model arbitrarily heavy (1e308 ms overflows the added
      // density to infinity) to take a single step.
      if (mass_scaling_time_step > end_time)
        throw InputError("Time integration/Mass scaling time step",
                         "is " +
                           parameter_tools::format_short(
                             mass_scaling_time_step) +
                           " ms, longer than the End time " +
                           parameter_tools::format_short(end_time) +
                           " ms; a time step cannot be longer than the run");
    }
  } // namespace parameters
} // namespace rubberdyn
