// Rigid parts (Parts/<name>/Model = Rigid, LS-DYNA's MAT_RIGID; issue 7,
// verification "a rigid part dropped under gravity on a rubber block").
//
// The model of parameter_files/rigid_drop.prm (tests/model/model_fixtures.h):
// a steel block 10 x 10 x 5 mm (x, y from 5 to 15, z from 15 to 20), a rigid
// part, 5 mm above a rubber block 20 x 20 x 10 mm on a fixed floor, falling
// at 2 mm/ms under g = 9.81e-3 mm/ms^2; a rigid plane carried by the block
// at its bottom face touches the rubber's top.
//
// 1. Mass, centre and inertia of the block from its cells and density:
//    m = rho a b c = 7.85e-6 * 500 = 3.925e-3 kg, centre (10, 10, 17.5),
//    I = m diag(b^2 + c^2, a^2 + c^2, a^2 + b^2) / 12 (a box about its
//    centre), to 1e-12 (2-point Gauss is exact for the box).
// 2. Free fall before contact: the block's acceleration, from its velocity
//    at the first and the last half step before the first contact force,
//    (v^{k+1/2} - v^{j+1/2}) / (t_{k+1/2} - t_{j+1/2}) with t_{n+1/2} = t_n
//    + Dt^{n+1/2}/2, equals g to 1e-10 in each component (x and y: zero to
//    1e-10 g). Central differences integrate a constant acceleration
//    exactly, so only round-off remains, and only if the block's force is
//    its weight alone and its mass is the mass its nodes carry.
// 3. Momentum and contact impulse: from the last half step before contact
//    to the end (free flight again: no contact force at the last 20 steps)
//    m (v_end - v_before) = int F_contact dt + m g (t_end - t_before) in z,
//    the contact force (the `block_force_z` column's value at every step)
//    integrated by the trapezoidal rule over the step times. The issue asks
//    for 1 %; the test asks for 1e-10: with the force zero at both ends the
//    trapezoidal sum equals the solver's sum_n F^n Dt^n (summation by
//    parts), so only round-off may remain, provided the force reported is
//    the force that moves the block and the mass that divides it is the
//    block's. The block bounces: it leaves upwards at more than half its
//    impact speed.
// 4. Energy: the balance closes to 1 % of the impact energy at every step.
// 5. A spinning block in free flight (no gravity, no contact), about a
//    principal axis, w0 = (0, 0, 0.2) rad/ms, to 2 ms: the rotation is
//    exp(t [w0]x), the angle 0.2 t to 1e-10 rad, and the block's nodes stay
//    at c + R (X - C) (rigid) to 1e-10 mm. About a non-principal axis,
//    w0 = (0.1, 0.05, 0.2): the angular momentum L = R I0 R^T w stays L0 to
//    1e-12 relative (the integrator keeps L, and w = I^-1 L must follow it)
//    and the kinetic energy w.L/2 stays within 2e-3 of its initial value
//    (the energy is not exactly conserved by the explicit rotation update:
//    the drift measured is printed to the log).
#include <deal.II/base/mpi.h>
#include <deal.II/base/tensor.h>

#include <rubberdyn/simulation/explicit_simulation.h>
#include <rubberdyn/model/model.h>
#include <rubberdyn/postprocess/postprocessor.h>
#include <rubberdyn/time_integration/explicit_solver.h>

#include <cmath>
#include <iostream>
#include <memory>
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
  /** The block's body and the energies at every step. */
  class BodyRecorder : public postprocess::Postprocessor
  {
  public:
    std::string
    name() const override
    {
      return "body recorder";
    }

    void
    after_step(const postprocess::SimulationView &view) override
    {
      const time_integration::ExplicitSolver &s    = *view.explicit_solver();
      const model::RigidBody &                body = view.bodies().back();
      Step                                    step;
      step.time      = s.time();
      step.time_step = s.time_step();
      step.velocity  = body.velocity;
      step.force     = body.contact_force;
      step.rotation  = body.rotation;
      step.angular_velocity = body.angular_velocity;
      step.energy_error     = s.energies().absolute_error();
      // The block's nodes: x = X + u against the pose.
      double largest = 0.;
      for (const auto &cell : view.model().dof_handler.active_cell_iterators())
        if (cell->is_locally_owned() && cell->material_id() == 2)
          for (const unsigned int v : cell->vertex_indices())
            {
              Point<3> x = cell->vertex(v);
              for (unsigned int d = 0; d < 3; ++d)
                x[d] += s.displacement()(cell->vertex_dof_index(v, d));
              const Point<3> pose =
                body.current_reference_position() +
                body.rotation * (cell->vertex(v) - body.reference_position);
              largest = std::max(largest, (x - pose).norm());
            }
      step.node_offset = largest;
      steps.push_back(step);
    }

    struct Step
    {
      double       time, time_step, energy_error, node_offset;
      Tensor<1, 3> velocity, force, angular_velocity;
      Tensor<2, 3> rotation;
    };
    std::vector<Step> steps;
  };

  struct Run
  {
    model::RigidBody          body;
    std::vector<BodyRecorder::Step> steps;
  };

  Run
  run(const MPI_Comm      comm,
      const Tensor<1, 3> &velocity,
      const Tensor<1, 3> &angular_velocity,
      const Tensor<1, 3> &gravity,
      const bool          with_sole,
      const double        end_time,
      const std::string & directory)
  {
    model::Model model(comm);
    fixtures::make_rigid_drop(model, velocity, angular_velocity, gravity,
                              with_sole);
    parameters::TimeIntegration time_integration;
    time_integration.end_time = end_time;
    parameters::Output output;
    output.directory               = directory;
    output.field_output_interval   = 0.;
    output.history_output_interval = 0.1;
    simulation::ExplicitSimulation simulation(model, time_integration, output,
                                         "Rigid drop", "rigid drop");
    simulation.add_standard_postprocessors();
    auto          plugin   = std::make_unique<BodyRecorder>();
    BodyRecorder &recorder = *plugin;
    simulation.add_postprocessor(std::move(plugin));
    std::ostringstream log;
    simulation.run(log);
    Run result;
    result.steps = recorder.steps;
    return result;
  }

  /** The block's body after a run (mass, centre, inertia are set up). */
  model::RigidBody
  block_body(const MPI_Comm comm)
  {
    model::Model model(comm);
    fixtures::make_rigid_drop(model, Tensor<1, 3>(), Tensor<1, 3>(),
                              Tensor<1, 3>(), false);
    parameters::TimeIntegration time_integration;
    parameters::Output          output;
    output.directory = "unused";
    simulation::ExplicitSimulation simulation(model, time_integration, output,
                                         "Rigid drop", "rigid drop");
    return simulation.rigid_bodies().back();
  }



  void
  mass_properties(const MPI_Comm comm)
  {
    const model::RigidBody body = block_body(comm);
    const double a = 10., b = 10., c = 5., m = 7.85e-6 * a * b * c;
    const double inertia[3] = {m * (b * b + c * c) / 12.,
                               m * (a * a + c * c) / 12.,
                               m * (a * a + b * b) / 12.};
    double error = std::abs(body.mass - m) / m;
    error = std::max(error, (body.reference_position - Point<3>(10., 10., 17.5))
                                .norm() / 17.5);
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        error = std::max(error, std::abs(body.inertia[i][j] -
                                         (i == j ? inertia[i] : 0.)) /
                                  inertia[0]);
    out() << "1. Mass, centre and inertia of the rigid block against the box's "
             "closed forms: largest relative error below 1e-12: "
          << (error < 1e-12 ? "yes" : "no") << std::endl;
    check(error < 1e-12, "the rigid block's mass properties");
  }



  void
  drop(const MPI_Comm comm)
  {
    const Tensor<1, 3> g({0., 0., -9.81e-3});
    const Run run_result = run(comm, Tensor<1, 3>({0., 0., -2.}),
                               Tensor<1, 3>(), g, true, 5., "drop");
    const std::vector<BodyRecorder::Step> &steps = run_result.steps;
    const double m = 7.85e-6 * 500.;

    // 2. Free fall: the steps before the first contact force.
    unsigned int first_contact = 0;
    while (first_contact < steps.size() &&
           steps[first_contact].force.norm() == 0.)
      ++first_contact;
    check(first_contact > 10 && first_contact < steps.size(),
          "the block falls free for a while, then hits the rubber");
    const auto half_step_time = [&](const unsigned int n) {
      return steps[n].time + 0.5 * steps[n].time_step;
    };
    const unsigned int before = first_contact - 1;
    const Tensor<1, 3> acceleration =
      (steps[before].velocity - steps[0].velocity) /
      (half_step_time(before) - half_step_time(0));
    const double fall_error = (acceleration - g).norm() / g.norm();
    out() << "2. Free fall before contact: |a - g| / |g| below 1e-10: "
          << (fall_error < 1e-10 ? "yes" : "no") << std::endl;
    std::cout << "free fall over " << before
              << " steps: |a - g| / |g| = " << sci(fall_error) << std::endl;
    check(fall_error < 1e-10, "the falling block accelerates with g");

    // 3. Momentum change and impulse, from the last half step before
    // contact to the end.
    const unsigned int last = steps.size() - 1;
    for (unsigned int n = last - 20; n <= last; ++n)
      check(steps[n].force.norm() == 0., "free flight at the end");
    double impulse = 0.;
    for (unsigned int n = before; n < last; ++n)
      impulse += 0.5 * (steps[n].force[2] + steps[n + 1].force[2]) *
                 (steps[n + 1].time - steps[n].time);
    // The half steps at both ends: the force is zero there.
    impulse += m * g[2] * (half_step_time(last) - half_step_time(before));
    const double momentum_change =
      m * (steps[last].velocity[2] - steps[before].velocity[2]);
    const double impulse_error =
      std::abs(momentum_change - impulse) / std::abs(momentum_change);
    out() << "3. Momentum change against contact impulse plus weight: "
             "within 1e-10: "
          << (impulse_error < 1e-10 ? "yes" : "no") << "; the block leaves "
          << "upwards at more than half its impact speed: "
          << (steps[last].velocity[2] > -0.5 * steps[before].velocity[2] ?
                "yes" :
                "no")
          << std::endl;
    std::cout << "momentum change " << momentum_change << " kg mm/ms, impulse "
              << impulse << ", relative difference " << sci(impulse_error)
              << "; rebound speed " << steps[last].velocity[2] << " mm/ms"
              << std::endl;
    check(impulse_error < 1e-10, "momentum change = impulse");
    check(steps[last].velocity[2] > -0.5 * steps[before].velocity[2],
          "the block bounces back");

    // 4. Energy.
    const double impact_energy =
      0.5 * m * steps[before].velocity.norm_square();
    double largest_error = 0.;
    for (const BodyRecorder::Step &step : steps)
      largest_error = std::max(largest_error, step.energy_error);
    out() << "4. Energy balance within 1 % of the impact energy at every "
             "step: "
          << (largest_error < 0.01 * impact_energy ? "yes" : "no")
          << std::endl;
    std::cout << "largest energy error " << sci(largest_error / impact_energy)
              << " of the impact energy" << std::endl;
    check(largest_error < 0.01 * impact_energy, "energy balance");
  }



  void
  spin(const MPI_Comm comm)
  {
    // About a principal axis: R = exp(t [w0]x) exactly.
    {
      const Run          r = run(comm, Tensor<1, 3>(),
                        Tensor<1, 3>({0., 0., 0.2}), Tensor<1, 3>(), false,
                        2., "spin_principal");
      double angle_error = 0., offset = 0.;
      for (const BodyRecorder::Step &step : r.steps)
        {
          const Tensor<1, 3> theta = model::rotation_vector(step.rotation);
          angle_error = std::max(angle_error,
                                 (theta - Tensor<1, 3>({0., 0., 0.2 * step.time}))
                                   .norm());
          offset = std::max(offset, step.node_offset);
        }
      out() << "5. Spin about a principal axis to 2 ms: angle 0.2 t to "
               "1e-10 rad: "
            << (angle_error < 1e-10 ? "yes" : "no")
            << "; nodes at c + R (X - C) to 1e-10 mm: "
            << (offset < 1e-10 ? "yes" : "no") << std::endl;
      check(angle_error < 1e-10, "rotation about a principal axis");
      check(offset < 1e-10, "the rigid part's nodes follow its pose");
    }
    // About a non-principal axis: L and E.
    {
      const model::RigidBody body = block_body(comm);
      const Tensor<1, 3>     w0({0.1, 0.05, 0.2});
      const Run              r = run(comm, Tensor<1, 3>(), w0, Tensor<1, 3>(),
                        false, 2., "spin_general");
      const Tensor<1, 3> L0 = body.inertia * w0;
      const double       E0 = 0.5 * w0 * L0;
      double             momentum_error = 0., energy_drift = 0., offset = 0.;
      for (const BodyRecorder::Step &step : r.steps)
        {
          const Tensor<2, 3> I =
            step.rotation * body.inertia * transpose(step.rotation);
          const Tensor<1, 3> L = I * step.angular_velocity;
          // w^{n+1/2} = (I^n)^-1 L: compare at the same rotation.
          momentum_error =
            std::max(momentum_error, (L - L0).norm() / L0.norm());
          energy_drift = std::max(
            energy_drift,
            std::abs(0.5 * step.angular_velocity * L - E0) / E0);
          offset = std::max(offset, step.node_offset);
        }
      out() << "   Spin about a non-principal axis to 2 ms: angular momentum "
               "kept to 1e-12: "
            << (momentum_error < 1e-12 ? "yes" : "no")
            << "; kinetic energy within 2e-3: "
            << (energy_drift < 2e-3 ? "yes" : "no")
            << "; nodes at c + R (X - C) to 1e-10 mm: "
            << (offset < 1e-10 ? "yes" : "no") << std::endl;
      std::cout << "non-principal spin: |L - L0| / |L0| = "
                << sci(momentum_error) << ", energy drift "
                << sci(energy_drift) << std::endl;
      check(momentum_error < 1e-12, "angular momentum of a free spin");
      check(energy_drift < 2e-3, "kinetic energy of a free spin");
      check(offset < 1e-10, "the spinning part's nodes follow its pose");
    }
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                   comm = MPI_COMM_WORLD;
  mass_properties(comm);
  drop(comm);
  spin(comm);
}
