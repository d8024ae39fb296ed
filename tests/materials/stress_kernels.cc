// The batched stress kernels used by the explicit elements give what the
// laws' own evaluate() gives: for 32 random deformation gradients (det F
// from 0.4 to 2.5, shears up to 0.5) the Kirchhoff stress, stored energy
// and wave speed of the batched Yeoh kernel (with 1, 2 and 3 volumetric
// terms of the polynomial volumetric function, and with the log squared and
// Simo-Taylor functions) and of the batched finite-strain J2 kernel
// (Elastic; J2 plasticity from a virgin history, and a second step from
// the first one's plastic history with elastic unloading at some points
// and further flow at others) agree with MaterialModel::evaluate() to 1e-12
// relative (the kernels take J^{-1/3} from simd_math::inverse_cube_root
// instead of std::pow, and ln J from simd_math::natural_log instead of
// std::log). An inverted point is reported by its index. Also checks
// simd_math::inverse_cube_root against 1 / std::cbrt and
// simd_math::natural_log against std::log over x in [1e-6, 1e6] to 1e-15
// relative (a few ulp), and natural_log(1) = 0 exactly (the energy at rest).
#include <rubberdyn/base/simd_math.h>
#include <rubberdyn/materials/elastic.h>
#include <rubberdyn/materials/hardening_curve.h>
#include <rubberdyn/materials/j2_plasticity.h>
#include <rubberdyn/materials/stress_kernel.h>
#include <rubberdyn/materials/yeoh.h>

#include <memory>
#include <random>

#include "../tests.h"

using namespace dealii;
using namespace rubberdyn;
using testing::check;
using testing::out;
using testing::sci;

int
main()
{
  constexpr unsigned int N = materials::StressKernel::batch_size;

  // inverse_cube_root over 12 decades.
  {
    std::mt19937                           generator(1);
    std::uniform_real_distribution<double> exponent(-6., 6.);
    double                                 worst = 0.;
    for (unsigned int i = 0; i < 1000000; ++i)
      {
        const double x     = std::pow(10., exponent(generator));
        const double exact = 1. / std::cbrt(x);
        worst              = std::max(worst,
                         std::abs(simd_math::inverse_cube_root(x) - exact) /
                           exact);
      }
    out() << "inverse_cube_root within 1e-15 of 1/cbrt: "
          << (worst < 1e-15 ? "yes" : "no") << std::endl;
    std::cerr << "inverse_cube_root: largest relative error " << sci(worst)
              << std::endl;
    check(worst < 1e-15, "inverse_cube_root to 1e-15");
  }

  // natural_log over 12 decades, and around 1 (where ln x is small and
  // only a relative error tells).
  {
    std::mt19937                           generator(2);
    std::uniform_real_distribution<double> exponent(-6., 6.),
      near_one(-1e-3, 1e-3);
    double worst = 0.;
    for (unsigned int i = 0; i < 1000000; ++i)
      for (const double x :
           {std::pow(10., exponent(generator)), 1. + near_one(generator)})
        {
          const double exact = std::log(x);
          if (exact != 0.)
            worst = std::max(worst,
                             std::abs(simd_math::natural_log(x) - exact) /
                               std::abs(exact));
        }
    out() << "natural_log within 1e-15 of std::log, natural_log(1) = "
          << simd_math::natural_log(1.) << ": "
          << (worst < 1e-15 ? "yes" : "no") << std::endl;
    std::cerr << "natural_log: largest relative error " << sci(worst)
              << std::endl;
    check(worst < 1e-15, "natural_log to 1e-15");
    check(simd_math::natural_log(1.) == 0., "natural_log(1) = 0");
  }

  std::vector<
    std::pair<std::string, std::shared_ptr<materials::MaterialModel<3>>>>
    laws = {{"Yeoh, K only",
             std::make_shared<materials::Yeoh<3>>(0.55e-3,
                                                  -0.05e-3,
                                                  0.015e-3,
                                                  std::array<double, 3>{
                                                    {1.2, 0., 0.}},
                                                  1.1e-6)},
            {"Yeoh, D1..D3",
             std::make_shared<materials::Yeoh<3>>(0.55e-3,
                                                  -0.05e-3,
                                                  0.95e-3,
                                                  std::array<double, 3>{
                                                    {1.2, 0.3, 0.05}},
                                                  1.1e-6)},
            {"Yeoh, log squared",
             std::make_shared<materials::Yeoh<3>>(
               0.55e-3,
               -0.05e-3,
               0.015e-3,
               std::array<double, 3>{{1.2, 0., 0.}},
               1.1e-6,
               materials::VolumetricFunction::log_squared)},
            {"Yeoh, Simo-Taylor",
             std::make_shared<materials::Yeoh<3>>(
               0.55e-3,
               -0.05e-3,
               0.95e-3,
               std::array<double, 3>{{1.2, 0., 0.}},
               1.1e-6,
               materials::VolumetricFunction::simo_taylor)},
            {"Elastic",
             std::make_shared<materials::Elastic<3>>(210., 0.3, 7.85e-6)},
            {"J2 plasticity",
             std::make_shared<materials::J2Plasticity<3>>(
               70.,
               0.33,
               2.7e-6,
               materials::HardeningCurve(0.2, {0.1}, {0.3}, "test"))}};

  std::mt19937                           generator(7);
  std::uniform_real_distribution<double> entry(-0.5, 0.5);
  std::vector<Tensor<2, 3>>              gradients;
  while (gradients.size() < N)
    {
      Tensor<2, 3> F;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          F[i][j] = (i == j ? 1. : 0.) + entry(generator);
      if (determinant(F) > 0.4 && determinant(F) < 2.5)
        gradients.push_back(F);
    }
  double F_batch[9 * N];
  for (unsigned int i = 0; i < N; ++i)
    for (unsigned int r = 0; r < 3; ++r)
      for (unsigned int c = 0; c < 3; ++c)
        F_batch[(3 * r + c) * N + i] = gradients[i][r][c];

  constexpr unsigned int row[6] = {0, 1, 2, 0, 0, 1};
  constexpr unsigned int col[6] = {0, 1, 2, 1, 2, 2};

  // The largest relative difference between the kernel's outputs for the
  // gradients in F and MaterialModel::evaluate() point by point, from the
  // history state_old; the kernel's new history in state_new.
  const auto largest_difference =
    [&](const materials::MaterialModel<3> &law,
        const materials::StressKernel &    kernel,
        const std::vector<Tensor<2, 3>> &  F,
        const std::vector<double> &        state_old,
        std::vector<double> &              state_new) {
      const unsigned int n_state = law.n_state_variables();
      double             F_flat[9 * N];
      for (unsigned int i = 0; i < N; ++i)
        for (unsigned int r = 0; r < 3; ++r)
          for (unsigned int c = 0; c < 3; ++c)
            F_flat[(3 * r + c) * N + i] = F[i][r][c];
      double             tau[6 * N], energy[N], wave_speed[N];
      const unsigned int evaluated =
        kernel.evaluate(N, F_flat, state_old.data(), state_new.data(), tau,
                        energy, wave_speed);
      check(evaluated == N, law.name() + ": all points evaluated");

      std::vector<double> state_single(n_state);
      double              worst = 0.;
      for (unsigned int i = 0; i < N; ++i)
        {
          materials::MaterialResponse<3> response;
          law.evaluate(F[i],
                       ArrayView<const double>(state_old.data() + i * n_state,
                                               n_state),
                       make_array_view(state_single),
                       false,
                       response);
          const double scale = response.kirchhoff_stress.norm();
          for (unsigned int k = 0; k < 6; ++k)
            worst = std::max(worst,
                             std::abs(tau[k * N + i] -
                                      response.kirchhoff_stress[row[k]][col[k]]) /
                               scale);
          worst = std::max(worst,
                           std::abs(energy[i] - response.strain_energy_density) /
                             std::abs(response.strain_energy_density));
          worst = std::max(worst,
                           std::abs(wave_speed[i] -
                                    response.dilatational_wave_speed) /
                             response.dilatational_wave_speed);
          for (unsigned int s = 0; s < n_state; ++s)
            worst = std::max(worst,
                             std::abs(state_new[i * n_state + s] -
                                      state_single[s]) /
                               std::max(1., std::abs(state_single[s])));
        }
      return worst;
    };

  for (const auto &[name, law] : laws)
    {
      const unsigned int  n_state = law->n_state_variables();
      std::vector<double> state_old(N * n_state), state_new(N * n_state);
      for (unsigned int i = 0; i < N; ++i)
        law->initialize_state(
          ArrayView<double>(state_old.data() + i * n_state, n_state));
      const auto kernel = materials::create_stress_kernel(*law);

      const double worst =
        largest_difference(*law, *kernel, gradients, state_old, state_new);
      std::cerr << name << ": largest relative difference " << sci(worst)
                << std::endl;
      out() << name << ": batched kernel = evaluate() to 1e-12: "
            << (worst < 1e-12 ? "yes" : "no") << std::endl;
      check(worst < 1e-12, name + ": kernel agrees with evaluate()");

      if (n_state > 0)
        {
          // A second step from the first one's plastic history: half of
          // the points go back 1 % of the way to F = I (strains of about
          // 0.005, below the elastic strain of about 0.008 = yield stress /
          // G: elastic unloading from a plastic state), the others are
          // stretched by a further 30 % along x (more plastic flow from
          // alpha > 0).
          std::vector<Tensor<2, 3>> second = gradients;
          Tensor<2, 3>              stretch = unit_symmetric_tensor<3>();
          stretch[0][0]                     = 1.3;
          for (unsigned int i = 0; i < N; ++i)
            second[i] = (i % 2 == 0) ?
                          Tensor<2, 3>(0.99 * gradients[i] +
                                       0.01 * unit_symmetric_tensor<3>()) :
                          Tensor<2, 3>(stretch * gradients[i]);
          const std::vector<double> state_first = state_new;
          const double worst_second =
            largest_difference(*law, *kernel, second, state_first, state_new);
          const unsigned int alpha = materials::finite_strain_j2::
            equivalent_plastic_strain_index;
          unsigned int plastic_first = 0, elastic_second = 0,
                       plastic_second = 0;
          for (unsigned int i = 0; i < N; ++i)
            {
              plastic_first += (state_first[i * n_state + alpha] > 0.);
              if (state_first[i * n_state + alpha] > 0.)
                (state_new[i * n_state + alpha] >
                     state_first[i * n_state + alpha] ?
                   plastic_second :
                   elastic_second) += 1;
            }
          std::cerr << name << ", second step: largest relative difference "
                    << sci(worst_second) << "; " << plastic_first
                    << " points plastic in the first step, of which "
                    << elastic_second << " unload elastically and "
                    << plastic_second << " flow further" << std::endl;
          out() << name
                << ", second step from a plastic history: batched kernel = "
                   "evaluate() to 1e-12: "
                << (worst_second < 1e-12 ? "yes" : "no") << std::endl;
          check(worst_second < 1e-12,
                name + ": kernel agrees with evaluate() from a history");
          check(elastic_second > 0 && plastic_second > 0,
                name + ": the second step unloads some plastic points and "
                       "loads others further");
        }

      // An inverted point (a reflection) at index 13 is reported.
      double F_bad[9 * N];
      std::copy(F_batch, F_batch + 9 * N, F_bad);
      for (unsigned int c = 0; c < 3; ++c)
        F_bad[(3 * 0 + c) * N + 13] *= -1.;
      double             tau[6 * N], energy[N], wave_speed[N];
      const unsigned int failed =
        kernel->evaluate(N, F_bad, state_old.data(), state_new.data(), tau,
                         energy, wave_speed);
      out() << name << ": inverted point reported at index " << failed
            << std::endl;
      check(failed == 13, name + ": inverted point index");
    }
}
