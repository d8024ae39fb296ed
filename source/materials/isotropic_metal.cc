#include <rubberdyn/materials/isotropic_metal.h>

namespace rubberdyn
{
  namespace materials
  {
    template <int dim>
    IsotropicMetal<dim>::IsotropicMetal(
      const finite_strain_j2::ElasticModuli &moduli)
      : moduli(moduli)
    {}



    template <int dim>
    finite_strain_j2::ElasticModuli
    IsotropicMetal<dim>::moduli_of(const double youngs_modulus,
                                   const double poissons_ratio,
                                   const double density)
    {
      return {youngs_modulus / (2. * (1. + poissons_ratio)),
              youngs_modulus / (3. * (1. - 2. * poissons_ratio)),
              density};
    }



    template <int dim>
    double
    IsotropicMetal<dim>::density() const
    {
      return moduli.density;
    }



    template <int dim>
    double
    IsotropicMetal<dim>::shear_modulus() const
    {
      return moduli.shear_modulus;
    }



    template <int dim>
    double
    IsotropicMetal<dim>::bulk_modulus() const
    {
      return moduli.bulk_modulus;
    }



    template <int dim>
    double
    IsotropicMetal<dim>::reference_wave_speed() const
    {
      return finite_strain_j2::reference_wave_speed(moduli);
    }



    template <int dim>
    std::vector<DerivedConstant>
    IsotropicMetal<dim>::derived_constants() const
    {
      return finite_strain_j2::derived_constants(moduli);
    }



    template class IsotropicMetal<2>;
    template class IsotropicMetal<3>;
  } // namespace materials
} // namespace rubberdyn
