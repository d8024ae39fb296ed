#ifndef rubberdyn_materials_elastic_h
#define rubberdyn_materials_elastic_h

#include <rubberdyn/materials/isotropic_metal.h>

namespace rubberdyn
{
  namespace materials
  {
    /**
     * Elastic metal (or plastic) for small elastic strains under large
     * rotations: the decoupled compressible neo-Hookean law of
     * finite_strain_j2 without yielding, from Young's modulus and Poisson's
     * ratio. It is identical to `J2 plasticity` below its yield stress.
     */
    template <int dim>
    class Elastic : public IsotropicMetal<dim>
    {
    public:
      /** Read the constants from the current subsection (path @p path). */
      Elastic(const ParameterHandler &prm, const std::string &path);

      /** Construct from E (GPa), nu and the density (kg/mm^3). */
      Elastic(const double youngs_modulus,
              const double poissons_ratio,
              const double density);

      /** No entries beyond the shared ones (E, nu, density). */
      static void
      declare_parameters(ParameterHandler &prm);

      std::string
      name() const override;

      void
      evaluate(const Tensor<2, dim> &         F,
               const ArrayView<const double> &state_old,
               const ArrayView<double> &      state_new,
               const bool                     compute_tangent,
               MaterialResponse<dim> &        response) const override;

      void
      print_constants(std::ostream &out) const override;

      /** A FiniteStrainJ2StressKernel with this law's constants. */
      std::unique_ptr<StressKernel>
      create_stress_kernel() const override;

    private:
      using IsotropicMetal<dim>::moduli;
    };
  } // namespace materials
} // namespace rubberdyn

#endif
