// The internal force of the explicit hexahedra is the exact gradient of
// their stored energy, f_a = dE/du_a (hyperelastic laws, no bulk viscosity
// at zero velocity). Checked by central finite differences of
// SolidHexElements' own energy, h = 1e-6 mm, on 3 x 2 x 1 distorted cells
// with a random displacement (compression and shear of up to ~20 %), for
// the F-bar formulation without and with its volumetric stabilisation
// (beta = 0.1) and the displacement formulation, for Yeoh rubber (batched
// kernel) and neo-Hooke steel (point-by-point kernel). This covers the
// F-bar force formula (de Souza Neto et al. 1996), the sum-factorised
// reference gradients and their transpose, and the lane layout (6 cells
// fill one block of 4 lanes and half of another, whose other lanes are
// padding that must not contribute). Criterion: max |f - f_FD| /
// max |f| < 1e-6 (truncation error of the difference quotient is about
// 1e-10 relative; rounding of E about 1e-16 E / h).
#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>

#include <rubberdyn/elements/solid_hex_elements.h>
#include <rubberdyn/materials/elastic.h>
#include <rubberdyn/materials/yeoh.h>

#include <random>

#include "../tests.h"
#include "distorted_block.h"

using namespace dealii;
using namespace rubberdyn;
using testing::check;
using testing::out;
using testing::sci;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  Triangulation<3> tria;
  // The interior and boundary nodes off the lattice.
  fixtures::make_distorted_block(tria, 3, 2);
  std::mt19937 generator(42);
  std::uniform_real_distribution<double> jitter(-0.8, 0.8);
  FESystem<3>   fe(FE_Q<3>(1), 3);
  DoFHandler<3> dof_handler(tria);
  dof_handler.distribute_dofs(fe);
  const auto partitioner = std::make_shared<Utilities::MPI::Partitioner>(
    dof_handler.locally_owned_dofs(), MPI_COMM_SELF);

  const materials::Yeoh<3> rubber(0.55e-3, -0.05e-3, 0.015e-3,
                                  std::array<double, 3>{{2. / 1.65, 0., 0.}},
                                  1.1e-6);
  const materials::Elastic<3> steel(210., 0.3, 7.85e-6);

  // Homogeneous 20 % compression with lateral expansion and shear, plus a
  // random perturbation of every dof.
  VectorType u0(partitioner);
  {
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < dofs.size(); ++i)
          {
            const auto         ci = fe.system_to_component_index(i);
            const Point<3>     X  = cell->vertex(ci.second);
            const unsigned int d  = ci.first;
            const double       strain[3] = {0.11, 0.11, -0.2};
            u0[dofs[i]] = strain[d] * X[d] + (d == 0 ? 0.1 * X[2] : 0.);
          }
      }
    for (unsigned int i = 0; i < u0.size(); ++i)
      u0[i] += 0.1 * jitter(generator);
  }

  double worst = 0.;
  for (const auto &[law_name, law] :
       std::vector<std::pair<std::string, const materials::MaterialModel<3> *>>{
         {"Yeoh", &rubber}, {"Elastic", &steel}})
    for (const auto &[formulation, stabilization] :
         std::vector<std::pair<elements::Formulation, double>>{
           {elements::Formulation::fbar, 0.},
           {elements::Formulation::fbar, 0.1},
           {elements::Formulation::displacement, 0.}})
      {
        elements::SolidHexElements hexes;
        hexes.initialize(dof_handler,
                         partitioner,
                         {{{0}, law, formulation, stabilization}},
                         {0.06, 1.5});
        const std::vector<double> no_scaling(hexes.n_elements(), 1.);
        VectorType                u(u0), v(partitioner), f(partitioner),
          scratch(partitioner);
        const auto energy = [&](const VectorType &displacement) {
          elements::ElementStepResult result;
          scratch = 0.;
          hexes.compute_forces(displacement, v, no_scaling, scratch, result);
          check(!result.failure.failed, "no element fails");
          return result.internal_energy;
        };
        elements::ElementStepResult result;
        hexes.compute_forces(u, v, no_scaling, f, result);

        const double h = 1e-6;
        double       max_force = 0., max_error = 0.;
        for (unsigned int i = 0; i < u.size(); ++i)
          {
            const double saved = u[i];
            u[i]               = saved + h;
            const double E_plus = energy(u);
            u[i]                = saved - h;
            const double E_minus = energy(u);
            u[i]                 = saved;
            const double f_fd    = (E_plus - E_minus) / (2. * h);
            max_force            = std::max(max_force, std::abs(f[i]));
            max_error = std::max(max_error, std::abs(f[i] - f_fd));
          }
        const double relative = max_error / max_force;
        worst                 = std::max(worst, relative);
        out() << law_name << ", "
              << (formulation == elements::Formulation::fbar ?
                    (stabilization > 0. ? "F-bar, stabilised (beta 0.1)" :
                                          "F-bar") :
                    "displacement")
              << ": energy " << std::setprecision(8) << result.internal_energy
              << " J, max |f| " << max_force << " kN, FD error below 1e-6: "
              << (relative < 1e-6 ? "yes" : "no") << std::endl;
      }
  std::cerr << "largest relative error " << sci(worst) << std::endl;
  check(worst < 1e-6, "internal force = energy gradient to 1e-6");
}
