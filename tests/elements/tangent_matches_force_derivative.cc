// The element tangent of the quasi-static solver
// (SolidHexElements::compute_tangents()) is the exact derivative of the
// explicit internal force (SolidHexElements::compute_forces() at zero
// velocity, where bulk viscosity vanishes): K_ij = d f_i / d u_j, checked
// against central finite differences of compute_forces(), h = 1e-6 mm, on
// two distorted hexahedra (one block, two lanes) with a pre-deformation of
// 25 % compression, lateral expansion, shear and a random perturbation of
// every dof. Laws: Yeoh (the reference study's C10, C20, C30) with
// K/G = 1000 and K/G = 50, for F-bar without and with its volumetric
// stabilisation (beta = 0.1) and the displacement formulation; finite-strain
// J2 plasticity (algorithmic tangent of the radial return, Simo 1988) loaded
// well past yield from a virgin history, F-bar and displacement.
// Criterion: max_ij |K_ij - K_FD_ij| / max_ij |K_ij| < 1e-7 (the difference
// quotient's truncation error is ~h^2 |f'''| ~ 1e-12 relative and its
// rounding ~1e-16 |f| / h ~ 1e-10 relative; measured: 4e-10 to 1.5e-9,
// printed to stderr). A wrong term in the tangent (e.g. dropping the geometric
// term tau d g_a, or the F-bar term d t (g0 - g)) gives errors of 1e-2 to 1.
#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/full_matrix.h>

#include <rubberdyn/elements/solid_hex_elements.h>
#include <rubberdyn/materials/hardening_curve.h>
#include <rubberdyn/materials/j2_plasticity.h>
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
  const fixtures::DistortedBlock   block(2, 1);
  const FESystem<3>               &fe          = block.fe;
  const DoFHandler<3>             &dof_handler = block.dof_handler;
  const auto                      &partitioner = block.partitioner;
  const unsigned int               n           = dof_handler.n_dofs();

  // Reference study's Yeoh constants (GPa); D1 = 2 / K with K = ratio G,
  // G = 2 C10.
  const double C10 = 0.55e-3, C20 = -0.05e-3, C30 = 0.015e-3;
  const auto   yeoh = [&](const double ratio) {
    const double K = ratio * 2. * C10;
    return materials::Yeoh<3>(C10,
                              C20,
                              C30,
                              std::array<double, 3>{{2. / K, 0., 0.}},
                              1.1e-6);
  };
  const materials::Yeoh<3> rubber_1000 = yeoh(1000.), rubber_50 = yeoh(50.);
  // Steel-like J2 with linear hardening (yield 0.3 GPa, 0.5 GPa at 10 %
  // plastic strain): the pre-deformation below is ~100 times the yield
  // strain, so every Gauss point returns radially.
  const materials::J2Plasticity<3> steel(
    210.,
    0.3,
    7.85e-6,
    materials::HardeningCurve::parse(0.3, "0.1:0.5", "test"));

  std::mt19937                           generator(7);
  std::uniform_real_distribution<double> jitter(-1., 1.);
  VectorType                             u0(partitioner);
  {
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < dofs.size(); ++i)
          {
            const auto         ci        = fe.system_to_component_index(i);
            const Point<3>     X         = cell->vertex(ci.second);
            const unsigned int d         = ci.first;
            const double       strain[3] = {0.12, 0.1, -0.25};
            u0[dofs[i]] = strain[d] * X[d] + (d == 0 ? 0.15 * X[2] : 0.);
          }
      }
    for (unsigned int i = 0; i < n; ++i)
      u0[i] += 0.2 * jitter(generator);
  }

  struct Case
  {
    std::string                        name;
    const materials::MaterialModel<3> *law;
    elements::Formulation              formulation;
    double                             stabilization;
  };
  const std::vector<Case> cases = {
    {"Yeoh K/G 1000, F-bar", &rubber_1000, elements::Formulation::fbar, 0.},
    {"Yeoh K/G 1000, F-bar stabilised (beta 0.1)",
     &rubber_1000,
     elements::Formulation::fbar,
     0.1},
    {"Yeoh K/G 1000, displacement",
     &rubber_1000,
     elements::Formulation::displacement,
     0.},
    {"Yeoh K/G 50, F-bar", &rubber_50, elements::Formulation::fbar, 0.},
    {"Yeoh K/G 50, F-bar stabilised (beta 0.1)",
     &rubber_50,
     elements::Formulation::fbar,
     0.1},
    {"Yeoh K/G 50, displacement",
     &rubber_50,
     elements::Formulation::displacement,
     0.},
    {"J2 plasticity, F-bar", &steel, elements::Formulation::fbar, 0.},
    {"J2 plasticity, displacement",
     &steel,
     elements::Formulation::displacement,
     0.}};

  double worst = 0.;
  for (const Case &c : cases)
    {
      elements::SolidHexElements hexes;
      // No collapse check: the perturbed pre-deformation is legitimate.
      hexes.initialize(dof_handler,
                       partitioner,
                       {{{0}, c.law, c.formulation, c.stabilization}},
                       {0.06, 1.5, 0.});
      const std::vector<double> no_scaling(hexes.n_elements(), 1.);
      VectorType                u(u0), v(partitioner), f(partitioner);
      const auto                force = [&](const VectorType &displacement) {
        elements::ElementStepResult result;
        f = 0.;
        hexes.compute_forces(displacement, v, no_scaling, f, result);
        check(!result.failure.failed, "no element fails");
        return f;
      };

      FullMatrix<double> K(n, n), K_fd(n, n);
      hexes.compute_tangents(u,
                             [&](const unsigned int *dofs, const double *Ke) {
                               for (unsigned int i = 0; i < 24; ++i)
                                 for (unsigned int j = 0; j < 24; ++j)
                                   K(dofs[i], dofs[j]) += Ke[24 * i + j];
                             });
      const double h = 1e-6;
      for (unsigned int j = 0; j < n; ++j)
        {
          const double saved = u[j];
          u[j]               = saved + h;
          const VectorType f_plus(force(u));
          u[j] = saved - h;
          const VectorType f_minus(force(u));
          u[j] = saved;
          for (unsigned int i = 0; i < n; ++i)
            K_fd(i, j) = (f_plus[i] - f_minus[i]) / (2. * h);
        }
      double max_K = 0., max_error = 0., asymmetry = 0.;
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = 0; j < n; ++j)
          {
            max_K     = std::max(max_K, std::abs(K(i, j)));
            max_error = std::max(max_error, std::abs(K(i, j) - K_fd(i, j)));
            asymmetry = std::max(asymmetry, std::abs(K(i, j) - K(j, i)));
          }
      const double relative = max_error / max_K;
      worst                 = std::max(worst, relative);
      out() << c.name << ": max |K| " << std::setprecision(6) << max_K
            << " kN/mm, symmetric: "
            << (asymmetry < 1e-10 * max_K ? "yes" : "no")
            << ", FD error below 1e-7: " << (relative < 1e-7 ? "yes" : "no")
            << std::endl;
      std::cerr << c.name << ": relative error " << sci(relative)
                << ", asymmetry " << sci(asymmetry / max_K) << std::endl;
    }
  std::cerr << "largest relative error " << sci(worst) << std::endl;
  check(worst < 1e-7, "tangent = derivative of the internal force to 1e-7");
}
