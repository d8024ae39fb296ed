#include <rubberdyn/base/exceptions.h>
#include <rubberdyn/materials/stress_kernel.h>

namespace rubberdyn
{
  namespace materials
  {
    PointwiseStressKernel::PointwiseStressKernel(const MaterialModel<3> &law)
      : law(law)
    {}



    unsigned int
    PointwiseStressKernel::evaluate(const unsigned int n,
                                    const double *     F,
                                    const double *     state_old,
                                    double *           state_new,
                                    double *           tau,
                                    double *           energy,
                                    double *           wave_speed) const
    {
      constexpr unsigned int row[6] = {0, 1, 2, 0, 0, 1};
      constexpr unsigned int col[6] = {0, 1, 2, 1, 2, 2};
      AssertIndexRange(n, batch_size + 1);
      const unsigned int     n_state = law.n_state_variables();
      MaterialResponse<3>    response;
      for (unsigned int i = 0; i < n; ++i)
        {
          Tensor<2, 3> F_i;
          for (unsigned int r = 0; r < 3; ++r)
            for (unsigned int c = 0; c < 3; ++c)
              F_i[r][c] = F[(3 * r + c) * batch_size + i];
          try
            {
              law.evaluate(F_i,
                           ArrayView<const double>(state_old + i * n_state,
                                                   n_state),
                           ArrayView<double>(state_new + i * n_state, n_state),
                           false,
                           response);
            }
          catch (const InvertedMaterialError &)
            {
              return i;
            }
          for (unsigned int k = 0; k < 6; ++k)
            tau[k * batch_size + i] = response.kirchhoff_stress[row[k]][col[k]];
          energy[i]     = response.strain_energy_density;
          wave_speed[i] = response.dilatational_wave_speed;
        }
      return n;
    }



    std::unique_ptr<StressKernel>
    create_stress_kernel(const MaterialModel<3> &law)
    {
      std::unique_ptr<StressKernel> kernel = law.create_stress_kernel();
      if (!kernel)
        kernel = std::make_unique<PointwiseStressKernel>(law);
      return kernel;
    }
  } // namespace materials
} // namespace rubberdyn
