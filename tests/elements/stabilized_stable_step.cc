// The stable step includes the stiffness of the F-bar volumetric
// stabilisation U(r) = kappa/2 (r + 1/r - 2), kappa = beta K (doc/theory.md
// sections 8.1 and 8.3): rho_0 c^2 gains kappa / r_c, r_c the collapse
// ratio (0.25), which bounds kappa / r_q for every state an element
// accepts.
//
// 1. Closed form: a 2 mm cube at rest has the step
//    l / sqrt(c^2 + beta K / (rho r_c)), l = 2 / sqrt3 mm (doc/theory.md
//    section 8.3), c the reference wave speed, in a force evaluation and
//    in reference_time_steps() (1e-12).
// 2. Time integration at scale 1.0 (the step re-evaluated every step, as
//    the explicit solver does): a 3 x 3 x 3 patch of distorted 2 mm
//    hexahedra of the shipped rubber (nu = 0.499), compressed to 80 % of
//    its height, its boundary nodes held in that state, its 8 interior
//    nodes displaced randomly by up to 0.1 mm (Gauss-point ratios r_q down
//    to about 0.9) and given random velocities of up to 1 mm/ms. Lumped
//    mass, central differences (doc/theory.md 8.2), no bulk viscosity: the
//    total energy E = K + U must stay within 10 % of E_0 for 10 000 steps,
//    for beta = 0, 0.03, 0.1, 1 (measured: at most 7.7 % at beta = 0, 3.4 %
//    with the stabilisation; central differences near the stability limit
//    oscillate by a few per cent, an unstable step grows without bound).
//    Before the stabilisation entered the step, beta = 1 grew the energy
//    610-fold and an element inverted at step 5340.
// (tests/elements/stable_step_bound checks single free elements against
// the largest eigenvalue of their tangent.)
#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <rubberdyn/elements/solid_hex_elements.h>
#include <rubberdyn/materials/yeoh.h>

#include <map>
#include <random>

#include "../tests.h"

using namespace dealii;
using namespace rubberdyn;
using testing::check;
using testing::out;
using testing::sci;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double                     G = 1.1e-3, nu = 0.499;
  const double K = 2. * G * (1. + nu) / (3. * (1. - 2. * nu));
  const materials::Yeoh<3> rubber(0.55e-3,
                                  -0.05e-3,
                                  0.015e-3,
                                  std::array<double, 3>{{2. / K, 0., 0.}},
                                  1.1e-6);
  const double             betas[4] = {0., 0.03, 0.1, 1.};
  const FESystem<3>        fe(FE_Q<3>(1), 3);

  // 1. Closed form on a cube at rest.
  {
    Triangulation<3> tria;
    GridGenerator::hyper_cube(tria, 0., 2.);
    DoFHandler<3> dof_handler(tria);
    dof_handler.distribute_dofs(fe);
    const auto partitioner = std::make_shared<Utilities::MPI::Partitioner>(
      dof_handler.locally_owned_dofs(), MPI_COMM_SELF);
    double worst = 0.;
    for (const double beta : betas)
      {
        const elements::ElementSettings settings;
        elements::SolidHexElements      hexes;
        hexes.initialize(dof_handler,
                         partitioner,
                         {{{0}, &rubber, elements::Formulation::fbar, beta}},
                         settings);
        VectorType u(partitioner), v(partitioner), f(partitioner);
        elements::ElementStepResult result;
        hexes.compute_forces(u, v, {1.}, f, result);
        const double c = rubber.reference_wave_speed();
        const double exact =
          2. / std::sqrt(3.) /
          std::sqrt(c * c + beta * K / (rubber.density() *
                                        settings.fbar_collapse_ratio));
        const double error =
          std::max(std::abs(result.min_time_step - exact),
                   std::abs(hexes.reference_time_steps()[0] - exact)) /
          exact;
        worst = std::max(worst, error);
        out() << "cube at rest, beta " << beta << ": step "
              << std::setprecision(6) << exact << " ms = "
              << exact * c * std::sqrt(3.) / 2. << " l/c" << std::endl;
      }
    std::cerr << "closed form: largest relative error " << sci(worst)
              << std::endl;
    check(worst < 1e-12, "step at rest equals the closed form to 1e-12");
  }

  // 2. The patch.
  Triangulation<3> tria;
  GridGenerator::subdivided_hyper_cube(tria, 3, 0., 6.);
  {
    std::mt19937                           generator(7);
    std::uniform_real_distribution<double> uniform(-1., 1.);
    std::map<unsigned int, Point<3>>       moved;
    for (const auto &cell : tria.active_cell_iterators())
      for (unsigned int a = 0; a < 8; ++a)
        if (moved.count(cell->vertex_index(a)) == 0)
          {
            Point<3> x = cell->vertex(a);
            for (unsigned int d = 0; d < 3; ++d)
              x[d] += 0.25 * uniform(generator);
            moved[cell->vertex_index(a)] = x;
          }
    for (const auto &cell : tria.active_cell_iterators())
      for (unsigned int a = 0; a < 8; ++a)
        cell->vertex(a) = moved[cell->vertex_index(a)];
  }
  DoFHandler<3> dof_handler(tria);
  dof_handler.distribute_dofs(fe);
  const auto partitioner = std::make_shared<Utilities::MPI::Partitioner>(
    dof_handler.locally_owned_dofs(), MPI_COMM_SELF);

  // Compressed state, held boundary, random interior perturbation.
  VectorType        u0(partitioner), v0(partitioner);
  std::vector<bool> held(u0.size(), true);
  {
    const double lambda = 0.8, lateral = 1. / std::sqrt(lambda);
    const double stretch[3] = {lateral - 1., lateral - 1., lambda - 1.};
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < dofs.size(); ++i)
          {
            const auto     ci = fe.system_to_component_index(i);
            const Point<3> X  = cell->vertex(ci.second);
            u0[dofs[i]]       = stretch[ci.first] * X[ci.first];
            held[dofs[i]] = !(X[0] > 1. && X[0] < 5. && X[1] > 1. &&
                              X[1] < 5. && X[2] > 1. && X[2] < 5.);
          }
      }
    std::mt19937                           generator(11);
    std::uniform_real_distribution<double> uniform(-1., 1.);
    for (unsigned int i = 0; i < u0.size(); ++i)
      if (!held[i])
        {
          u0[i] += 0.1 * uniform(generator);
          v0[i] = uniform(generator);
        }
  }

  bool all_bounded = true;
  for (const double beta : betas)
    {
      elements::ElementSettings settings;
      settings.bulk_viscosity_linear    = 0.;
      settings.bulk_viscosity_quadratic = 0.;
      elements::SolidHexElements hexes;
      hexes.initialize(dof_handler,
                       partitioner,
                       {{{0}, &rubber, elements::Formulation::fbar, beta}},
                       settings);
      const std::vector<double> no_scaling(hexes.n_elements(), 1.);
      VectorType u(u0), v(v0), f(partitioner), mass(partitioner);
      hexes.add_lumped_mass(mass, no_scaling);

      elements::ElementStepResult result;
      hexes.compute_forces(u, v, no_scaling, f, result);
      check(!result.failure.failed, "the initial state is admissible");
      const double smallest_ratio = result.min_volume_ratio;
      double       E0             = result.internal_energy;
      for (unsigned int i = 0; i < u.size(); ++i)
        E0 += 0.5 * mass[i] * v[i] * v[i];

      // Central differences with the step of the current state (scale
      // 1.0): v^{n+1/2} = v^{n-1/2} + dt^n a^n, dt^n the mean of the two
      // half steps (the first one half), u^{n+1} = u^n + dt^{n+1/2}
      // v^{n+1/2}; the kinetic energy at t_n from the mean of the two half
      // step velocities.
      const unsigned int n_steps    = 10000;
      double             step       = result.min_time_step;
      double             last_step  = 0.;
      double             max_error  = 0.;
      unsigned int       n          = 0;
      std::string        failure;
      for (; n < n_steps; ++n)
        {
          const double average_step =
            (n == 0) ? 0.5 * step : 0.5 * (last_step + step);
          double kinetic = 0.;
          for (unsigned int i = 0; i < u.size(); ++i)
            if (!held[i])
              {
                const double v_old = v[i];
                v[i]               = v_old - average_step * f[i] / mass[i];
                kinetic += 0.125 * mass[i] * (v_old + v[i]) * (v_old + v[i]);
              }
          if (n > 0)
            max_error =
              std::max(max_error,
                       std::abs(kinetic + result.internal_energy - E0) / E0);
          for (unsigned int i = 0; i < u.size(); ++i)
            u[i] += step * v[i];
          f = 0.;
          hexes.compute_forces(u, v, no_scaling, f, result);
          if (result.failure.failed)
            {
              failure = result.failure.message;
              break;
            }
          last_step = step;
          step      = result.min_time_step;
        }
      const bool bounded = (n == n_steps && max_error < 0.1);
      all_bounded        = all_bounded && bounded;
      out() << "beta " << beta << ": initial smallest J_q/J_0 "
            << std::setprecision(2) << smallest_ratio << ", " << n
            << " steps" << (failure.empty() ? "" : " (failed: " + failure + ")")
            << ", energy within 10 % of E_0: " << (bounded ? "yes" : "no")
            << std::endl;
      std::cerr << "beta " << beta << ": largest |E - E_0| / E_0 "
                << sci(max_error) << ", last step " << sci(step) << " ms"
                << std::endl;
    }
  check(all_bounded, "no energy growth at scale 1.0");
}
