// Cost of one material-point evaluation (ns), with and without the
// tangent, for each law, on one core. The explicit solver calls the
// stress-only variant 8 times per hexahedron per step, so this bounds the
// material share of the ns per element-cycle figure.
#include <rubberdyn/materials/elastic.h>
#include <rubberdyn/materials/hardening_curve.h>
#include <rubberdyn/materials/j2_plasticity.h>
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
}
