#ifndef rubberdyn_materials_isotropic_metal_h
#define rubberdyn_materials_isotropic_metal_h

#include <rubberdyn/materials/finite_strain_j2.h>
#include <rubberdyn/materials/material_model.h>

namespace rubberdyn
{
  namespace materials
  {
    /**
     * What the metal laws (`Elastic`, `J2 plasticity`) share: the elastic
     * moduli G, K and the density of finite_strain_j2, and what follows
     * from them alone (the wave speed, the derived constants). The laws
     * add their name, their evaluation and, for plasticity, the hardening.
     */
    template <int dim>
    class IsotropicMetal : public MaterialModel<dim>
    {
    public:
      /** The density (kg/mm^3). */
      double
      density() const override;

      /** G (GPa). */
      double
      shear_modulus() const override;

      /** K (GPa). */
      double
      bulk_modulus() const override;

      /** The dilatational wave speed sqrt((K + 4 G / 3) / rho) (mm/ms). */
      double
      reference_wave_speed() const override;

      /** The density, G, K and the wave speed (see
       * finite_strain_j2::derived_constants()). */
      std::vector<DerivedConstant>
      derived_constants() const override;

    protected:
      /** The law of the moduli @p moduli. */
      explicit IsotropicMetal(const finite_strain_j2::ElasticModuli &moduli);

      /**
       * The moduli from Young's modulus @p youngs_modulus (GPa), Poisson's
       * ratio @p poissons_ratio (-) and the @p density (kg/mm^3).
       */
      static finite_strain_j2::ElasticModuli
      moduli_of(const double youngs_modulus,
                const double poissons_ratio,
                const double density);

      finite_strain_j2::ElasticModuli moduli;
    };
  } // namespace materials
} // namespace rubberdyn

#endif
