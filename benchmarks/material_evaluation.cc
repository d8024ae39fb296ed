// Cost of one material-point evaluation (ns), with and without the
// tangent, for each law, on one core. The explicit solver calls the
// stress-only variant 8 times per hexahedron per step, so this bounds the
// material share of the ns per element-cycle figure. Then the batched Yeoh
// kernel that the explicit elements use, per point, for each volumetric
// function.
#include <rubberdyn/materials/elastic.h>
#include <rubberdyn/materials/hardening_curve.h>
#include <rubberdyn/materials/j2_plasticity.h>
#include <rubberdyn/materials/stress_kernel.h>
#include <rubberdyn/materials/yeoh.h>

#include <chrono>
#include <iomanip>
#include <iostream>
#include <memory>
#include <vector>

using namespace dealii;
using namespace rubberdyn::materials;

int
main()
{
  const std::vector<std::pair<std::string, std::shared_ptr<MaterialModel<3>>>>
    laws = {{"Yeoh", std::make_shared<Yeoh<3>>(
                       0.55e-3, -0.05e-3, 0.015e-3,
                       std::array<double, 3>{{3.6, 0., 0.}}, 1.1e-6)},
            {"Elastic", std::make_shared<Elastic<3>>(210., 0.3, 7.85e-6)},
            {"J2 plasticity",
             std::make_shared<J2Plasticity<3>>(
               210., 0.3, 7.85e-6,
               HardeningCurve(0.94, {0.08}, {1.04}, "benchmark"))}};

  const unsigned int n = 2000000;
  std::cout << "law, ns per evaluation (stress only), ns per evaluation "
               "(stress and tangent)\n";
  for (const auto &law : laws)
    {
      std::vector<double> state_old(law.second->n_state_variables()),
        state_new(law.second->n_state_variables());
      law.second->initialize_state(make_array_view(state_old));
      double timings[2];
      double sink = 0.;
      for (const bool tangent : {false, true})
        {
          const auto start = std::chrono::steady_clock::now();
          for (unsigned int i = 0; i < n; ++i)
            {
              Tensor<2, 3> F;
              F[0][0] = 1.01 + 1e-9 * (i % 100);
              F[1][1] = F[2][2] = 0.995;
              F[0][1]           = 0.01;
              MaterialResponse<3> response;
              law.second->evaluate(F,
                                   make_array_view(std::as_const(state_old)),
                                   make_array_view(state_new),
                                   tangent,
                                   response);
              sink += response.kirchhoff_stress[0][0];
            }
          timings[tangent] =
            std::chrono::duration<double, std::nano>(
              std::chrono::steady_clock::now() - start)
              .count() /
            n;
        }
      std::cout << law.first << ", " << std::setprecision(3) << timings[0]
                << ", " << timings[1] << (sink == 0.123 ? " " : "") << "\n";
    }

  constexpr unsigned int N = StressKernel::batch_size;
  std::cout << "\nbatched Yeoh kernel, volumetric function, ns per point\n";
  std::vector<double> F(9 * N), tau(6 * N), energy(N), wave_speed(N);
  for (unsigned int i = 0; i < N; ++i)
    {
      F[0 * N + i] = 1.01 + 1e-3 * i;
      F[4 * N + i] = F[8 * N + i] = 0.995;
      F[1 * N + i]                = 0.01;
    }
  for (const VolumetricFunction function : {VolumetricFunction::polynomial,
                                            VolumetricFunction::log_squared,
                                            VolumetricFunction::simo_taylor})
    {
      const Yeoh<3>      law(0.55e-3,
                        -0.05e-3,
                        0.015e-3,
                        std::array<double, 3>{{3.6, 0., 0.}},
                        1.1e-6,
                        function);
      const auto         kernel  = create_stress_kernel(law);
      const unsigned int batches = 200000;
      double             sink    = 0.;
      const auto         start   = std::chrono::steady_clock::now();
      for (unsigned int b = 0; b < batches; ++b)
        {
          F[0] += 1e-12;
          kernel->evaluate(N,
                           F.data(),
                           nullptr,
                           nullptr,
                           tau.data(),
                           energy.data(),
                           wave_speed.data());
          sink += tau[0];
        }
      const double ns = std::chrono::duration<double, std::nano>(
                          std::chrono::steady_clock::now() - start)
                          .count() /
                        (double(batches) * N);
      std::cout << volumetric_function_name(function) << ", "
                << std::setprecision(3) << ns << (sink == 0.123 ? " " : "")
                << "\n";
    }
}
