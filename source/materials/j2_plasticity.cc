#include <deal.II/base/parameter_handler.h>

#include <rubberdyn/base/parameter_tools.h>
#include <rubberdyn/materials/j2_plasticity.h>
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
    J2Plasticity<dim>::J2Plasticity(const ParameterHandler &prm,
                                    const std::string &     path)
      : IsotropicMetal<dim>(finite_strain_j2::read_elastic_moduli(prm, path))
      , hardening(HardeningCurve::parse(prm.get_double("Yield stress"),
                                        prm.get("Hardening curve"),
                                        path))
    {}



    template <int dim>
    J2Plasticity<dim>::J2Plasticity(const double          youngs_modulus,
                                    const double          poissons_ratio,
                                    const double          density,
                                    const HardeningCurve &hardening)
      : IsotropicMetal<dim>(
          IsotropicMetal<dim>::moduli_of(youngs_modulus,
                                         poissons_ratio,
                                         density))
      , hardening(hardening)
    {}



    template <int dim>
    void
    J2Plasticity<dim>::declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("Yield stress",
                        "0.94",
                        Patterns::Double(0.),
                        "(J2 plasticity) Initial uniaxial yield stress "
                        "(GPa). Bolt grade 10.9: 0.94.");
      prm.declare_entry(
        "Hardening curve",
        "0.08:1.04",
        Patterns::Anything(),
        "(J2 plasticity) Piecewise-linear isotropic hardening after the "
        "yield stress, as 'plastic strain:yield stress' points (-, GPa) "
        "separated by commas, e.g. '0.02:1.0, 0.08:1.04'. Plastic strains "
        "strictly increasing and positive, stresses not decreasing; the "
        "last slope continues past the table; empty for perfect "
        "plasticity.");
    }



    template <int dim>
    std::string
    J2Plasticity<dim>::name() const
    {
      return "J2 plasticity";
    }



    template <int dim>
    unsigned int
    J2Plasticity<dim>::n_state_variables() const
    {
      return finite_strain_j2::n_state_variables;
    }



    template <int dim>
    void
    J2Plasticity<dim>::initialize_state(const ArrayView<double> &state) const
    {
      finite_strain_j2::initialize_state(state);
    }



    template <int dim>
    double
    J2Plasticity<dim>::equivalent_plastic_strain(
      const ArrayView<const double> &state) const
    {
      AssertDimension(state.size(), finite_strain_j2::n_state_variables);
      return state[finite_strain_j2::equivalent_plastic_strain_index];
    }



    template <int dim>
    std::vector<DerivedConstant>
    J2Plasticity<dim>::derived_constants() const
    {
      using parameter_tools::Sign;
      std::vector<DerivedConstant> constants =
        IsotropicMetal<dim>::derived_constants();
      const double H = hardening.largest_slope();
      constants.push_back({"the initial yield stress",
                           hardening.yield_stress(0.),
                           "GPa",
                           {"Yield stress"},
                           Sign::positive});
      constants.push_back({"the steepest hardening slope H",
                           H,
                           "GPa",
                           {"Hardening curve"},
                           Sign::non_negative});
      constants.push_back({"the return mapping's 3G + H",
                           3. * moduli.shear_modulus + H,
                           "GPa",
                           {"Hardening curve", "Young's modulus"},
                           Sign::positive});
      return constants;
    }



    template <int dim>
    void
    J2Plasticity<dim>::print_constants(std::ostream &out) const
    {
      out << "J2 plasticity: G = " << format_short(moduli.shear_modulus)
          << " GPa, K = " << format_short(moduli.bulk_modulus)
          << " GPa, density = " << format_short(moduli.density)
          << " kg/mm^3, hardening (plastic strain:GPa) = "
          << hardening.to_string() << std::endl;
    }



    template <int dim>
    void
    J2Plasticity<dim>::evaluate(const Tensor<2, dim> &         F,
                                const ArrayView<const double> &state_old,
                                const ArrayView<double> &      state_new,
                                const bool                     compute_tangent,
                                MaterialResponse<dim> &        response) const
    {
      MaterialResponse<3> response_3d;
      finite_strain_j2::update(internal::embed_in_3d(F),
                               moduli.shear_modulus,
                               moduli.bulk_modulus,
                               moduli.density,
                               &hardening,
                               state_old,
                               state_new,
                               compute_tangent,
                               response_3d);
      internal::restrict_from_3d(response_3d, compute_tangent, response);
    }

    template <int dim>
    std::unique_ptr<StressKernel>
    J2Plasticity<dim>::create_stress_kernel() const
    {
      return std::make_unique<FiniteStrainJ2StressKernel>(moduli, &hardening);
    }

    template class J2Plasticity<2>;
    template class J2Plasticity<3>;

    RUBBERDYN_REGISTER_MATERIAL(
      J2Plasticity,
      "J2 plasticity",
      "finite-strain von Mises plasticity (Simo 1988) with piecewise-linear "
      "isotropic hardening, elastic part as 'Elastic'")
  } // namespace materials
} // namespace rubberdyn
