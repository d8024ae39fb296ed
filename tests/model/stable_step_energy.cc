// The element stable step is conservative: at `Time step scale factor`
// 1.0 a run of 10 000 steps on a distorted mesh gains no energy, for every
// element formulation and F-bar stabilisation the code accepts, with and
// without a rigid surface at a small and a large penalty scale (issue
// "Reliability of the explicit engine", doc/theory.md section 8.3).
//
// The model: a 16 x 12 x 6 mm block of the shipped rubber (Yeoh, nu =
// 0.499, tests/model/model_fixtures.h) in 8 x 6 x 3 = 144 hexahedra of
// 2 mm, its interior vertices moved randomly by up to 0.3 mm (fixed
// seed), so that no two elements are alike. Two load cases, each for
// F-bar with `F-bar stabilization` 0 and 1 (the range's ends) and for the
// displacement element:
// - "fixed base": the face z = 0 held, every other node moving at
//   1 mm/ms in x and z at t = 0. The sudden start excites every mode of the
//   mesh, the highest included;
// - "impact": the free block at 1 mm/ms downwards onto a fixed rigid plane
//   0.01 mm below it, penalty scale 0.1 (the default) and 10 (where the
//   springs set the step as much as the elements: element step 1.35e-3 ms,
//   combined 0.92e-3 ms). The block bounces off and flies away.
// No bulk viscosity and no gravity: nothing dissipates or does work, so
// the total energy E = kinetic + internal + contact must stay at its
// initial value up to the oscillation of central differences (the scheme
// conserves a modified energy, which differs from E by a term of order
// (omega dt / 2)^2 times the energy in mode omega; measured: E oscillates
// between +0.5 and +1.3 % of E_0 for 40 000 steps in the fixed-base F-bar
// case and never grows).
//
// Checked: E stays finite and never exceeds E_ref by more than 2 % (the
// oscillation with a margin), E_ref = E_0 for the fixed base; for the
// impacts E_ref is E when the block has left the plane (the contact's work
// constant from then on), because the impact of stiff penalty springs
// itself changes the solid's energy once: the spring force is sampled at
// the steps, a node's contact lasts a step or two, and its rebound energy
// depends on where in the step it touched. The contact energy is the work
// done on the springs as the steps see it (trapezoidal, which books the
// penalty's updates to the current geometry too), so E itself stays at
// E_0 through the impact, and what the springs did not give back stays in
// it as their leftover work. The jump of the solid's energy, kinetic +
// internal, (E_ref - contact) / E_0 - 1, is printed; it must be
// below 2 % at the default penalty (measured at most 0.05 %); at penalty
// 10 it is 12 % (F-bar) and 9 % (displacement; 10 % with the penalty of
// the reference geometry, before 2026-12-03) at the scale factor 1.0
// (F-bar: 10 % at 0.9, 0.8 % at 0.5, none at 0.25): a limit of penalty
// contact at a step near the springs' stability limit, not an instability
// (the energy is constant after it, within 0.4 %), left to the contact
// issue.
//
// Fails with the old length l = volume / largest face area (before
// 2026-12-01): fixed base, F-bar: E grows by 3.2 %, displacement by 3.1 %.
#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_generator.h>

#include <rubberdyn/simulation/explicit_simulation.h>
#include <rubberdyn/model/model.h>
#include <rubberdyn/postprocess/postprocessor.h>
#include <rubberdyn/time_integration/explicit_solver.h>

#include <cmath>
#include <random>
#include <sstream>
#include <vector>

#include "../tests.h"
#include "model_fixtures.h"

using namespace dealii;
using namespace rubberdyn;
using testing::check;
using testing::out;

namespace
{
  /**
   * The total energy after every step (collective: the solver's sums);
   * stops the run after n_steps steps.
   */
  class EnergyRecorder : public postprocess::Postprocessor
  {
  public:
    static constexpr unsigned int n_steps = 10000;

    std::string
    name() const override
    {
      return "energy recorder";
    }

    void
    after_step(const postprocess::SimulationView &view) override
    {
      const time_integration::EnergyBalance &e = view.explicit_solver()->energies();
      energies.push_back(e.kinetic + e.internal + e.contact);
      contact_work.push_back(e.contact);
      initial = e.initial;
      steps   = view.explicit_solver()->step();
      // The step after the last one in which the contact's work changed
      // (nodes chatter: the contact energy drops to 0 and back during the
      // impact). After the impact it stays at what the penalty's updates
      // to the current geometry left behind, not at 0.
      if (e.contact != last_contact)
        left = energies.size();
      last_contact = e.contact;
    }

    bool
    stop_requested() const override
    {
      return steps >= n_steps;
    }

    std::vector<double> energies;
    /** The contact's part of them (J). */
    std::vector<double> contact_work;
    /** E_0 (J). */
    double       initial = 0.;
    unsigned int steps   = 0;
    /**
     * Index into energies of the step after the last one in which the
     * contact's work changed; 0: none.
     */
    std::size_t left = 0;
    /** The contact's work after the last step (J). */
    double last_contact = 0.;
  };

  struct Case
  {
    std::string           name;
    elements::Formulation formulation;
    double                stabilization;
    /** Penalty scale of the rigid plane; 0: fixed base, no plane. */
    double penalty_scale;
  };

  /**
   * The block of the header, with its interior vertices moved by up to
   * 0.3 mm (fixed seed: the same mesh in every case and on every machine
   * with the same standard library).
   */
  void
  make_block(model::Model &model, const Case &test_case)
  {
    GridGenerator::subdivided_hyper_rectangle(model.triangulation,
                                              {8, 6, 3},
                                              Point<3>(0., 0., 0.),
                                              Point<3>(16., 12., 6.));
    // The faces z = 0: boundary id 4 (the others keep 0).
    for (const auto &cell : model.triangulation.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->at_boundary(f) && std::abs(cell->face(f)->center()[2]) < 1e-9)
          cell->face(f)->set_boundary_id(4);
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
    rubber.name         = "rubber";
    rubber.material_ids = {0};
    rubber.law          = fixtures::rubber_law();
    rubber.formulation  = test_case.formulation;
    if (test_case.penalty_scale == 0.)
      {
        rubber.initial_velocity = Tensor<1, 3>({1., 0., 1.});
        model::BoundaryCondition base;
        base.name         = "base";
        base.boundary_ids = {4};
        model.boundary_conditions.push_back(base);
      }
    else
      {
        rubber.initial_velocity = Tensor<1, 3>({0., 0., -1.});
        model::RigidSurfaceDefinition plane;
        plane.name           = "plane";
        plane.surface.point  = Point<3>(0., 0., -0.01);
        plane.surface.normal = Tensor<1, 3>({0., 0., 1.});
        plane.body.name      = "plane";
        plane.boundary_ids   = {4};
        plane.penalty_scale  = test_case.penalty_scale;
        model.rigid_surfaces.push_back(plane);
      }
    model.parts.push_back(std::move(rubber));
    model.setup();
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                   comm = MPI_COMM_WORLD;
  using elements::Formulation;
  const std::vector<Case> cases = {
    {"fixed base, F-bar", Formulation::fbar, 0., 0.},
    {"fixed base, F-bar, stabilization 1", Formulation::fbar, 1., 0.},
    {"fixed base, displacement", Formulation::displacement, 0., 0.},
    {"impact, F-bar, penalty 0.1", Formulation::fbar, 0., 0.1},
    {"impact, F-bar, stabilization 1, penalty 0.1", Formulation::fbar, 1., 0.1},
    {"impact, displacement, penalty 0.1", Formulation::displacement, 0., 0.1},
    {"impact, F-bar, penalty 10", Formulation::fbar, 0., 10.},
    {"impact, F-bar, stabilization 1, penalty 10", Formulation::fbar, 1., 10.},
    {"impact, displacement, penalty 10", Formulation::displacement, 0., 10.}};

  // The allowed excess of E over E_0 (see the header).
#ifndef STABLE_STEP_ENERGY_ASSEMBLED
  const double      bound      = 0.02;
  const std::string bound_text = "2 %";
#else
  // At 0.9 of the assembled critical step the highest modes' share of E
  // oscillates more (measured: up to 2.9 % in the fixed-base cases, the
  // same in the first and the last 2000 steps).
  const double      bound      = 0.05;
  const std::string bound_text = "5 %";
#endif
  // The allowed change of the solid's energy by an impact at the default
  // penalty (see the header).
  const double jump_bound = 0.02;
  // Every case runs; the failures are reported together.
  std::string failures;
  for (const Case &test_case : cases)
    {
      model::Model model(comm);
      make_block(model, test_case);

      parameters::TimeIntegration time_integration;
      // Ended by the recorder after 10 000 steps.
      time_integration.end_time                 = 1e3;
      time_integration.time_step_scale          = 1.;
      time_integration.bulk_viscosity_linear    = 0.;
      time_integration.bulk_viscosity_quadratic = 0.;
      time_integration.fbar_stabilization       = test_case.stabilization;
#ifdef STABLE_STEP_ENERGY_ASSEMBLED
      // tests/model/stable_step_energy_assembled.cc: the same cases with
      // the assembled estimate, refreshed every STABLE_STEP_ENERGY_REFRESH
      // steps.
      time_integration.assembled_step_estimate      = true;
      time_integration.stable_step_refresh_interval =
        STABLE_STEP_ENERGY_REFRESH;
      time_integration.time_step_scale = STABLE_STEP_ENERGY_SCALE;
#endif
      parameters::Output output;
      output.directory               = "stable_step_energy";
      output.field_output_interval   = 0.;
      output.history_output_interval = 1e3;
      simulation::ExplicitSimulation simulation(model,
                                           time_integration,
                                           output,
                                           "Stable step energy",
                                           "stable step energy");
      auto                      plugin   = std::make_unique<EnergyRecorder>();
      EnergyRecorder           &recorder = *plugin;
      simulation.add_standard_postprocessors();
      simulation.add_postprocessor(std::move(plugin));
      std::ostringstream log;
      std::string        failure;
      try
        {
          simulation.run(log);
        }
      catch (const std::exception &e)
        {
          failure = e.what();
        }

      const double E0     = recorder.initial;
      bool         finite = E0 > 0.;
      for (const double E : recorder.energies)
        finite &= std::isfinite(E);
      // The impacts: the block must have left the plane by mid-run.
      const bool left =
        recorder.left > 0 && recorder.left < recorder.energies.size() / 2;
      const double E_ref  = left ? recorder.energies[recorder.left] : E0;
      double       growth = 0.;
      for (std::size_t i = recorder.left; i < recorder.energies.size(); ++i)
        growth = std::max(growth, recorder.energies[i] / E_ref - 1.);
      const double jump =
        left ? (E_ref - recorder.contact_work[recorder.left]) / E0 - 1. : 0.;
#ifdef STABLE_STEP_ENERGY_ASSEMBLED
      // No growth: the largest E / E_ref - 1 of the last 2000 steps against
      // that of the 2000 after the impact (or the start).
      double early = 0., late = 0.;
      {
        const std::size_t n = recorder.energies.size();
        for (std::size_t i = recorder.left;
             i < std::min(n, recorder.left + 2000);
             ++i)
          early = std::max(early, recorder.energies[i] / E_ref - 1.);
        for (std::size_t i = (n > 2000 ? n - 2000 : 0); i < n; ++i)
          late = std::max(late, recorder.energies[i] / E_ref - 1.);
        std::cerr << "  windows: early " << early << ", late " << late
                  << std::endl;
      }
      // Bounded: an instability grows without end, an oscillation does
      // not (measured: late - early at most 2e-4).
      out() << test_case.name
            << ": no growth (last 2000 steps' largest within 2e-3 of the "
               "first 2000's): "
            << (late <= early + 2e-3 ? "yes" : "no") << std::endl;
      if (late > early + 2e-3)
        failures += test_case.name + ": the energy grew from " +
                    testing::sci(early) + " to " + testing::sci(late) + "; ";
#endif
      out() << test_case.name << ": " << recorder.steps
            << " steps, largest E / E_ref - 1 below " << bound_text << ": "
            << (finite && failure.empty() && growth <= bound ? "yes" : "no");
#ifndef STABLE_STEP_ENERGY_ASSEMBLED
      if (test_case.penalty_scale > 0.)
        out() << "; impact (kinetic + internal) / E_0 - 1 = "
              << std::lround(100. * jump) << " %";
#else
      // The stiff penalty's jump (6-10 %) follows where in a step each
      // node touched, which the estimate's last digits move: on stderr
      // only.
      if (test_case.penalty_scale > 0. && test_case.penalty_scale <= 0.1)
        out() << "; impact (kinetic + internal) / E_0 - 1 below 2 %: "
              << (jump <= jump_bound ? "yes" : "no");
#endif
      out() << std::endl;
      std::cerr << test_case.name << ": " << recorder.steps
                << " steps, largest E / E_ref - 1 = " << growth
                << ", (kinetic + internal) / E_0 - 1 after the impact = "
                << jump << (failure.empty() ? "" : ", failed: " + failure)
                << std::endl;
      if (!failure.empty())
        failures += test_case.name + ": the run failed: " + failure + "; ";
      else if (test_case.penalty_scale > 0. && !left)
        failures += test_case.name + ": the block did not leave the plane; ";
      else if (!finite)
        failures += test_case.name + ": the energy is not finite; ";
      else if (growth > bound)
        failures += test_case.name + ": the energy grew by " +
                    testing::sci(growth) + " of E_ref (bound " +
                    testing::sci(bound) + "); ";
      else if (test_case.penalty_scale > 0. && test_case.penalty_scale <= 0.1 &&
               jump > jump_bound)
        failures += test_case.name + ": the impact changed the energy by " +
                    testing::sci(jump) + " (bound 2e-2); ";
    }
  check(failures.empty(), failures);
}
