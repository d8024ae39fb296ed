#include <rubberdyn/base/simd_math.h>
#include <rubberdyn/materials/yeoh_stress_kernel.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace rubberdyn
{
  namespace materials
  {
    namespace
    {
      // The loop of YeohStressKernel::evaluate() for one volumetric
      // function, inlined into yeoh_points() so that it is cloned for AVX2
      // with it. Invalid points (det F <= 0 or not finite) get a NaN wave
      // speed.
      template <VolumetricFunction volumetric_function>
      inline __attribute__((always_inline)) void
      yeoh_points_loop(const double C10,
                       const double C20,
                       const double C30,
                       const double a1,
                       const double a2,
                       const double a3,
                       const double inverse_density,
                       const double *__restrict F,
                       double *__restrict tau,
                       double *__restrict energy,
                       double *__restrict wave_speed)
      {
        const double infinity = std::numeric_limits<double>::infinity();
        const double nan      = std::numeric_limits<double>::quiet_NaN();
        // All batch_size points, used or not: a fixed trip count and
        // stride let GCC vectorise without remainder loops or alias checks.
        constexpr std::size_t n = StressKernel::batch_size;
        for (std::size_t i = 0; i < n; ++i)
          {
            const double F00 = F[0 * n + i], F01 = F[1 * n + i],
                         F02 = F[2 * n + i], F10 = F[3 * n + i],
                         F11 = F[4 * n + i], F12 = F[5 * n + i],
                         F20 = F[6 * n + i], F21 = F[7 * n + i],
                         F22 = F[8 * n + i];
            const double J = F00 * (F11 * F22 - F12 * F21) -
                             F01 * (F10 * F22 - F12 * F20) +
                             F02 * (F10 * F21 - F11 * F20);
            const double J_m13 = simd_math::inverse_cube_root(J);
            const double J_m23 = J_m13 * J_m13;

            // b = F F^T and the deviator of its isochoric part.
            const double b00 = F00 * F00 + F01 * F01 + F02 * F02;
            const double b11 = F10 * F10 + F11 * F11 + F12 * F12;
            const double b22 = F20 * F20 + F21 * F21 + F22 * F22;
            const double b01 = F00 * F10 + F01 * F11 + F02 * F12;
            const double b02 = F00 * F20 + F01 * F21 + F02 * F22;
            const double b12 = F10 * F20 + F11 * F21 + F12 * F22;
            const double third_I1 = (b00 + b11 + b22) * (1. / 3.);
            const double I1_bar   = 3. * J_m23 * third_I1;
            const double x        = I1_bar - 3.;
            const double d00 = J_m23 * (b00 - third_I1),
                         d11 = J_m23 * (b11 - third_I1),
                         d22 = J_m23 * (b22 - third_I1), d01 = J_m23 * b01,
                         d02 = J_m23 * b02, d12 = J_m23 * b12;
            const double W1 = C10 + 2. * C20 * x + 3. * C30 * x * x;
            const double W2 = 2. * C20 + 6. * C30 * x;

            // U, the Kirchhoff pressure tau_vol = J U' and J^2 U''.
            double U, tau_vol, J2_d2U;
            if constexpr (volumetric_function == VolumetricFunction::polynomial)
              {
                // U = sum_k a_k (J-1)^(2k) and its derivatives.
                const double y  = J - 1.;
                const double y2 = y * y;
                U               = y2 * (a1 + y2 * (a2 + y2 * a3));
                const double dU = y * (2. * a1 + y2 * (4. * a2 + 6. * a3 * y2));
                const double d2U = 2. * a1 + y2 * (12. * a2 + 30. * a3 * y2);
                tau_vol          = J * dU;
                J2_d2U           = J * J * d2U;
              }
            else
              {
                // K = 2 a1.
                const VolumetricValues v =
                  logarithmic_volumetric_values<volumetric_function>(
                    J,
                    simd_math::natural_log(J),
                    2. * a1);
                U       = v.U;
                tau_vol = v.J_dU;
                J2_d2U  = v.J2_d2U;
              }

            const double two_W1  = 2. * W1;
            tau[0 * n + i]       = tau_vol + two_W1 * d00;
            tau[1 * n + i]       = tau_vol + two_W1 * d11;
            tau[2 * n + i]       = tau_vol + two_W1 * d22;
            tau[3 * n + i]       = two_W1 * d01;
            tau[4 * n + i]       = two_W1 * d02;
            tau[5 * n + i]       = two_W1 * d12;
            energy[i]            = x * (C10 + x * (C20 + x * C30)) + U;

            // The same upper estimate of the longitudinal modulus as
            // Yeoh::evaluate() (doc/theory.md).
            const double dev_norm_square =
              d00 * d00 + d11 * d11 + d22 * d22 +
              2. * (d01 * d01 + d02 * d02 + d12 * d12);
            const double mu_bar = 2. / 3. * W1 * I1_bar;
            // The largest eigenvalue max(J^2 U'', 0) of the volumetric
            // part; J^2 U'' < 0 only for log squared beyond J = e. The
            // other functions skip the max, which would stop GCC from
            // fusing J^2 U'' into the sum below (FMA) and change the
            // default's results in the last bit.
            double volumetric_modulus = J2_d2U;
            if constexpr (volumetric_function ==
                          VolumetricFunction::log_squared)
              volumetric_modulus = std::max(J2_d2U, 0.);
            const double modulus =
              volumetric_modulus + 4. / 3. * std::abs(mu_bar) +
              std::abs(two_W1) * std::sqrt(dev_norm_square) +
              4. * std::max(W2, 0.) * dev_norm_square;
            const double speed =
              std::sqrt(std::max(modulus, 0.) * inverse_density);
            const bool valid = (J > 0.) & (J < infinity);
            wave_speed[i]    = valid ? speed : nan;
          }
      }



      // All volumetric functions in one cloned function: GCC clones the
      // caller of an always_inline template, not the template itself.
      RUBBERDYN_VECTOR_CLONES void
      yeoh_points(const VolumetricFunction volumetric_function,
                  const double             C10,
                  const double             C20,
                  const double             C30,
                  const double             a1,
                  const double             a2,
                  const double             a3,
                  const double             inverse_density,
                  const double *__restrict F,
                  double *__restrict tau,
                  double *__restrict energy,
                  double *__restrict wave_speed)
      {
        switch (volumetric_function)
          {
            case VolumetricFunction::polynomial:
              yeoh_points_loop<VolumetricFunction::polynomial>(C10,
                                                               C20,
                                                               C30,
                                                               a1,
                                                               a2,
                                                               a3,
                                                               inverse_density,
                                                               F,
                                                               tau,
                                                               energy,
                                                               wave_speed);
              break;
            case VolumetricFunction::log_squared:
              yeoh_points_loop<VolumetricFunction::log_squared>(C10,
                                                                C20,
                                                                C30,
                                                                a1,
                                                                a2,
                                                                a3,
                                                                inverse_density,
                                                                F,
                                                                tau,
                                                                energy,
                                                                wave_speed);
              break;
            case VolumetricFunction::simo_taylor:
              yeoh_points_loop<VolumetricFunction::simo_taylor>(C10,
                                                                C20,
                                                                C30,
                                                                a1,
                                                                a2,
                                                                a3,
                                                                inverse_density,
                                                                F,
                                                                tau,
                                                                energy,
                                                                wave_speed);
              break;
          }
      }
    } // namespace



    YeohStressKernel::YeohStressKernel(
      const std::array<double, 3> &C,
      const std::array<double, 3> &inverse_d,
      const double                 density,
      const VolumetricFunction     volumetric_function)
      : C(C)
      , inverse_d(inverse_d)
      , density(density)
      , volumetric_function(volumetric_function)
    {}



    unsigned int
    YeohStressKernel::evaluate(const unsigned int n,
                               const double *     F,
                               const double *,
                               double *,
                               double *tau,
                               double *energy,
                               double *wave_speed) const
    {
      yeoh_points(volumetric_function,
                  C[0],
                  C[1],
                  C[2],
                  inverse_d[0],
                  inverse_d[1],
                  inverse_d[2],
                  1. / density,
                  F,
                  tau,
                  energy,
                  wave_speed);
      for (unsigned int i = 0; i < n; ++i)
        if (!(wave_speed[i] >= 0.))
          return i;
      return n;
    }
  } // namespace materials
} // namespace rubberdyn
