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
      // The loop body of YeohStressKernel::evaluate(); a free function so
      // that it can be cloned for AVX2. Invalid points (det F <= 0 or not
      // finite) get a NaN wave speed.
      RUBBERDYN_VECTOR_CLONES void
      yeoh_points(const double C10,
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

            // U = sum_k a_k (J-1)^(2k) and its derivatives.
            const double y   = J - 1.;
            const double y2  = y * y;
            const double U   = y2 * (a1 + y2 * (a2 + y2 * a3));
            const double dU  = y * (2. * a1 + y2 * (4. * a2 + 6. * a3 * y2));
            const double d2U = 2. * a1 + y2 * (12. * a2 + 30. * a3 * y2);

            const double tau_vol = J * dU;
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
            const double modulus =
              J * J * d2U + 4. / 3. * std::abs(mu_bar) +
              std::abs(two_W1) * std::sqrt(dev_norm_square) +
              4. * std::max(W2, 0.) * dev_norm_square;
            const double speed =
              std::sqrt(std::max(modulus, 0.) * inverse_density);
            const bool valid = (J > 0.) & (J < infinity);
            wave_speed[i]    = valid ? speed : nan;
          }
      }
    } // namespace



    YeohStressKernel::YeohStressKernel(const std::array<double, 3> &C,
                                       const std::array<double, 3> &inverse_d,
                                       const double                 density)
      : C(C)
      , inverse_d(inverse_d)
      , density(density)
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
      yeoh_points(C[0], C[1], C[2], inverse_d[0], inverse_d[1], inverse_d[2],
                  1. / density, F, tau, energy, wave_speed);
      for (unsigned int i = 0; i < n; ++i)
        if (!(wave_speed[i] >= 0.))
          return i;
      return n;
    }
  } // namespace materials
} // namespace rubberdyn
