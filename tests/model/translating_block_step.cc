// A body that only translates has a constant stable step (issue
// "Reliability of the explicit engine"): the linear bulk viscosity, which
// lowers the step by about C_l = 6 %, must not switch on for the round-off
// of the volumetric rate div v of a uniform velocity field (about 1e-17
// 1/ms here), only for a rate that matters against the element's
// frequency c / l (the threshold |div v| l / c >= 1e-10 of
// source/elements/solid_hex_forces.cc; doc/theory.md section 8.3).
//
// The model: the distorted 16 x 12 x 6 mm rubber block of
// stable_step_energy.cc (144 hexahedra, interior vertices moved by up to
// 0.3 mm), falling freely under gravity from (1.3, -0.7, 2.1) mm/ms (the
// accelerations f / m = m g / m differ from g by round-off from node to
// node, so that the velocity field is uniform up to round-off), with the
// default bulk viscosity (C_l = 0.06, C_q = 1.5), F-bar and displacement
// elements. Checked over 500 steps: every step equals the first to 1e-12
// relative (the current lengths change by round-off only; measured: equal
// to the last bit).
//
// Fails before the threshold (2026-12-01): see the commit message.
#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_generator.h>

#include <rubberdyn/simulation/explicit_simulation.h>
#include <rubberdyn/model/model.h>
#include <rubberdyn/postprocess/postprocessor.h>
#include <rubberdyn/time_integration/explicit_solver.h>

#include <algorithm>
#include <random>
#include <sstream>
#include <vector>

#include "../tests.h"
#include "model_fixtures.h"

using namespace dealii;
using namespace rubberdyn;
using testing::check;
using testing::out;
using testing::sci;

namespace
{
  /** The step of every time step; stops after n_steps. */
  class StepRecorder : public postprocess::Postprocessor
  {
  public:
    static constexpr unsigned int n_steps = 500;

    std::string
    name() const override
    {
      return "step recorder";
    }

    void
    after_step(const postprocess::SimulationView &view) override
    {
      steps.push_back(view.explicit_solver()->time_step());
    }

    bool
    stop_requested() const override
    {
      return steps.size() >= n_steps;
    }

    std::vector<double> steps;
  };
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                   comm = MPI_COMM_WORLD;
  for (const elements::Formulation formulation :
       {elements::Formulation::fbar, elements::Formulation::displacement})
    {
      model::Model model(comm);
      GridGenerator::subdivided_hyper_rectangle(model.triangulation,
                                                {8, 6, 3},
                                                Point<3>(0., 0., 0.),
                                                Point<3>(16., 12., 6.));
      std::mt19937                           generator(2026);
      std::uniform_real_distribution<double> shift(-0.3, 0.3);
      std::vector<bool> moved(model.triangulation.n_vertices(), false);
      for (const auto &cell : model.triangulation.active_cell_iterators())
        for (const unsigned int v : cell->vertex_indices())
          {
            Point<3> &x = cell->vertex(v);
            if (moved[cell->vertex_index(v)])
              continue;
            moved[cell->vertex_index(v)] = true;
            if (x[0] > 1e-9 && x[0] < 16. - 1e-9 && x[1] > 1e-9 &&
                x[1] < 12. - 1e-9 && x[2] > 1e-9 && x[2] < 6. - 1e-9)
              for (unsigned int d = 0; d < 3; ++d)
                x[d] += shift(generator);
          }
      model::Part rubber;
      rubber.name             = "rubber";
      rubber.material_ids     = {0};
      rubber.law              = fixtures::rubber_law();
      rubber.formulation      = formulation;
      rubber.initial_velocity = Tensor<1, 3>({1.3, -0.7, 2.1});
      model.parts.push_back(std::move(rubber));
      model.gravity = Tensor<1, 3>({0., 0., -9.81e-3});
      model.setup();

      parameters::TimeIntegration time_integration;
      time_integration.end_time = 1e3; // ended by the recorder
      parameters::Output output;
      output.directory               = "translating_block_step";
      output.field_output_interval   = 0.;
      output.history_output_interval = 1e3;
      simulation::ExplicitSimulation simulation(model,
                                           time_integration,
                                           output,
                                           "Translating block",
                                           "translating block");
      auto                      plugin   = std::make_unique<StepRecorder>();
      StepRecorder             &recorder = *plugin;
      simulation.add_standard_postprocessors();
      simulation.add_postprocessor(std::move(plugin));
      std::ostringstream log;
      simulation.run(log);

      const auto [smallest, largest] =
        std::minmax_element(recorder.steps.begin(), recorder.steps.end());
      const double first = recorder.steps.front();
      const double spread =
        std::max(first - *smallest, *largest - first) / first;
      const std::string name =
        formulation == elements::Formulation::fbar ? "F-bar" : "displacement";
      out() << name << ": " << recorder.steps.size()
            << " steps, all equal to the first to 1e-12: "
            << (spread <= 1e-12 ? "yes" : "no") << std::endl;
      std::cerr << name << ": first step " << first << " ms, smallest "
                << *smallest << ", largest " << *largest << ", relative spread "
                << spread << std::endl;
      check(spread <= 1e-12,
            name + ": the step of a translating block varies by " +
              sci(spread) + " (bound 1e-12)");
    }
}
