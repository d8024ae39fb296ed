#include <deal.II/base/parameter_handler.h>

#include <rubberdyn/base/parameter_tools.h>
#include <rubberdyn/materials/elastic.h>
#include <rubberdyn/materials/finite_strain_j2_stress_kernel.h>
#include <rubberdyn/materials/material_registry.h>

#include <cmath>
#include <ostream>

namespace rubberdyn
{
  namespace materials
  {
    using parameter_tools::format_number;
    using parameter_tools::format_short;

    template <int dim>
    Elastic<dim>::Elastic(const ParameterHandler &prm, const std::string &path)
      : IsotropicMetal<dim>(finite_strain_j2::read_elastic_moduli(prm, path))
    {}



    template <int dim>
    Elastic<dim>::Elastic(const double youngs_modulus,
                          const double poissons_ratio,
                          const double density)
      : IsotropicMetal<dim>(
          IsotropicMetal<dim>::moduli_of(youngs_modulus,
                                         poissons_ratio,
                                         density))
    {}



    template <int dim>
    void
    Elastic<dim>::declare_parameters(ParameterHandler &)
    {}



    template <int dim>
    std::string
    Elastic<dim>::name() const
    {
      return "Elastic";
    }



    template <int dim>
    void
    Elastic<dim>::print_constants(std::ostream &out) const
    {
      out << "Elastic: G = " << format_short(moduli.shear_modulus)
          << " GPa, K = " << format_short(moduli.bulk_modulus)
          << " GPa, density = " << format_short(moduli.density)
          << " kg/mm^3, wave speed = " << format_short(this->reference_wave_speed())
          << " mm/ms" << std::endl;
    }



    template <int dim>
    void
    Elastic<dim>::evaluate(const Tensor<2, dim> &F,
                           const ArrayView<const double> &,
                           const ArrayView<double> &,
                           const bool             compute_tangent,
                           MaterialResponse<dim> &response) const
    {
      MaterialResponse<3> response_3d;
      finite_strain_j2::update(internal::embed_in_3d(F),
                               moduli.shear_modulus,
                               moduli.bulk_modulus,
                               moduli.density,
                               nullptr,
                               {},
                               {},
                               compute_tangent,
                               response_3d);
      internal::restrict_from_3d(response_3d, compute_tangent, response);
    }

    template <int dim>
    std::unique_ptr<StressKernel>
    Elastic<dim>::create_stress_kernel() const
    {
      return std::make_unique<FiniteStrainJ2StressKernel>(moduli, nullptr);
    }

    template class Elastic<2>;
    template class Elastic<3>;

    RUBBERDYN_REGISTER_MATERIAL(
      Elastic,
      "Elastic",
      "elastic metal or plastic: compressible neo-Hooke in the form of Simo "
      "& Hughes (1998), Hooke's law at small strain, from 'Young's modulus' "
      "and 'Poisson's ratio'")
  } // namespace materials
} // namespace rubberdyn
