// Bulk viscosity of the explicit hexahedra (doc/theory.md section 8.4).
//
// 1. The reported power is the power of the viscous force actually
//    applied: on 3 x 2 x 1 distorted cells (6 elements: a full block and a
//    half-filled one) with a random displacement and random velocities
//    (some elements compress, others expand), the force is evaluated with
//    and without bulk viscosity at the same state; f_visc is their
//    difference and P = sum_i v_i f_visc,i. The element layer's
//    bulk_viscosity_power must equal P to 1e-10 relative to sum_i
//    |v_i f_visc,i| (round-off of the difference of two forces whose
//    elastic parts are of the size of the viscous ones: measured 2e-16),
//    for the F-bar and the displacement element. Before the power was
//    taken from the viscous force, the displacement element reported the
//    centre's q V rate instead: 6.91532 against v . f_visc = 6.88322
//    (relative error 2.6e-03; F-bar was already exact).
// 2. Closed form (LS-DYNA theory manual, bulk viscosity; doc/theory.md
//    8.3-8.4): a cube of side h at rest in its reference configuration
//    under the homogeneous velocity v = -e z e_z (volumetric strain rate
//    -e, compression) dissipates P = rho l Q e^2 V with l = h / sqrt3 (the
//    stable-step length, doc/theory.md 8.3), V = h^3, Q = C_l c + C_q l e
//    and c the reference wave speed; its stable step is
//    l / (Q + sqrt(Q^2 + c^2)).
//    Under v = +e z e_z (expansion) there is no bulk viscosity: P = 0 and
//    the step is l / c. Both formulations, to 1e-12.
#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>

#include <rubberdyn/elements/solid_hex_elements.h>
#include <rubberdyn/materials/yeoh.h>

#include <random>

#include "../tests.h"
#include "distorted_block.h"

using namespace dealii;
using namespace rubberdyn;
using testing::check;
using testing::out;
using testing::sci;

namespace
{
  const char *
  name(const elements::Formulation formulation)
  {
    return formulation == elements::Formulation::fbar ? "F-bar" :
                                                        "displacement";
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const materials::Yeoh<3>         rubber(0.55e-3,
                                  -0.05e-3,
                                  0.015e-3,
                                  std::array<double, 3>{{2. / 1.65, 0., 0.}},
                                  1.1e-6);
  const double C_l = 0.06, C_q = 1.5;
  const elements::Formulation formulations[2] = {
    elements::Formulation::fbar, elements::Formulation::displacement};

  // 1. Reported power = v . f_visc on distorted elements.
  {
    Triangulation<3> tria;
    fixtures::make_distorted_block(tria, 3, 2);
    FESystem<3>   fe(FE_Q<3>(1), 3);
    DoFHandler<3> dof_handler(tria);
    dof_handler.distribute_dofs(fe);
    const auto partitioner = std::make_shared<Utilities::MPI::Partitioner>(
      dof_handler.locally_owned_dofs(), MPI_COMM_SELF);

    std::mt19937                           generator(5);
    std::uniform_real_distribution<double> uniform(-1., 1.);
    VectorType u(partitioner), v(partitioner);
    for (unsigned int i = 0; i < u.size(); ++i)
      {
        u[i] = 0.01 * uniform(generator);
        v[i] = 20. * uniform(generator);
      }

    for (const auto formulation : formulations)
      {
        elements::SolidHexElements with, without;
        with.initialize(dof_handler,
                        partitioner,
                        {{{0}, &rubber, formulation}},
                        {C_l, C_q});
        without.initialize(dof_handler,
                           partitioner,
                           {{{0}, &rubber, formulation}},
                           {0., 0.});
        const std::vector<double>   no_scaling(with.n_elements(), 1.);
        VectorType                  f_with(partitioner), f_without(partitioner);
        elements::ElementStepResult r_with, r_without;
        with.compute_forces(u, v, no_scaling, f_with, r_with);
        without.compute_forces(u, v, no_scaling, f_without, r_without);
        check(!r_with.failure.failed && !r_without.failure.failed,
              "no element fails");

        double power = 0., scale = 0., elastic = 0., viscous = 0.;
        for (unsigned int i = 0; i < u.size(); ++i)
          {
            const double f_visc = f_with[i] - f_without[i];
            power += v[i] * f_visc;
            scale += std::abs(v[i] * f_visc);
            elastic = std::max(elastic, std::abs(f_without[i]));
            viscous = std::max(viscous, std::abs(f_visc));
          }
        const double error = std::abs(r_with.bulk_viscosity_power - power) / scale;
        out() << name(formulation) << ": v . f_visc = " << std::setprecision(6)
              << power << " kN mm/ms, reported "
              << r_with.bulk_viscosity_power << ", equal to 1e-10: "
              << (error < 1e-10 ? "yes" : "no")
              << "; without bulk viscosity reported "
              << r_without.bulk_viscosity_power << std::endl;
        std::cerr << name(formulation) << ": relative error " << sci(error)
                  << ", largest elastic force " << sci(elastic)
                  << " kN, largest viscous force " << sci(viscous) << " kN"
                  << std::endl;
        check(error < 1e-10, "reported viscous power = v . f_visc");
        check(r_without.bulk_viscosity_power == 0.,
              "no viscous power without bulk viscosity");
      }
  }

  // 2. Closed form on a cube at rest.
  {
    const double     h = 2., e = 0.5; // mm, 1/ms
    Triangulation<3> tria;
    GridGenerator::hyper_cube(tria, 0., h);
    FESystem<3>   fe(FE_Q<3>(1), 3);
    DoFHandler<3> dof_handler(tria);
    dof_handler.distribute_dofs(fe);
    const auto partitioner = std::make_shared<Utilities::MPI::Partitioner>(
      dof_handler.locally_owned_dofs(), MPI_COMM_SELF);

    const double rho = rubber.density(), c = rubber.reference_wave_speed();
    const double l = h / std::sqrt(3.), V = h * h * h;
    const double Q = C_l * c + C_q * l * e;
    const double P_exact    = rho * l * Q * e * e * V;
    const double step_exact = l / (Q + std::sqrt(Q * Q + c * c));
    out() << "cube " << h << " mm, volumetric strain rate -" << e
          << "/ms: P = rho l Q e^2 V = " << std::setprecision(8) << P_exact
          << " kN mm/ms, step l/(Q + sqrt(Q^2 + c^2)) = " << step_exact
          << " ms" << std::endl;

    double worst = 0.;
    for (const auto formulation : formulations)
      for (const double sign : {-1., 1.})
        {
          elements::SolidHexElements hexes;
          hexes.initialize(dof_handler,
                           partitioner,
                           {{{0}, &rubber, formulation}},
                           {C_l, C_q});
          VectorType                           u(partitioner), v(partitioner),
            f(partitioner);
          std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
          const auto cell = dof_handler.begin_active();
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            {
              const auto ci = fe.system_to_component_index(i);
              if (ci.first == 2)
                v[dofs[i]] = sign * e * cell->vertex(ci.second)[2];
            }
          elements::ElementStepResult result;
          hexes.compute_forces(u, v, {1.}, f, result);
          const bool   compression = (sign < 0.);
          const double P  = compression ? P_exact : 0.;
          const double dt = compression ? step_exact : l / c;
          const double error =
            std::max(std::abs(result.bulk_viscosity_power - P) / P_exact,
                     std::abs(result.min_time_step - dt) / dt);
          worst = std::max(worst, error);
          out() << name(formulation) << ", "
                << (compression ? "compression" : "expansion")
                << ": power and step equal the closed form to 1e-12: "
                << (error < 1e-12 ? "yes" : "no") << std::endl;
          std::cerr << name(formulation) << ", sign " << sign
                    << ": relative error " << sci(error) << std::endl;
        }
    check(worst < 1e-12, "closed form of the bulk viscosity");
  }
}
