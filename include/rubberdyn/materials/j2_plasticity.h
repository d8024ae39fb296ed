#ifndef rubberdyn_materials_j2_plasticity_h
#define rubberdyn_materials_j2_plasticity_h

#include <rubberdyn/materials/hardening_curve.h>
#include <rubberdyn/materials/isotropic_metal.h>

namespace rubberdyn
{
  namespace materials
  {
    /**
     * Finite-strain J2 (von Mises) plasticity with isotropic,
     * piecewise-linear hardening, for the bolt, sleeves and sheet metal:
     * the multiplicative model of Simo (1988) described in
     * finite_strain_j2, with the elastic law of `Elastic`.
     */
    template <int dim>
    class J2Plasticity : public IsotropicMetal<dim>
    {
    public:
      /** Read the constants from the current subsection (path @p path). */
      J2Plasticity(const ParameterHandler &prm, const std::string &path);

      /** Construct from E (GPa), nu, the density and the hardening curve. */
      J2Plasticity(const double          youngs_modulus,
                   const double          poissons_ratio,
                   const double          density,
                   const HardeningCurve &hardening);

      /** Declare `Yield stress` and `Hardening curve`. */
      static void
      declare_parameters(ParameterHandler &prm);

      std::string
      name() const override;

      unsigned int
      n_state_variables() const override;

      void
      initialize_state(const ArrayView<double> &state) const override;

      /** The history's $\alpha$ (finite_strain_j2). */
      double
      equivalent_plastic_strain(
        const ArrayView<const double> &state) const override;

      void
      evaluate(const Tensor<2, dim> &         F,
               const ArrayView<const double> &state_old,
               const ArrayView<double> &      state_new,
               const bool                     compute_tangent,
               MaterialResponse<dim> &        response) const override;

      /**
       * The elastic constants (see finite_strain_j2::derived_constants()),
       * the yield stress, the steepest hardening slope H and the return
       * mapping's denominator 3G + H.
       */
      std::vector<DerivedConstant>
      derived_constants() const override;

      void
      print_constants(std::ostream &out) const override;

      /** A FiniteStrainJ2StressKernel with this law's constants. */
      std::unique_ptr<StressKernel>
      create_stress_kernel() const override;

    private:
      using IsotropicMetal<dim>::moduli;
      HardeningCurve                  hardening;
    };
  } // namespace materials
} // namespace rubberdyn

#endif
