#ifndef rubberdyn_materials_finite_strain_j2_h
#define rubberdyn_materials_finite_strain_j2_h

#include <rubberdyn/materials/material_model.h>

namespace dealii
{
  class ParameterHandler;
}

namespace rubberdyn
{
  namespace materials
  {
    class HardeningCurve;

    /**
     * The stress update of finite-strain J2 plasticity after Simo (1988),
     * in the form of Simo & Hughes, Computational Inelasticity (1998),
     * Boxes 9.1 and 9.2, shared by the `Elastic` and `J2 plasticity` laws.
     *
     * Elastic response (decoupled compressible neo-Hooke in the elastic
     * left Cauchy-Green tensor $\bar b_e$):
     * @f[
     *   W = \tfrac{K}{2}\left[\tfrac12 (J^2 - 1) - \ln J\right]
     *     + \tfrac{G}{2} (\mathrm{tr}\,\bar b_e - 3),
     *   \qquad \tau = \tfrac{K}{2} (J^2 - 1) I + G\,\mathrm{dev}\,\bar b_e .
     * @f]
     * At small strain it is Hooke's law with the same $G$ and $K$ (so with
     * Young's modulus and Poisson's ratio as given); unlike St.
     * Venant-Kirchhoff it does not soften in compression, and it is exact
     * under large rotations, which the bolt and sleeves see.
     *
     * History: the isochoric plastic metric $\bar C_p^{-1}$ and the
     * equivalent plastic strain $\alpha$, so that the trial state
     * $\bar b_e^{tr} = \bar F \bar C_p^{-1} \bar F^T$ needs only the current
     * deformation gradient. Yield function $f = \|s\| - \sqrt{2/3}\,
     * k(\alpha)$, $s = \mathrm{dev}\,\tau$; radial return with the exact
     * solution of the piecewise-linear hardening equation; the algorithmic
     * tangent is the exact linearisation (not symmetrised).
     */
    namespace finite_strain_j2
    {
      /**
       * Number of history variables: $\bar C_p^{-1}$ (6), $\alpha$ and the
       * accumulated plastic dissipation per unit reference volume (GPa).
       */
      constexpr unsigned int n_state_variables = 8;

      /** Index of the equivalent plastic strain in the history. */
      constexpr unsigned int equivalent_plastic_strain_index = 6;

      /** Index of the accumulated plastic dissipation in the history. */
      constexpr unsigned int plastic_dissipation_index = 7;

      /** Small-strain elastic moduli of a metal. */
      struct ElasticModuli
      {
        /** Shear modulus G (GPa). */
        double shear_modulus;
        /** Bulk modulus K (GPa). */
        double bulk_modulus;
        /** Reference density (kg/mm^3). */
        double density;
      };

      /**
       * Read `Young's modulus`, `Poisson's ratio` and `Density` from the
       * current subsection (full path @p path) and convert them.
       *
       * @throws InputError if E <= 0, nu is outside [0, 0.5) or the density
       *   is not positive.
       */
      ElasticModuli
      read_elastic_moduli(const ParameterHandler &prm, const std::string &path);

      /**
       * The derived constants of the elastic part (see
       * MaterialModel::derived_constants()): the density, G and K from
       * `Young's modulus` and `Poisson's ratio`, and the wave speed
       * $\sqrt{(K + \tfrac43 G)/\rho}$.
       */
      std::vector<DerivedConstant>
      derived_constants(const ElasticModuli &moduli);

      /** The wave speed $\sqrt{(K + \tfrac43 G)/\rho}$ (mm/ms). */
      double
      reference_wave_speed(const ElasticModuli &moduli);

      /** History of a virgin point: $\bar C_p^{-1} = I$, $\alpha = 0$. */
      void
      initialize_state(const ArrayView<double> &state);

      /**
       * The 3D update.
       *
       * @param F Deformation gradient at the end of the step.
       * @param shear_modulus G (GPa).
       * @param bulk_modulus K (GPa).
       * @param density Reference density (kg/mm^3), for the wave speed.
       * @param hardening Yield curve, or nullptr for a purely elastic law.
       * @param state_old History at the start of the step, or an empty
       *   view for the elastic law.
       * @param state_new History at the end of the step (written unless
       *   empty).
       * @param compute_tangent Whether to fill the tangent.
       * @param response Result.
       */
      void
      update(const Tensor<2, 3> &           F,
             const double                   shear_modulus,
             const double                   bulk_modulus,
             const double                   density,
             const HardeningCurve *         hardening,
             const ArrayView<const double> &state_old,
             const ArrayView<double> &      state_new,
             const bool                     compute_tangent,
             MaterialResponse<3> &          response);
    } // namespace finite_strain_j2
  }   // namespace materials
} // namespace rubberdyn

#endif
