#include <deal.II/base/parameter_handler.h>
#include <deal.II/physics/elasticity/standard_tensors.h>

#include <rubberdyn/base/exceptions.h>
#include <rubberdyn/base/parameter_tools.h>
#include <rubberdyn/materials/finite_strain_j2.h>
#include <rubberdyn/materials/hardening_curve.h>

#include <cmath>

namespace rubberdyn
{
  namespace materials
  {
    namespace finite_strain_j2
    {
      namespace
      {
        // Storage order of a symmetric 3x3 tensor in the history.
        constexpr unsigned int voigt_i[6] = {0, 1, 2, 0, 0, 1};
        constexpr unsigned int voigt_j[6] = {0, 1, 2, 1, 2, 2};

        SymmetricTensor<2, 3>
        read_symmetric(const ArrayView<const double> &state)
        {
          SymmetricTensor<2, 3> t;
          for (unsigned int c = 0; c < 6; ++c)
            t[voigt_i[c]][voigt_j[c]] = state[c];
          return t;
        }

        void
        write_symmetric(const SymmetricTensor<2, 3> &t,
                        const ArrayView<double> &    state)
        {
          for (unsigned int c = 0; c < 6; ++c)
            state[c] = t[voigt_i[c]][voigt_j[c]];
        }
      } // namespace



      ElasticModuli
      read_elastic_moduli(const ParameterHandler &prm, const std::string &path)
      {
        const double E   = prm.get_double("Young's modulus");
        const double nu  = prm.get_double("Poisson's ratio");
        const double rho = prm.get_double("Density");
        parameter_tools::require_positive(E, path + "/Young's modulus");
        parameter_tools::require_positive(rho, path + "/Density");
        if (!(nu >= 0. && nu < 0.5))
          throw InputError(path + "/Poisson's ratio",
                           "must lie in [0, 0.5), but is " +
                             parameter_tools::format_number(nu));
        return {E / (2. * (1. + nu)), E / (3. * (1. - 2. * nu)), rho};
      }



      double
      reference_wave_speed(const ElasticModuli &moduli)
      {
        return std::sqrt(
          (moduli.bulk_modulus + 4. / 3. * moduli.shear_modulus) /
          moduli.density);
      }



      std::vector<DerivedConstant>
      derived_constants(const ElasticModuli &moduli)
      {
        using parameter_tools::Sign;
        return {{"the density",
                 moduli.density,
                 "kg/mm^3",
                 {"Density"},
                 Sign::positive},
                {"the shear modulus G = E/(2(1 + nu))",
                 moduli.shear_modulus,
                 "GPa",
                 {"Young's modulus", "Poisson's ratio"},
                 Sign::positive},
                {"the bulk modulus K = E/(3(1 - 2 nu))",
                 moduli.bulk_modulus,
                 "GPa",
                 {"Young's modulus", "Poisson's ratio"},
                 Sign::positive},
                {"the dilatational wave speed sqrt((K + 4G/3)/density)",
                 reference_wave_speed(moduli),
                 "mm/ms",
                 {"Young's modulus", "Poisson's ratio", "Density"},
                 Sign::positive}};
      }



      void
      initialize_state(const ArrayView<double> &state)
      {
        AssertDimension(state.size(), n_state_variables);
        write_symmetric(unit_symmetric_tensor<3>(), state);
        state[equivalent_plastic_strain_index] = 0.;
        state[plastic_dissipation_index]       = 0.;
      }



      void
      update(const Tensor<2, 3> &           F,
             const double                   G,
             const double                   K,
             const double                   density,
             const HardeningCurve *         hardening,
             const ArrayView<const double> &state_old,
             const ArrayView<double> &      state_new,
             const bool                     compute_tangent,
             MaterialResponse<3> &          response)
      {
        using Tensors = Physics::Elasticity::StandardTensors<3>;

        const double J = determinant(F);
        if (!(J > 0.) || !std::isfinite(J))
          throw InvertedMaterialError(J);

        // Elastic trial state (Simo & Hughes Box 9.1, step 1).
        const Tensor<2, 3> F_bar = std::pow(J, -1. / 3.) * F;
        const SymmetricTensor<2, 3> Cp_inv_old =
          (state_old.size() == 0) ? unit_symmetric_tensor<3>() :
                              read_symmetric(state_old);
        const double alpha_old =
          (state_old.size() == 0) ? 0. : state_old[equivalent_plastic_strain_index];
        const SymmetricTensor<2, 3> be_trial = symmetrize(
          Tensor<2, 3>(F_bar * Tensor<2, 3>(Cp_inv_old) * transpose(F_bar)));
        const double                Ie_bar  = trace(be_trial) / 3.;
        const double                mu_bar  = G * Ie_bar;
        const SymmetricTensor<2, 3> s_trial = G * deviator(be_trial);
        const double                s_trial_norm = s_trial.norm();

        // Yield check and radial return (steps 2-4).
        double delta_alpha = 0.;
        if (hardening != nullptr)
          {
            const double q_trial = std::sqrt(1.5) * s_trial_norm;
            if (q_trial > hardening->yield_stress(alpha_old))
              delta_alpha = hardening->solve_return(q_trial, mu_bar, alpha_old);
          }
        const double delta_gamma = std::sqrt(1.5) * delta_alpha;
        const double beta_1 =
          (delta_alpha > 0. ? 2. * mu_bar * delta_gamma / s_trial_norm : 0.);
        const SymmetricTensor<2, 3> s = (1. - beta_1) * s_trial;

        // Stress: volumetric U = K/2 [ (J^2-1)/2 - ln J ], J U' = K/2 (J^2-1).
        const double tau_vol      = 0.5 * K * (J * J - 1.);
        response.kirchhoff_stress = tau_vol * Tensors::I + s;

        // Updated elastic state; stored energy and dissipation.
        const SymmetricTensor<2, 3> be_new =
          (delta_alpha > 0. ? s / G + Ie_bar * Tensors::I : be_trial);
        response.strain_energy_density =
          0.5 * K * (0.5 * (J * J - 1.) - std::log(J)) +
          0.5 * G * (trace(be_new) - 3.);
        // Longitudinal modulus of the elastic response, K + 4G/3 at F = I.
        response.dilatational_wave_speed = std::sqrt(
          (0.5 * K * (J * J + 1.) + 4. / 3. * mu_bar + s.norm()) / density);

        Assert((state_new.size() == 0) == (state_old.size() == 0),
               ExcMessage("old and new history must both be given or both "
                          "be empty"));
        if (!(state_new.size() == 0))
          {
            const double alpha_new = alpha_old + delta_alpha;
            const Tensor<2, 3> F_bar_inv = invert(F_bar);
            write_symmetric(symmetrize(Tensor<2, 3>(F_bar_inv *
                                                    Tensor<2, 3>(be_new) *
                                                    transpose(F_bar_inv))),
                            state_new);
            state_new[equivalent_plastic_strain_index] = alpha_new;
            // Dissipation k(alpha_{n+1}) * delta alpha (backward Euler).
            state_new[plastic_dissipation_index] =
              state_old[plastic_dissipation_index] +
              (delta_alpha > 0. ? hardening->yield_stress(alpha_new) *
                                    delta_alpha :
                                  0.);
          }

        if (compute_tangent)
          {
            // Volumetric part: (J U' + J^2 U'') I x I - 2 J U' II, with
            // J U' + J^2 U'' = K J^2.
            const SymmetricTensor<4, 3> c_vol =
              K * J * J * Tensors::IxI - 2. * tau_vol * Tensors::S;
            const SymmetricTensor<4, 3> c_dev_trial =
              2. * mu_bar * Tensors::dev_P -
              2. / 3. *
                (outer_product(s_trial, Tensors::I) +
                 outer_product(Tensors::I, s_trial));
            if (delta_alpha == 0.)
              response.spatial_tangent = c_vol + c_dev_trial;
            else
              {
                // Box 9.2, with the last term not symmetrised (the exact
                // linearisation; see doc/theory.md).
                const double H = hardening->slope(alpha_old + delta_alpha);
                const SymmetricTensor<2, 3> n = s_trial / s_trial_norm;
                const double beta_0 = 1. + H / (3. * mu_bar);
                const double beta_2 = (1. - 1. / beta_0) * 2. / 3. *
                                      s_trial_norm / mu_bar * delta_gamma;
                const double beta_3 = 1. / beta_0 - beta_1 + beta_2;
                const double beta_4 =
                  (1. / beta_0 - beta_1) * s_trial_norm / mu_bar;
                const SymmetricTensor<2, 3> dev_n_squared =
                  deviator(symmetrize(Tensor<2, 3>(n) * Tensor<2, 3>(n)));
                response.spatial_tangent =
                  c_vol + (1. - beta_1) * c_dev_trial -
                  2. * mu_bar * beta_3 * outer_product(n, n) -
                  2. * mu_bar * beta_4 * outer_product(n, dev_n_squared);
              }
          }
      }
    } // namespace finite_strain_j2
  }   // namespace materials
} // namespace rubberdyn
