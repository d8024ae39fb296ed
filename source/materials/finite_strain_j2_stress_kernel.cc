#include <rubberdyn/base/simd_math.h>
#include <rubberdyn/materials/finite_strain_j2_stress_kernel.h>

#include <cmath>
#include <cstddef>
#include <limits>

namespace rubberdyn
{
  namespace materials
  {
    namespace
    {
      // All batch_size points, used or not: a fixed trip count and stride
      // let GCC vectorise without remainder loops or alias checks.
      constexpr std::size_t n = StressKernel::batch_size;

      // Pass 1: the trial state of finite_strain_j2::update() (Simo &
      // Hughes Box 9.1, step 1) at every point. Without history (the
      // elastic law) C_p^{-1} = I. Outputs, each with stride n: J,
      // J^{-2/3}, the trial b_e (xx, yy, zz, xy, xz, yz), I_e = tr(b_e)/3
      // (mu_bar = G I_e) and ||s_trial|| = G ||dev b_e||.
      template <bool with_history>
      inline __attribute__((always_inline)) void
      trial_points_loop(const double G,
                        const double *__restrict F,
                        const double *__restrict Cp_inv,
                        double *__restrict J_out,
                        double *__restrict J_m23_out,
                        double *__restrict be,
                        double *__restrict Ie_out,
                        double *__restrict s_norm)
      {
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
            // b_e = J^{-2/3} F C_p^{-1} F^T.
            double b00, b11, b22, b01, b02, b12;
            if constexpr (with_history)
              {
                const double c00 = Cp_inv[0 * n + i], c11 = Cp_inv[1 * n + i],
                             c22 = Cp_inv[2 * n + i], c01 = Cp_inv[3 * n + i],
                             c02 = Cp_inv[4 * n + i], c12 = Cp_inv[5 * n + i];
                // A = F C_p^{-1}.
                const double A00 = F00 * c00 + F01 * c01 + F02 * c02,
                             A01 = F00 * c01 + F01 * c11 + F02 * c12,
                             A02 = F00 * c02 + F01 * c12 + F02 * c22,
                             A10 = F10 * c00 + F11 * c01 + F12 * c02,
                             A11 = F10 * c01 + F11 * c11 + F12 * c12,
                             A12 = F10 * c02 + F11 * c12 + F12 * c22,
                             A20 = F20 * c00 + F21 * c01 + F22 * c02,
                             A21 = F20 * c01 + F21 * c11 + F22 * c12,
                             A22 = F20 * c02 + F21 * c12 + F22 * c22;
                b00 = A00 * F00 + A01 * F01 + A02 * F02;
                b11 = A10 * F10 + A11 * F11 + A12 * F12;
                b22 = A20 * F20 + A21 * F21 + A22 * F22;
                b01 = A00 * F10 + A01 * F11 + A02 * F12;
                b02 = A00 * F20 + A01 * F21 + A02 * F22;
                b12 = A10 * F20 + A11 * F21 + A12 * F22;
              }
            else
              {
                b00 = F00 * F00 + F01 * F01 + F02 * F02;
                b11 = F10 * F10 + F11 * F11 + F12 * F12;
                b22 = F20 * F20 + F21 * F21 + F22 * F22;
                b01 = F00 * F10 + F01 * F11 + F02 * F12;
                b02 = F00 * F20 + F01 * F21 + F02 * F22;
                b12 = F10 * F20 + F11 * F21 + F12 * F22;
              }
            b00 *= J_m23;
            b11 *= J_m23;
            b22 *= J_m23;
            b01 *= J_m23;
            b02 *= J_m23;
            b12 *= J_m23;
            const double Ie  = (b00 + b11 + b22) * (1. / 3.);
            const double d00 = b00 - Ie, d11 = b11 - Ie, d22 = b22 - Ie;
            J_out[i]      = J;
            J_m23_out[i]  = J_m23;
            Ie_out[i]     = Ie;
            be[0 * n + i] = b00;
            be[1 * n + i] = b11;
            be[2 * n + i] = b22;
            be[3 * n + i] = b01;
            be[4 * n + i] = b02;
            be[5 * n + i] = b12;
            s_norm[i] =
              G * std::sqrt(d00 * d00 + d11 * d11 + d22 * d22 +
                            2. * (b01 * b01 + b02 * b02 + b12 * b12));
          }
      }



      // Pass 3: stress, energy and wave speed from pass 1's trial state and
      // pass 2's increments delta_alpha (0 at elastic points); with
      // history, the new C_p^{-1} (stride n). Invalid points (det F <= 0 or
      // not finite) get a NaN wave speed.
      template <bool with_history>
      inline __attribute__((always_inline)) void
      final_points_loop(const double G,
                        const double K,
                        const double inverse_density,
                        const double *__restrict F,
                        const double *__restrict J_in,
                        const double *__restrict J_m23,
                        const double *__restrict be,
                        const double *__restrict Ie_in,
                        const double *__restrict s_norm,
                        const double *__restrict delta_alpha,
                        const double *__restrict Cp_inv_old,
                        double *__restrict Cp_inv_new,
                        double *__restrict tau,
                        double *__restrict energy,
                        double *__restrict wave_speed)
      {
        const double infinity = std::numeric_limits<double>::infinity();
        const double nan      = std::numeric_limits<double>::quiet_NaN();
        const double inverse_G = 1. / G;
        for (std::size_t i = 0; i < n; ++i)
          {
            const double J   = J_in[i];
            const double b00 = be[0 * n + i], b11 = be[1 * n + i],
                         b22 = be[2 * n + i], b01 = be[3 * n + i],
                         b02 = be[4 * n + i], b12 = be[5 * n + i];
            const double Ie     = Ie_in[i];
            const double mu_bar = G * Ie;

            // Radial return: s = (1 - beta_1) s_trial with beta_1 =
            // 2 mu_bar delta_gamma / ||s_trial||, delta_gamma = sqrt(3/2)
            // delta_alpha. The division is discarded at elastic points
            // (where ||s_trial|| may be 0).
            const double da      = delta_alpha[i];
            const bool   plastic = da > 0.;
            const double beta_1 =
              plastic ? 2. * mu_bar * std::sqrt(1.5) * da / s_norm[i] : 0.;
            const double factor = (1. - beta_1) * G;
            const double s00 = factor * (b00 - Ie), s11 = factor * (b11 - Ie),
                         s22 = factor * (b22 - Ie), s01 = factor * b01,
                         s02 = factor * b02, s12 = factor * b12;

            // tau = K/2 (J^2 - 1) I + s.
            const double tau_vol = 0.5 * K * (J * J - 1.);
            tau[0 * n + i]       = tau_vol + s00;
            tau[1 * n + i]       = tau_vol + s11;
            tau[2 * n + i]       = tau_vol + s22;
            tau[3 * n + i]       = s01;
            tau[4 * n + i]       = s02;
            tau[5 * n + i]       = s12;

            // The updated elastic state s/G + Ie I has the trace 3 Ie, as
            // the trial state: the stored energy needs no select.
            energy[i] = 0.5 * K * (0.5 * (J * J - 1.) -
                                   simd_math::natural_log(J)) +
                        0.5 * G * (3. * Ie - 3.);
            const double s_new_norm = std::abs(1. - beta_1) * s_norm[i];
            const double speed =
              std::sqrt((0.5 * K * (J * J + 1.) + 4. / 3. * mu_bar +
                         s_new_norm) *
                        inverse_density);
            const bool valid = (J > 0.) & (J < infinity);
            wave_speed[i]    = valid ? speed : nan;

            if constexpr (with_history)
              {
                // C_p^{-1} = F_bar^{-1} b_e F_bar^{-T} with b_e = s/G + Ie I
                // = J^{2/3} F^{-1} b_e F^{-T}; F^{-1} = cof(F)^T / J.
                const double F00 = F[0 * n + i], F01 = F[1 * n + i],
                             F02 = F[2 * n + i], F10 = F[3 * n + i],
                             F11 = F[4 * n + i], F12 = F[5 * n + i],
                             F20 = F[6 * n + i], F21 = F[7 * n + i],
                             F22 = F[8 * n + i];
                const double inverse_J = 1. / J;
                const double G00 = (F11 * F22 - F12 * F21) * inverse_J,
                             G01 = (F02 * F21 - F01 * F22) * inverse_J,
                             G02 = (F01 * F12 - F02 * F11) * inverse_J,
                             G10 = (F12 * F20 - F10 * F22) * inverse_J,
                             G11 = (F00 * F22 - F02 * F20) * inverse_J,
                             G12 = (F02 * F10 - F00 * F12) * inverse_J,
                             G20 = (F10 * F21 - F11 * F20) * inverse_J,
                             G21 = (F01 * F20 - F00 * F21) * inverse_J,
                             G22 = (F00 * F11 - F01 * F10) * inverse_J;
                const double e00 = s00 * inverse_G + Ie,
                             e11 = s11 * inverse_G + Ie,
                             e22 = s22 * inverse_G + Ie, e01 = s01 * inverse_G,
                             e02 = s02 * inverse_G, e12 = s12 * inverse_G;
                // B = F^{-1} b_e, then B F^{-T}.
                const double B00 = G00 * e00 + G01 * e01 + G02 * e02,
                             B01 = G00 * e01 + G01 * e11 + G02 * e12,
                             B02 = G00 * e02 + G01 * e12 + G02 * e22,
                             B10 = G10 * e00 + G11 * e01 + G12 * e02,
                             B11 = G10 * e01 + G11 * e11 + G12 * e12,
                             B12 = G10 * e02 + G11 * e12 + G12 * e22,
                             B20 = G20 * e00 + G21 * e01 + G22 * e02,
                             B21 = G20 * e01 + G21 * e11 + G22 * e12,
                             B22 = G20 * e02 + G21 * e12 + G22 * e22;
                const double J_23 = 1. / J_m23[i];
                const double c[6] = {
                  J_23 * (B00 * G00 + B01 * G01 + B02 * G02),
                  J_23 * (B10 * G10 + B11 * G11 + B12 * G12),
                  J_23 * (B20 * G20 + B21 * G21 + B22 * G22),
                  J_23 * (B00 * G10 + B01 * G11 + B02 * G12),
                  J_23 * (B00 * G20 + B01 * G21 + B02 * G22),
                  J_23 * (B10 * G20 + B11 * G21 + B12 * G22)};
                for (std::size_t k = 0; k < 6; ++k)
                  Cp_inv_new[k * n + i] =
                    plastic ? c[k] : Cp_inv_old[k * n + i];
              }
          }
      }



      // The vectorised passes, each compiled for AVX2 and the baseline
      // (GCC clones the caller of an always_inline template, not the
      // template itself).
      RUBBERDYN_VECTOR_CLONES void
      trial_points(const bool   with_history,
                   const double G,
                   const double *__restrict F,
                   const double *__restrict Cp_inv,
                   double *__restrict J,
                   double *__restrict J_m23,
                   double *__restrict be,
                   double *__restrict Ie,
                   double *__restrict s_norm)
      {
        if (with_history)
          trial_points_loop<true>(G, F, Cp_inv, J, J_m23, be, Ie, s_norm);
        else
          trial_points_loop<false>(G, F, Cp_inv, J, J_m23, be, Ie, s_norm);
      }



      RUBBERDYN_VECTOR_CLONES void
      final_points(const bool   with_history,
                   const double G,
                   const double K,
                   const double inverse_density,
                   const double *__restrict F,
                   const double *__restrict J,
                   const double *__restrict J_m23,
                   const double *__restrict be,
                   const double *__restrict Ie,
                   const double *__restrict s_norm,
                   const double *__restrict delta_alpha,
                   const double *__restrict Cp_inv_old,
                   double *__restrict Cp_inv_new,
                   double *__restrict tau,
                   double *__restrict energy,
                   double *__restrict wave_speed)
      {
        if (with_history)
          final_points_loop<true>(G, K, inverse_density, F, J, J_m23, be, Ie,
                                  s_norm, delta_alpha, Cp_inv_old, Cp_inv_new,
                                  tau, energy, wave_speed);
        else
          final_points_loop<false>(G, K, inverse_density, F, J, J_m23, be, Ie,
                                   s_norm, delta_alpha, Cp_inv_old,
                                   Cp_inv_new, tau, energy, wave_speed);
      }
    } // namespace



    FiniteStrainJ2StressKernel::FiniteStrainJ2StressKernel(
      const finite_strain_j2::ElasticModuli &moduli,
      const HardeningCurve *                 hardening)
      : moduli(moduli)
    {
      if (hardening != nullptr)
        this->hardening.emplace(*hardening);
    }



    unsigned int
    FiniteStrainJ2StressKernel::evaluate(const unsigned int n_used,
                                         const double *     F,
                                         const double *     state_old,
                                         double *           state_new,
                                         double *           tau,
                                         double *           energy,
                                         double *           wave_speed) const
    {
      using namespace finite_strain_j2;
      AssertIndexRange(n_used, n + 1);
      const double G            = moduli.shear_modulus;
      const bool   with_history = hardening.has_value();
      constexpr unsigned int n_state = n_state_variables;

      // The history, in structure-of-arrays layout (stride n).
      alignas(64) double Cp_inv_old[6 * n], Cp_inv_new[6 * n];
      alignas(64) double alpha_old[n];
      if (with_history)
        for (std::size_t i = 0; i < n; ++i)
          {
            for (std::size_t k = 0; k < 6; ++k)
              Cp_inv_old[k * n + i] = state_old[i * n_state + k];
            alpha_old[i] =
              state_old[i * n_state + equivalent_plastic_strain_index];
          }

      alignas(64) double J[n], J_m23[n], be[6 * n], Ie[n], s_norm[n];
      // (The elastic law's passes never read the history arrays.)
      trial_points(with_history, G, F, with_history ? Cp_inv_old : nullptr,
                   J, J_m23, be, Ie, s_norm);

      // Pass 2: yield check and return mapping, point by point.
      alignas(64) double delta_alpha[n];
      double             dissipation_increment[n];
      for (std::size_t i = 0; i < n; ++i)
        {
          delta_alpha[i]           = 0.;
          dissipation_increment[i] = 0.;
        }
      if (with_history)
        {
          const double initial_yield_stress = hardening->yield_stress(0.);
          for (std::size_t i = 0; i < n; ++i)
            {
              const double q_trial = std::sqrt(1.5) * s_norm[i];
              // k(alpha) >= k(0): below the initial yield stress no lookup.
              if (q_trial > initial_yield_stress &&
                  q_trial > hardening->yield_stress(alpha_old[i]))
                {
                  delta_alpha[i] =
                    hardening->solve_return(q_trial, G * Ie[i], alpha_old[i]);
                  // Dissipation k(alpha_{n+1}) delta alpha (backward Euler).
                  if (delta_alpha[i] > 0.)
                    dissipation_increment[i] =
                      hardening->yield_stress(alpha_old[i] + delta_alpha[i]) *
                      delta_alpha[i];
                }
            }
        }

      final_points(with_history, G, moduli.bulk_modulus, 1. / moduli.density,
                   F, J, J_m23, be, Ie, s_norm, delta_alpha,
                   with_history ? Cp_inv_old : nullptr, Cp_inv_new, tau,
                   energy, wave_speed);

      if (with_history)
        for (std::size_t i = 0; i < n; ++i)
          {
            double *const new_i = state_new + i * n_state;
            for (std::size_t k = 0; k < 6; ++k)
              new_i[k] = Cp_inv_new[k * n + i];
            new_i[equivalent_plastic_strain_index] =
              alpha_old[i] + delta_alpha[i];
            new_i[plastic_dissipation_index] =
              state_old[i * n_state + plastic_dissipation_index] +
              dissipation_increment[i];
          }

      for (unsigned int i = 0; i < n_used; ++i)
        if (!(wave_speed[i] >= 0.))
          return i;
      return n_used;
    }
  } // namespace materials
} // namespace rubberdyn
