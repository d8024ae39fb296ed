// J2 plasticity in uniaxial tension: the input hardening curve comes back,
// and unloading follows Young's modulus.
//
// Bolt steel: E = 210 GPa, nu = 0.3, yield 0.94 GPa, hardening table
// (0.02, 1.00 GPa), (0.08, 1.04 GPa). The specimen is stretched to 12 % in
// uniaxial stress (lateral faces free, solved by Newton's method with the
// consistent tangent), then unloaded by 0.2 % stretch.
//
// Checks, with their sources:
// - In uniaxial stress the Kirchhoff stress tau_11 equals the yield stress
//   k(alpha) at every plastic step: ||dev tau|| = sqrt(2/3) tau_11 in
//   uniaxial stress, and the return mapping enforces ||s|| = sqrt(2/3)
//   k(alpha) (Simo & Hughes 1998, Box 9.1). Tolerance 1e-10 relative:
//   round-off of the Newton solution for the lateral stretch (1e-12).
// - alpha is the plastic part of the logarithmic strain, alpha = ln(l) -
//   tau_11/E, to first order in the elastic strain eps_e = k/E (< 0.005):
//   Simo's update accumulates the plastic flow of bbar_e through
//   mu_bar = G tr(bbar_e)/3 = G (1 + O(eps_e)), and the neo-Hookean elastic
//   strain differs from tau/E by O(eps_e^2). So the relative difference
//   must stay below 2 eps_e (2 eps_e = 1.0 %) once the point is clearly
//   plastic (alpha > eps_e; just past yield alpha -> 0 and a relative
//   measure means nothing).
// - The unloading slope d tau_11 / d ln(l) equals E to first order in the
//   elastic strain: within 1 % (eps_e = 0.5 %).
#include <rubberdyn/materials/finite_strain_j2.h>
#include <rubberdyn/materials/hardening_curve.h>
#include <rubberdyn/materials/homogeneous_deformation.h>
#include <rubberdyn/materials/j2_plasticity.h>

#include <vector>

#include "../tests.h"

using namespace dealii;
using namespace rubberdyn::materials;
using testing::check;
using testing::out;
using testing::sci;

int
main()
{
  const double         E = 210., nu = 0.3;
  const HardeningCurve curve(0.94, {0.02, 0.08}, {1.0, 1.04}, "test");
  const J2Plasticity<3> steel(E, nu, 7.85e-6, curve);

  std::vector<double> state_old(steel.n_state_variables()),
    state_new(steel.n_state_variables());
  steel.initialize_state(make_array_view(state_old));

  const auto mode = homogeneous_deformation::Mode::uniaxial_stress;
  double     mu   = 1.;
  MaterialResponse<3> response;
  double max_yield_error = 0., max_log_strain_error = 0.;
  out() << std::setprecision(6);
  out() << "stretch, tau_11 (GPa), alpha, k(alpha) (GPa)" << std::endl;
  const unsigned int n_steps = 120;
  double             last_tau = 0., last_log_stretch = 0.;
  for (unsigned int step = 1; step <= n_steps; ++step)
    {
      const double l = 1. + 0.12 * step / n_steps;
      mu             = homogeneous_deformation::solve(
        steel, mode, l, mu, make_array_view(std::as_const(state_old)),
        make_array_view(state_new), response);
      state_old = state_new;
      const double alpha =
        state_new[finite_strain_j2::equivalent_plastic_strain_index];
      const double tau = response.kirchhoff_stress[0][0];
      if (alpha > 0.)
        max_yield_error =
          std::max(max_yield_error,
                   std::abs(tau - curve.yield_stress(alpha)) / tau);
      if (alpha > curve.yield_stress(0.) / E)
        {
          max_log_strain_error =
            std::max(max_log_strain_error,
                     std::abs(alpha - (std::log(l) - tau / E)) / alpha);
        }
      if (step % 10 == 0)
        out() << l << ", " << tau << ", " << alpha << ", "
              << curve.yield_stress(alpha) << std::endl;
      last_tau         = tau;
      last_log_stretch = std::log(l);
    }
  out() << "tau_11 = k(alpha) on the plastic branch: error "
        << sci(max_yield_error) << std::endl;
  out() << "alpha = ln(l) - tau_11/E: largest relative difference "
        << sci(max_log_strain_error) << std::endl;
  check(max_yield_error < 1e-10, "hardening curve reproduced");
  check(max_log_strain_error < 2. * curve.yield_stress(0.12) / E,
        "alpha is the plastic log strain to O(eps_e)");

  // Unload by 0.2 % stretch: elastic.
  const double alpha_before =
    state_old[finite_strain_j2::equivalent_plastic_strain_index];
  const double l_unload = 1.12 - 0.002;
  mu = homogeneous_deformation::solve(steel, mode, l_unload, mu,
                                      make_array_view(std::as_const(state_old)),
                                      make_array_view(state_new), response);
  const double slope = (last_tau - response.kirchhoff_stress[0][0]) /
                       (last_log_stretch - std::log(l_unload));
  out() << "unloading: plastic strain unchanged: "
        << (state_new[finite_strain_j2::equivalent_plastic_strain_index] ==
                alpha_before ?
              "yes" :
              "no")
        << ", slope / E = " << std::setprecision(3) << slope / E << std::endl;
  check(state_new[finite_strain_j2::equivalent_plastic_strain_index] ==
          alpha_before,
        "unloading is elastic");
  check(std::abs(slope / E - 1.) < 0.01, "unloading slope is E within 1 %");
}
