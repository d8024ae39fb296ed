// `Stable time step estimate = assembled` finds the assembled model's
// highest frequency of a system whose value is known in closed form: a
// column of n = 8 cubes of h = 2 mm of the shipped rubber (Yeoh, nu =
// 0.499, tests/model/model_fixtures.h), F-bar, every node held in y and z
// (all nodes lie on the lateral faces), the ends free. Its x motions whose
// four nodes of a cross-section move together are a chain of lumped masses
// m = rho h^3 (m/2 at the ends) and springs (lambda + 2 mu) h: uniaxial
// strain, uniform in each element, the F-bar centre and Gauss points alike.
// The free-free chain's frequencies are (2c/h) sin(k pi / (2n)), k = 0..n
// (the lumped-mass chain: Hughes, The Finite Element Method, ch. 9;
// Belytschko, Liu & Moran, Nonlinear Finite Elements for Continua and
// Structures, section 6.3): the largest, k = n, the mode
// u_i = (-1)^i, is omega_max = 2c/h with c^2 = (K + 4G/3)/rho, the law's
// wave speed at rest. A cross-section's other patterns change no element's
// centre volume (sum_a g0_a . u_a = 0) and are held by G = 2.2e-3 K only,
// far below. The element bound is 2 sqrt(3) c/h (doc/theory.md 8.3: l =
// h/sqrt(3) for a cube), sqrt(3) above.
//
// Checked: the estimate omega_est = sqrt(omega_squared()) within
// [1 - 1e-4, 1 + 5.5e-3] of 2c/h. From below: a Ritz value is a Rayleigh
// quotient (never above the largest eigenvalue), and the finite
// differences of the forces at a strain of 1e-8 are exact to about 1e-8;
// the lower tolerance is that round-off with room. From above: the
// estimate is theta + r with the residual r <= 1e-2 theta (the converged
// criterion), rounded up by at most 2^-11: sqrt(1.01) (1 + 2^-11) - 1 =
// 5.5e-3 on omega. And the step taken is 0.9 * 2 / omega_est to 1e-12
// (no bulk viscosity, no contact), the element bound's step times about
// sqrt(3).
#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_generator.h>

#include <rubberdyn/model/model.h>
#include <rubberdyn/postprocess/postprocessor.h>
#include <rubberdyn/simulation/explicit_simulation.h>
#include <rubberdyn/time_integration/explicit_solver.h>

#include <cmath>
#include <iomanip>
#include <sstream>

#include "../tests.h"
#include "model_fixtures.h"

using namespace dealii;
using namespace rubberdyn;
using testing::check;
using testing::out;
using testing::sci;

namespace
{
  /** The estimate and the step of the first step; stops after 3 steps. */
  class EstimateRecorder : public postprocess::Postprocessor
  {
  public:
    std::string
    name() const override
    {
      return "estimate recorder";
    }

    void
    after_step(const postprocess::SimulationView &view) override
    {
      const time_integration::ExplicitSolver &solver = *view.explicit_solver();
      if (steps == 0)
        {
          omega_squared = solver.assembled_step_estimate() != nullptr ?
                            solver.assembled_step_estimate()->omega_squared() :
                            0.;
          step          = solver.time_step();
        }
      ++steps;
    }

    bool
    stop_requested() const override
    {
      return steps >= 3;
    }

    unsigned int steps         = 0;
    double       omega_squared = 0.;
    double       step          = 0.;
  };
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                   comm = MPI_COMM_WORLD;
  const unsigned int               n    = 8;
  const double                     h    = 2.;

  model::Model model(comm);
  GridGenerator::subdivided_hyper_rectangle(model.triangulation,
                                            {n, 1, 1},
                                            Point<3>(0., 0., 0.),
                                            Point<3>(n * h, h, h));
  // The lateral faces (normal y or z): boundary id 1, held in y and z.
  for (const auto &cell : model.triangulation.active_cell_iterators())
    for (const unsigned int f : cell->face_indices())
      if (cell->at_boundary(f) && f >= 2)
        cell->face(f)->set_boundary_id(1);
  model::BoundaryCondition lateral;
  lateral.name         = "lateral";
  lateral.boundary_ids = {1};
  lateral.components   = {1, 2};
  model.boundary_conditions.push_back(lateral);
  model.parts.push_back(fixtures::rubber_part("rubber", 0));
  // A slow uniform x velocity: a rigid motion, no compression (Q = 0).
  model.parts.back().initial_velocity = Tensor<1, 3>({0.1, 0., 0.});
  model.setup();

  parameters::TimeIntegration time_integration;
  time_integration.end_time                 = 1e3; // ended by the recorder
  time_integration.assembled_step_estimate  = true;
  time_integration.bulk_viscosity_linear    = 0.;
  time_integration.bulk_viscosity_quadratic = 0.;
  parameters::Output output;
  output.directory               = "assembled_step_estimate";
  output.field_output_interval   = 0.;
  output.history_output_interval = 1e3;
  simulation::ExplicitSimulation simulation(model,
                                            time_integration,
                                            output,
                                            "Assembled step estimate",
                                            "assembled step estimate");
  auto                           plugin = std::make_unique<EstimateRecorder>();
  EstimateRecorder              &recorder = *plugin;
  simulation.add_standard_postprocessors();
  simulation.add_postprocessor(std::move(plugin));
  std::ostringstream log;
  simulation.run(log);

  // The reference: the law's small-strain moduli (model_fixtures.h).
  const double C10 = 0.00055, nu = 0.499, G = 2. * C10, rho = 1.1e-6;
  const double K             = 2. * G * (1. + nu) / (3. * (1. - 2. * nu));
  const double c             = std::sqrt((K + 4. / 3. * G) / rho);
  const double omega_ref     = 2. * c / h;
  const double omega_est     = std::sqrt(recorder.omega_squared);
  const double ratio         = omega_est / omega_ref;
  const double expected_step = 0.9 * 2. / omega_est;
  const double step_error =
    std::abs(recorder.step - expected_step) / expected_step;
  // The element bound's omega: 2 c / l, l = h / sqrt(3).
  const double element_step = 0.9 * h / std::sqrt(3.) / c;

  out() << "column of " << n << " cubes, F-bar: omega_est / (2c/h) within "
        << "[1 - 1e-4, 1 + 5.5e-3]: "
        << (ratio >= 1. - 1e-4 && ratio <= 1. + 5.5e-3 ? "yes" : "no")
        << std::endl;
  out() << "step = 0.9 * 2 / omega_est to 1e-12: "
        << (step_error <= 1e-12 ? "yes" : "no") << std::endl;
  out() << "step / element bound's step = " << std::fixed
        << std::setprecision(2) << recorder.step / element_step << std::endl;
  std::cerr << "omega_est " << omega_est << " 1/ms, 2c/h " << omega_ref
            << ", ratio " << std::setprecision(8) << ratio << ", step "
            << recorder.step << " ms, expected " << expected_step
            << ", element bound's step " << element_step << std::endl;
  check(ratio >= 1. - 1e-4 && ratio <= 1. + 5.5e-3,
        "omega_est / (2c/h) = " + sci(ratio) +
          ", outside [1 - 1e-4, 1 + 5.5e-3]");
  check(step_error <= 1e-12,
        "the step " + sci(recorder.step) +
          " ms is not 0.9 * 2 / omega_est = " + sci(expected_step) + " ms");
}
