// Every law refuses an inverted material point (det F <= 0) with the
// specific InvertedMaterialError that solvers catch and report, and never
// returns NaNs. Checked for det F = 0, det F < 0 (a reflection) and a NaN
// entry, in 3D and in plane strain; Yeoh with each volumetric function
// (the logarithmic ones must not take the log of a non-positive J).
#include <rubberdyn/base/exceptions.h>
#include <rubberdyn/materials/elastic.h>
#include <rubberdyn/materials/hardening_curve.h>
#include <rubberdyn/materials/j2_plasticity.h>
#include <rubberdyn/materials/yeoh.h>

#include <limits>
#include <memory>
#include <vector>

#include "../tests.h"

using namespace dealii;
using namespace rubberdyn::materials;
using testing::check;
using testing::out;

template <int dim>
void
run()
{
  std::vector<std::pair<std::string, std::shared_ptr<MaterialModel<dim>>>>
    laws = {{"Yeoh",
             std::make_shared<Yeoh<dim>>(0.55e-3,
                                         -0.05e-3,
                                         0.015e-3,
                                         std::array<double, 3>{{3.6, 0., 0.}},
                                         1.1e-6)},
            {"Yeoh, log squared",
             std::make_shared<Yeoh<dim>>(0.55e-3,
                                         -0.05e-3,
                                         0.015e-3,
                                         std::array<double, 3>{{3.6, 0., 0.}},
                                         1.1e-6,
                                         VolumetricFunction::log_squared)},
            {"Yeoh, Simo-Taylor",
             std::make_shared<Yeoh<dim>>(0.55e-3,
                                         -0.05e-3,
                                         0.015e-3,
                                         std::array<double, 3>{{3.6, 0., 0.}},
                                         1.1e-6,
                                         VolumetricFunction::simo_taylor)},
            {"Elastic", std::make_shared<Elastic<dim>>(210., 0.3, 7.85e-6)},
            {"J2 plasticity",
             std::make_shared<J2Plasticity<dim>>(
               210.,
               0.3,
               7.85e-6,
               HardeningCurve(0.94, {}, {}, "test"))}};

  std::vector<std::pair<std::string, Tensor<2, dim>>> gradients;
  Tensor<2, dim> F;
  for (unsigned int i = 0; i < dim; ++i)
    F[i][i] = 1.;
  F[0][0] = 0.;
  gradients.emplace_back("det F = 0", F);
  F[0][0] = -0.5;
  gradients.emplace_back("det F < 0", F);
  F[0][0] = std::numeric_limits<double>::quiet_NaN();
  gradients.emplace_back("NaN entry", F);

  for (const auto &law : laws)
    for (const auto &gradient : gradients)
      {
        std::vector<double> state_old(law.second->n_state_variables()),
          state_new(law.second->n_state_variables());
        law.second->initialize_state(make_array_view(state_old));
        bool thrown = false;
        try
          {
            MaterialResponse<dim> response;
            law.second->evaluate(gradient.second,
                                 make_array_view(std::as_const(state_old)),
                                 make_array_view(state_new),
                                 true,
                                 response);
          }
        catch (const rubberdyn::InvertedMaterialError &)
          {
            thrown = true;
          }
        out() << "dim " << dim << ", " << law.first << ", "
              << gradient.first << ": "
              << (thrown ? "InvertedMaterialError" : "NO EXCEPTION")
              << std::endl;
        check(thrown, law.first + " must throw for " + gradient.first);
      }
}

int
main()
{
  run<3>();
  run<2>();
}
