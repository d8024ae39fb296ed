// Yeoh rubber with the three volumetric functions U(J) (polynomial of the
// reference study, log squared, Simo-Taylor; doc/theory.md, "Volumetric
// functions"): where they agree and where they differ. The laws are built
// from parameter entries ('Volumetric function') through the material
// registry, as a study builds them.
//
// (1) Same small-strain bulk modulus: U''(1) = K for all three, so at F = I
//     the spatial tangent is 2 G P_dev + K I x I and the wave speed is
//     sqrt((K + 4G/3)/rho). Checked to 1e-12 relative: bulk_modulus(),
//     K = (1/9) sum_ij c_iijj at F = I, the wave speed at F = I and the
//     reference wave speed (hence the stable step) against the given K.
// (2) The energy landscape U(J) for J in (0, 2], by pure dilatation
//     F = J^(1/3) I (no isochoric part, so W = U): the polynomial tends to
//     the finite U(0) = 1/d1 = K/2 (checked: U(1e-12) = K/2 to 1e-11, the
//     next term being K (J - ...) ~ 1e-12 K), while the logarithmic ones
//     match their closed forms (K/2) ln^2 J and (K/4)(J^2 - 1 - 2 ln J) to
//     1e-12 relative, which grow without bound, and increase monotonically
//     as J decreases to 1e-12 (where U/K = 382 and 13.6). Beyond J = e,
//     log squared has J^2 U'' = K(1 - ln J) < 0; the wave-speed bound must
//     then take max(J^2 U'', 0) (doc/theory.md, section 4): at F = 4^(1/3) I
//     the isochoric part vanishes and rho c^2 = 4G/3 exactly (to 1e-12),
//     in the scalar law and in the batched kernel (without the max it would
//     be K(1 - ln 4) + 4G/3 < 0, a zero wave speed and no step limit).
// (3) Uniaxial stress, lambda from 1 down to 0.2 and up to 2, at K/G = 1000
//     and K/G = 10 (the library's Newton solver for the lateral stretch,
//     stepping from the previous state as the Material point study does):
//     the volume ratio J and the nominal stress P_11 of each function.
//     Checked: (a) the order of J. Writing e = J - 1, the Kirchhoff
//     pressures are K(e + e^2) (polynomial), K(e + e^2/2 + ...)
//     (Simo-Taylor), K(e - e^2/2 + ...) (log squared): for J != 1 the
//     polynomial resists volume change least in compression and most in
//     tension, so J_poly < J_ST < J_log everywhere (an exact ordering of
//     J U'(J), not only near J = 1). (b) The relative stress difference is
//     O((G/K)^2): the lateral equilibrium fixes e ~ s/K (s the deviatoric
//     stress, O(G)), the functions differ by O(K e^2), so J differs by
//     O((s/K)^2), and P_11 depends on J through the isochoric part. The
//     ratio of the differences at K/G = 10 and 1000 must be 10^4; within
//     15 % for lambda in [0.8, 1.25], where the next-order term O(e) with
//     |e| <= 0.024 at K/G = 10 is measured at up to 12.5 % (lambda = 1.25).
#include <deal.II/base/parameter_handler.h>

#include <rubberdyn/materials/homogeneous_deformation.h>
#include <rubberdyn/materials/material_registry.h>
#include <rubberdyn/materials/stress_kernel.h>
#include <rubberdyn/materials/yeoh.h>

#include <array>
#include <memory>
#include <vector>

#include "../tests.h"

using namespace dealii;
using namespace rubberdyn::materials;
using testing::check;
using testing::out;
using testing::sci;

namespace hd = homogeneous_deformation;

// Chapter-4 rubber of the reference study (GPa, kg/mm^3).
const double C10 = 0.55e-3, C20 = -0.05e-3, C30 = 0.015e-3, G = 2. * C10,
             density = 1.1e-6;

const std::array<VolumetricFunction, 3> functions = {
  {VolumetricFunction::polynomial,
   VolumetricFunction::simo_taylor,
   VolumetricFunction::log_squared}};

// The law as a study builds it from its material subsection.
std::unique_ptr<MaterialModel<3>>
create_law(const double K, const VolumetricFunction function)
{
  ParameterHandler prm;
  prm.enter_subsection("Specimen");
  registry::declare_part_parameters(prm, {"Yeoh", density, 0.499});
  prm.set("Model", "Yeoh");
  prm.set("Constants from", "coefficients");
  prm.set("C10", C10);
  prm.set("C20", C20);
  prm.set("C30", C30);
  prm.set("Volumetric model", "bulk modulus");
  prm.set("Bulk modulus", K);
  prm.set("Volumetric function", volumetric_function_name(function));
  auto law = registry::create<3>(prm, "Specimen");
  prm.leave_subsection();
  return law;
}

int
main()
{
  out() << std::setprecision(6);

  // (1) Small-strain bulk modulus and wave speed.
  {
    const double K = 1000. * G;
    out() << "(1) at F = I, K/G = 1000: K from bulk_modulus(), from the "
             "tangent, wave speed at F = I, reference wave speed "
             "(relative to the given K and to sqrt((K + 4G/3)/rho))"
          << std::endl;
    const double c_exact = std::sqrt((K + 4. / 3. * G) / density);
    for (const VolumetricFunction function : functions)
      {
        const auto          law = create_law(K, function);
        MaterialResponse<3> response;
        law->evaluate(unit_symmetric_tensor<3>(), {}, {}, true, response);
        double K_tangent = 0.;
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = 0; j < 3; ++j)
            K_tangent += response.spatial_tangent[i][i][j][j] / 9.;
        const double errors[4] = {
          std::abs(law->bulk_modulus() - K) / K,
          std::abs(K_tangent - K) / K,
          std::abs(response.dilatational_wave_speed - c_exact) / c_exact,
          std::abs(law->reference_wave_speed() - c_exact) / c_exact};
        out() << "  " << volumetric_function_name(function) << ": "
              << sci(errors[0]) << ", " << sci(errors[1]) << ", "
              << sci(errors[2]) << ", " << sci(errors[3]) << std::endl;
        for (const double e : errors)
          check(e < 1e-12,
                volumetric_function_name(function) +
                  ": small-strain K and wave speed to 1e-12");
      }
  }

  // (2) The energy landscape U(J)/K.
  {
    const double K = 1000. * G;
    out() << "\n(2) U(J)/K by pure dilatation, K/G = 1000" << std::endl;
    out() << "J, polynomial, Simo-Taylor, log squared" << std::endl;
    std::vector<std::unique_ptr<MaterialModel<3>>> laws;
    for (const VolumetricFunction function : functions)
      laws.push_back(create_law(K, function));
    const std::vector<double> Js       = {1e-12,
                                          1e-9,
                                          1e-6,
                                          1e-3,
                                          0.01,
                                          0.1,
                                          0.25,
                                          0.5,
                                          0.75,
                                          0.9,
                                          1.,
                                          1.1,
                                          1.25,
                                          1.5,
                                          2.};
    std::array<double, 3>     previous = {{0., 0., 0.}};
    for (unsigned int n = 0; n < Js.size(); ++n)
      {
        const double J = Js[n];
        out() << J;
        for (unsigned int f = 0; f < 3; ++f)
          {
            MaterialResponse<3> response;
            laws[f]->evaluate(std::cbrt(J) *
                                Tensor<2, 3>(unit_symmetric_tensor<3>()),
                              {},
                              {},
                              false,
                              response);
            // W = U exactly: the isochoric part of a dilatation is zero.
            const double U = response.strain_energy_density;
            out() << ", " << U / K;
            if (functions[f] == VolumetricFunction::polynomial)
              {
                if (J == 1e-12)
                  check(std::abs(U - K / 2.) < 1e-11 * K,
                        "polynomial: U(J -> 0) = 1/d1 = K/2, finite");
                check(U <= K / 2. || J > 1., "polynomial: U <= K/2 on (0, 1]");
              }
            else
              {
                // The closed forms, which grow without bound as J -> 0.
                const double U_exact =
                  (functions[f] == VolumetricFunction::log_squared ?
                     0.5 * K * std::log(J) * std::log(J) :
                     0.25 * K * (J * J - 1. - 2. * std::log(J)));
                check(std::abs(U - U_exact) <= 1e-12 * U_exact,
                      volumetric_function_name(functions[f]) +
                        ": U equals its closed form");
                // Monotonically decreasing towards J = 1 from below.
                if (n > 0 && J <= 1.)
                  check(U < previous[f],
                        volumetric_function_name(functions[f]) +
                          ": U increases as J decreases");
                if (J == 1e-12)
                  check(U > 10. * K,
                        volumetric_function_name(functions[f]) +
                          ": U(1e-12) > 10 K (unbounded as J -> 0)");
              }
            previous[f] = U;
          }
        out() << std::endl;
      }
  }

  // (2b) The wave speed of log squared beyond J = e.
  {
    const double        K   = 1000. * G;
    const auto          law = create_law(K, VolumetricFunction::log_squared);
    const double        a   = std::cbrt(4.);
    MaterialResponse<3> response;
    law->evaluate(a * Tensor<2, 3>(unit_symmetric_tensor<3>()),
                  {},
                  {},
                  false,
                  response);
    constexpr unsigned int N        = StressKernel::batch_size;
    double                 F[9 * N] = {}, tau[6 * N], energy[N], wave_speed[N];
    for (unsigned int i = 0; i < N; ++i)
      F[0 * N + i] = F[4 * N + i] = F[8 * N + i] = a;
    const auto kernel = create_stress_kernel(*law);
    check(kernel->evaluate(N, F, nullptr, nullptr, tau, energy, wave_speed) ==
            N,
          "kernel evaluates J = 4");
    const double c_exact   = std::sqrt(4. / 3. * G / density);
    const double errors[2] = {
      std::abs(response.dilatational_wave_speed - c_exact) / c_exact,
      std::abs(wave_speed[0] - c_exact) / c_exact};
    out() << "\n(2b) log squared at J = 4: rho c^2 = 4G/3, relative error "
             "of c: law "
          << sci(errors[0]) << ", kernel " << sci(errors[1]) << std::endl;
    check(errors[0] < 1e-12 && errors[1] < 1e-12,
          "log squared beyond J = e: wave speed from max(J^2 U'', 0)");
  }

  // (3) Uniaxial stress.
  out() << "\n(3) uniaxial stress: J and P_11 (MPa) of polynomial, "
           "Simo-Taylor, log squared; relative spread of P_11"
        << std::endl;
  const std::vector<double> K_over_G = {1000., 10.};
  // The printed stretches; the path steps by 0.01 from 1.
  const std::vector<double> printed =
    {0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 0.95, 1.05, 1.1, 1.25, 1.5, 2.};
  std::vector<std::vector<double>> spread(K_over_G.size(),
                                          std::vector<double>(printed.size()));
  for (unsigned int r = 0; r < K_over_G.size(); ++r)
    {
      const double K = K_over_G[r] * G;
      out() << "K/G = " << K_over_G[r] << std::endl;
      out() << "lambda, J_poly, J_ST, J_log, P_poly, P_ST, P_log, spread"
            << std::endl;
      std::vector<std::unique_ptr<MaterialModel<3>>> laws;
      for (const VolumetricFunction function : functions)
        laws.push_back(create_law(K, function));

      // results[f][p] = (J, P_11) at printed[p].
      std::vector<std::vector<std::pair<double, double>>> results(
        3,
        std::vector<std::pair<double, double>>(printed.size()));
      for (unsigned int f = 0; f < 3; ++f)
        for (const int direction : {-1, 1})
          {
            // 80 steps down to 0.2, 100 steps up to 2.
            const unsigned int n_steps = (direction < 0 ? 80 : 100);
            double             mu      = 1.;
            for (unsigned int step = 1; step <= n_steps; ++step)
              {
                const double        l = 1. + direction * 0.01 * step;
                MaterialResponse<3> response;
                mu = hd::solve(*laws[f],
                               hd::Mode::uniaxial_stress,
                               l,
                               mu,
                               {},
                               {},
                               response);
                for (unsigned int p = 0; p < printed.size(); ++p)
                  if (std::abs(printed[p] - l) < 1e-9)
                    results[f][p] = {l * mu * mu,
                                     response.kirchhoff_stress[0][0] / l};
              }
          }

      for (unsigned int p = 0; p < printed.size(); ++p)
        {
          const double P_poly = results[0][p].second;
          double       P_min = P_poly, P_max = P_poly;
          for (unsigned int f = 1; f < 3; ++f)
            {
              P_min = std::min(P_min, results[f][p].second);
              P_max = std::max(P_max, results[f][p].second);
            }
          spread[r][p] = (P_max - P_min) / std::abs(P_poly);
          out() << printed[p] << ", " << std::setprecision(8)
                << results[0][p].first << ", " << results[1][p].first << ", "
                << results[2][p].first << ", " << std::setprecision(6)
                << P_poly * 1e3 << ", " << results[1][p].second * 1e3 << ", "
                << results[2][p].second * 1e3 << ", " << sci(spread[r][p])
                << std::endl;
          check(results[0][p].first < results[1][p].first &&
                  results[1][p].first < results[2][p].first,
                "J_poly < J_ST < J_log at every stretch");
        }
      out() << "largest relative spread of P_11 at K/G = " << K_over_G[r]
            << ": "
            << sci(*std::max_element(spread[r].begin(), spread[r].end()))
            << std::endl;
    }

  out() << "ratio of the spreads at K/G = 10 and 1000, over (G/K)^2 ratio "
           "10^4"
        << std::endl;
  for (unsigned int p = 0; p < printed.size(); ++p)
    {
      const double ratio = spread[1][p] / spread[0][p] / 1e4;
      out() << printed[p] << ", " << std::setprecision(3) << ratio
            << std::setprecision(6) << std::endl;
      if (printed[p] >= 0.8 && printed[p] <= 1.25)
        check(std::abs(ratio - 1.) < 0.15,
              "the spread is O((G/K)^2) near lambda = 1");
    }
}
