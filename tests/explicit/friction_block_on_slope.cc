// Coulomb friction of the rigid-surface contact, slip and stick, with
// rigid-body mechanics (e.g. Meriam & Kraige, Engineering Mechanics:
// Dynamics, sect. 3/4) as the reference:
// 1. Slip: an elastic block on a fixed rigid plane under gravity tilted by
//    theta = 30 degrees from the plane's normal (a block on a 30-degree
//    slope), mu = 0.3 < tan(theta): it slides with a = g (sin(theta) - mu
//    cos(theta)) = 0.2402 g; checked within 2 % from the least-squares
//    slope of the nodes' mean x velocity, sampled every step from t = 1 to
//    3 ms. The energy balance with the friction work holds to 1 %.
// 2. Slip, then stick: the block at rest on a conveyor (a rigid plane of
//    huge mass moving tangentially at V = 0.5 mm/ms), gravity normal to it,
//    mu = 0.3: friction accelerates it at mu g until it moves with the
//    belt at t* = V / (mu g) = 1.67 ms, after which it sticks. Checked: the
//    velocity at t = 1 ms is mu g t within 2 %, and from 2.5 to 3 ms the
//    block moves with the belt (velocity V within 0.5 %).
// 3. The slope case again on rigid cylinders instead of the plane: a pin
//    (solid outside) of radius 1000 mm with its axis along y 1000 mm below
//    the block, and a tube (solid inside) of the same radius with its axis
//    1000 mm above: locally the same floor (the block travels about 1 mm,
//    0.001 rad of curvature), so the same acceleration within 2 %; this
//    checks the cylinders' gaps, normals and friction.
// The block starts touching the plane without load, so it bounces on the
// normal penalty springs (nothing damps them): the normal force
// oscillates around m g, which is why the checks use mean velocities over
// many bounce periods. (The accelerations were once the difference of two
// samples, at 1 and 3 ms, each at the mercy of the bounce phase: about
// +-1 % each: the smaller stable step of 2026-12-01 moved the tube's from
// +0.8 % to -2.1 %. The fitted slopes are within 0.5 % for all three.)
#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>

#include <rubberdyn/base/partitioner.h>
#include <rubberdyn/contact/rigid_surface_contact.h>
#include <rubberdyn/elements/solid_hex_elements.h>
#include <rubberdyn/materials/elastic.h>
#include <rubberdyn/contact/rigid_surface_forces.h>
#include <rubberdyn/elements/solid_hex_forces.h>
#include <rubberdyn/time_integration/explicit_solver.h>

#include "../tests.h"

using namespace dealii;
using namespace rubberdyn;
using testing::check;
using testing::out;
using testing::sci;

namespace
{
  struct SlopeResult
  {
    double acceleration;
    double displacement;
    double max_energy_error;
    double friction_work;
  };

  struct Run
  {
    double velocity_1, time_1, velocity_2, time_2;
    /** Least-squares slope of the mean velocity over [time_1, time_2]. */
    double acceleration;
    double displacement;
    double energy_error;
    double friction_work;
  };

  // An elastic 4 x 4 x 2 mm block of 1 mm cubes on the rigid plane z = 0
  // with friction coefficient mu, the plane moving at plane_velocity in x,
  // under the gravity vector @p gravity; mean x velocities of the nodes at
  // about time_1 and time_2 (ms).
  Run
  run_block(const contact::RigidSurface &floor_surface,
            const Tensor<1, 3> &gravity,
            const double        plane_velocity,
            const double        time_1,
            const double        time_2,
            const MPI_Comm      comm)
  {
    parallel::distributed::Triangulation<3> tria(comm);
    // colorize: boundary id 4 is z = 0.
    GridGenerator::subdivided_hyper_rectangle(tria, {4, 4, 2},
                                              Point<3>(0., 0., 0.),
                                              Point<3>(4., 4., 2.), true);
    // colorize also numbers the cells' material ids; one material here.
    for (const auto &cell : tria.active_cell_iterators())
      cell->set_material_id(0);
    const FESystem<3> fe(FE_Q<3>(1), 3);
    DoFHandler<3>     dof_handler(tria);
    dof_handler.distribute_dofs(fe);
    const auto partitioner = rubberdyn::ghosted_partitioner(dof_handler);

    const materials::Elastic<3> block(0.05, 0.3, 1e-6);
    elements::SolidHexElements  hexes;
    hexes.initialize(dof_handler, partitioner, {{{0}, &block, elements::Formulation::fbar}},
                     elements::ElementSettings());
    contact::RigidSurfaceContact floor;
    floor.initialize(dof_handler, partitioner, {4}, {block.bulk_modulus()},
                     1., {floor_surface});
    // The plane's body: held, or a belt of huge mass moving along x.
    std::vector<model::RigidBody> bodies(1);
    if (plane_velocity != 0.)
      {
        bodies[0].mass        = 1e6;
        bodies[0].free[0]     = true;
        bodies[0].velocity[0] = plane_velocity;
      }

    time_integration::ExplicitSettings settings;
    settings.gravity = gravity;
    elements::SolidHexForces hex_forces(
      hexes, std::vector<double>(hexes.n_elements(), 1.));
    contact::RigidSurfaceForces      floor_forces(floor, {0});
    time_integration::ExplicitSolver solver(dof_handler,
                                            {&hex_forces, &floor_forces},
                                            bodies,
                                            nullptr,
                                            partitioner,
                                            settings,
                                            comm);

    std::vector<unsigned int>            x_dofs;
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    std::set<unsigned int>               seen;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            if (fe.system_to_component_index(i).first == 0 &&
                partitioner->in_local_range(dofs[i]) &&
                seen.insert(partitioner->global_to_local(dofs[i])).second)
              x_dofs.push_back(partitioner->global_to_local(dofs[i]));
        }
    const auto mean = [&](const VectorType &vector) {
      double sums[2] = {0., double(x_dofs.size())};
      for (const unsigned int i : x_dofs)
        sums[0] += vector.local_element(i);
      Utilities::MPI::sum(ArrayView<const double>(sums, 2), comm,
                          ArrayView<double>(sums, 2));
      return sums[0] / sums[1];
    };

    Run result;
    // The velocity of the last half step belongs to t + dt/2.
    solver.run(time_1, []() {});
    result.velocity_1 = mean(solver.velocity());
    result.time_1     = solver.time() - 0.5 * solver.time_step();
    // Samples (t, mean v) of every step from time_1 to time_2.
    std::vector<std::pair<double, double>> samples = {
      {result.time_1, result.velocity_1}};
    solver.run(time_2, [&]() {
      samples.emplace_back(solver.time() - 0.5 * solver.time_step(),
                           mean(solver.velocity()));
    });
    double t_mean = 0., v_mean = 0.;
    for (const auto &[t, v] : samples)
      {
        t_mean += t / samples.size();
        v_mean += v / samples.size();
      }
    double covariance = 0., variance = 0.;
    for (const auto &[t, v] : samples)
      {
        covariance += (t - t_mean) * (v - v_mean);
        variance += (t - t_mean) * (t - t_mean);
      }
    result.acceleration  = covariance / variance;
    result.velocity_2    = mean(solver.velocity());
    result.time_2        = solver.time() - 0.5 * solver.time_step();
    result.displacement  = mean(solver.displacement());
    result.energy_error  = solver.energies().relative_error();
    result.friction_work = solver.energies().friction_work;
    return result;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm comm  = MPI_COMM_WORLD;
  const double   g     = 1.; // mm/ms^2, about 100 g, to keep the runs short
  const double   mu    = 0.3;
  const double   theta = numbers::PI / 6.;

  const contact::RigidSurface plane = {Point<3>(), Tensor<1, 3>({0., 0., 1.}),
                                      mu};
  const Tensor<1, 3> slope_gravity({g * std::sin(theta), 0., -g * std::cos(theta)});
  const Run slope = run_block(plane, slope_gravity, 0., 1., 3., comm);
  const double slope_acceleration = slope.acceleration;
  const double expected = g * (std::sin(theta) - mu * std::cos(theta));
  const double slope_error = std::abs(slope_acceleration / expected - 1.);
  out() << std::setprecision(4) << "slope: acceleration " << slope_acceleration
        << " mm/ms^2, g (sin - mu cos) = " << expected
        << ", within 2 %: " << (slope_error < 0.02 ? "yes" : "no")
        << "; energy error below 1 %: "
        << (slope.energy_error < 0.01 ? "yes" : "no") << std::endl;

  const double V    = 0.5;
  const Run    belt = run_block(plane, Tensor<1, 3>({0., 0., -g}), V, 1., 3., comm);
  const double slip_error  = std::abs(belt.velocity_1 / (mu * g * belt.time_1) - 1.);
  const double stick_error = std::abs(belt.velocity_2 / V - 1.);
  out() << "belt: velocity at " << belt.time_1 << " ms " << belt.velocity_1
        << " mm/ms, mu g t = " << mu * g * belt.time_1
        << ", within 2 %: " << (slip_error < 0.02 ? "yes" : "no")
        << "; at " << belt.time_2 << " ms " << belt.velocity_2
        << " mm/ms, belt " << V
        << ", within 0.5 %: " << (stick_error < 0.005 ? "yes" : "no")
        << std::endl;
  // The floor as a big pin below and as a big tube above. Cells span
  // x, y in [0, 4]: the axes pass over the block's centre line x = 2.
  const double                R = 1000.;
  contact::RigidSurface       pin{Point<3>(2., 0., -R), Tensor<1, 3>({0., 1., 0.}),
                            mu, R,
                            contact::RigidSurface::Shape::cylinder_solid_outside};
  contact::RigidSurface tube = pin;
  tube.point[2]              = R;
  tube.shape = contact::RigidSurface::Shape::cylinder_solid_inside;
  double cylinder_error = 0.;
  for (const auto &[name, surface] :
       std::vector<std::pair<std::string, contact::RigidSurface>>{
         {"pin", pin}, {"tube", tube}})
    {
      const Run    run = run_block(surface, slope_gravity, 0., 1., 3., comm);
      const double a   = run.acceleration;
      const double error = std::abs(a / expected - 1.);
      cylinder_error     = std::max(cylinder_error, error);
      out() << name << " of radius " << R << " mm: acceleration " << a
            << " mm/ms^2, within 2 %: " << (error < 0.02 ? "yes" : "no")
            << std::endl;
    }
  check(cylinder_error < 0.02, "slope on cylinders");

  std::cerr << "errors: slope acceleration " << sci(slope_error)
            << ", slope energy " << sci(slope.energy_error) << ", slip "
            << sci(slip_error) << ", stick " << sci(stick_error)
            << "; friction work on the slope " << slope.friction_work << " J"
            << std::endl;

  check(slope_error < 0.02, "sliding acceleration within 2 %");
  check(slope.energy_error < 0.01, "energy balance with friction");
  check(slip_error < 0.02, "belt: slip acceleration within 2 %");
  check(stick_error < 0.005, "belt: sticks at the belt's velocity");
}
