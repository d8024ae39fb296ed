#include <rubberdyn/base/exceptions.h>
#include <rubberdyn/materials/material_model.h>
#include <rubberdyn/materials/stress_kernel.h>

namespace rubberdyn
{
  namespace materials
  {
    template <int dim>
    unsigned int
    MaterialModel<dim>::n_state_variables() const
    {
      return 0;
    }



    template <int dim>
    void
    MaterialModel<dim>::initialize_state(const ArrayView<double> &) const
    {}



    template <int dim>
    double
    MaterialModel<dim>::equivalent_plastic_strain(
      const ArrayView<const double> &) const
    {
      return 0.;
    }



    template <int dim>
    std::unique_ptr<StressKernel>
    MaterialModel<dim>::create_stress_kernel() const
    {
      return nullptr;
    }



    template <int dim>
    void
    check_derived_constants(const MaterialModel<dim> &law,
                            const std::string        &path)
    {
      for (const DerivedConstant &constant : law.derived_constants())
        {
          Assert(!constant.entries.empty(),
                 ExcMessage("a derived constant must name its entries"));
          // "'Poisson's ratio' and 'Density'"
          std::string others;
          for (unsigned int i = 1; i < constant.entries.size(); ++i)
            others += std::string(i == 1                           ? "'" :
                                  i + 1 == constant.entries.size() ? " and '" :
                                                                     ", '") +
                      constant.entries[i] + "'";
          parameter_tools::require_usable(constant.value,
                                          path + "/" + constant.entries[0],
                                          constant.what,
                                          constant.unit,
                                          constant.sign,
                                          others);
        }
    }



    namespace internal
    {
      template <int dim>
      Tensor<2, 3>
      embed_in_3d(const Tensor<2, dim> &F)
      {
        Tensor<2, 3> F3;
        for (unsigned int i = 0; i < 3; ++i)
          F3[i][i] = 1.;
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            F3[i][j] = F[i][j];
        return F3;
      }



      template <int dim>
      void
      restrict_from_3d(const MaterialResponse<3> &response_3d,
                       const bool                 with_tangent,
                       MaterialResponse<dim> &    response)
      {
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = i; j < dim; ++j)
            response.kirchhoff_stress[i][j] =
              response_3d.kirchhoff_stress[i][j];
        if (with_tangent)
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int j = i; j < dim; ++j)
              for (unsigned int k = 0; k < dim; ++k)
                for (unsigned int l = k; l < dim; ++l)
                  response.spatial_tangent[i][j][k][l] =
                    response_3d.spatial_tangent[i][j][k][l];
        response.strain_energy_density = response_3d.strain_energy_density;
        response.dilatational_wave_speed =
          response_3d.dilatational_wave_speed;
      }



      template <int dim>
      Tensor<2, dim>
      kirchhoff_stress_derivative(const MaterialResponse<dim> &response,
                                  const Tensor<2, dim> &       F,
                                  const Tensor<2, dim> &       dF)
      {
        const Tensor<2, dim> l = dF * invert(F);
        const Tensor<2, dim> tau(response.kirchhoff_stress);
        return Tensor<2, dim>(response.spatial_tangent * symmetrize(l)) +
               l * tau + tau * transpose(l);
      }
    } // namespace internal


    template class MaterialModel<2>;
    template class MaterialModel<3>;
    template void
    check_derived_constants<2>(const MaterialModel<2> &, const std::string &);
    template void
    check_derived_constants<3>(const MaterialModel<3> &, const std::string &);

    namespace internal
    {
      template Tensor<2, 3>
      embed_in_3d<2>(const Tensor<2, 2> &);
      template Tensor<2, 3>
      embed_in_3d<3>(const Tensor<2, 3> &);
      template void
      restrict_from_3d<2>(const MaterialResponse<3> &,
                          const bool,
                          MaterialResponse<2> &);
      template void
      restrict_from_3d<3>(const MaterialResponse<3> &,
                          const bool,
                          MaterialResponse<3> &);
      template Tensor<2, 2>
      kirchhoff_stress_derivative<2>(const MaterialResponse<2> &,
                                     const Tensor<2, 2> &,
                                     const Tensor<2, 2> &);
      template Tensor<2, 3>
      kirchhoff_stress_derivative<3>(const MaterialResponse<3> &,
                                     const Tensor<2, 3> &,
                                     const Tensor<2, 3> &);
    } // namespace internal
  }   // namespace materials
} // namespace rubberdyn
