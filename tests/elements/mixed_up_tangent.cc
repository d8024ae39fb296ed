// The mixed u-p element (MixedUPElements, doc/theory.md section 11):
// 1. its tangent (compute_tangents()) is the exact derivative of its
//    condensed residual (compute_residual()): K_ij = d f_i / d u_j against
//    central differences, h = 1e-6 mm;
// 2. its residual is the exact gradient of its stored energy, the reduced
//    three-field functional E(u) = sum_q w_q W(tilde F_q) (central
//    differences of the energy, h = 1e-5 mm);
// 3. the tangent is symmetric (the element is variational);
// 4. in a homogeneous deformation the condensed fields are exact: tilde J =
//    det F and tilde p = the law's Cauchy pressure at every Gauss point,
//    and the residual of every interior node vanishes (a patch test); the
//    ParaView cell averages (cell_averages(), stored as float) are the
//    law's Cauchy stress tau(F) / J, its pressure and det F to 1e-6
//    relative.
// Mesh: two distorted Q2 hexahedra (Triangulation 2x1x1, 135 dofs) with a
// pre-deformation of 25 % compression, lateral expansion, shear and a
// random perturbation of every dof. Laws: Yeoh with the reference study's
// constants at K/G = 1000 and 50, and the neo-Hooke law of Cook's membrane
// (C10 = G/2, C20 = C30 = 0, K/G = 5000).
// Criteria: max_ij |K_ij - K_FD_ij| / max |K| < 1e-7 (truncation ~h^2
// |f'''| ~ 1e-12 relative, rounding ~1e-16 |f| / h ~ 1e-10 relative, as in
// tangent_matches_force_derivative; measured values on stderr); the same
// bound for the energy gradient relative to max |f|; the asymmetry below
// 1e-10 max |K|; the homogeneous fields to 1e-12 relative and the interior
// residual below 1e-12 max |f|. Measured: tangent errors 5.8e-10 to
// 6.5e-10, energy-gradient errors 1.7e-10 to 1.9e-10, asymmetry below
// 5e-16, homogeneous fields to 9e-15, interior residuals 4e-15.
#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/full_matrix.h>

#include <rubberdyn/elements/mixed_up_elements.h>
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
  const fixtures::DistortedBlock   block(2, 1, 2);
  const FESystem<3>               &fe          = block.fe;
  const DoFHandler<3>             &dof_handler = block.dof_handler;
  const auto                      &partitioner = block.partitioner;
  const unsigned int               n           = dof_handler.n_dofs();
  std::map<types::global_dof_index, Point<3>> support;
  DoFTools::map_dofs_to_support_points(MappingQ1<3>(), dof_handler, support);

  // Yeoh (GPa); D1 = 2 / K with K = ratio G, G = 2 C10.
  const auto yeoh = [&](const double C10,
                        const double C20,
                        const double C30,
                        const double ratio) {
    const double K = ratio * 2. * C10;
    return materials::Yeoh<3>(C10,
                              C20,
                              C30,
                              std::array<double, 3>{{2. / K, 0., 0.}},
                              1.1e-6);
  };
  const double             C10 = 0.55e-3, C20 = -0.05e-3, C30 = 0.015e-3;
  const materials::Yeoh<3> rubber_1000 = yeoh(C10, C20, C30, 1000.),
                           rubber_50   = yeoh(C10, C20, C30, 50.),
                           neo_hooke   = yeoh(0.0400969, 0., 0., 5000.);

  // A homogeneous deformation u = H X and a perturbed one.
  Tensor<2, 3> H;
  H[0][0] = 0.12;
  H[1][1] = 0.1;
  H[2][2] = -0.25;
  H[0][2] = 0.15;
  VectorType u_homogeneous(partitioner), u0(partitioner);
  {
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < dofs.size(); ++i)
          {
            const unsigned int c   = fe.system_to_component_index(i).first;
            const Point<3>    &X   = support.at(dofs[i]);
            u_homogeneous[dofs[i]] = (H * Tensor<1, 3>(X))[c];
          }
      }
    std::mt19937                           generator(7);
    std::uniform_real_distribution<double> jitter(-1., 1.);
    u0 = u_homogeneous;
    for (unsigned int i = 0; i < n; ++i)
      u0[i] += 0.2 * jitter(generator);
  }

  struct Case
  {
    std::string                        name;
    const materials::MaterialModel<3> *law;
  };
  const std::vector<Case> cases = {{"Yeoh K/G 1000", &rubber_1000},
                                   {"Yeoh K/G 50", &rubber_50},
                                   {"neo-Hooke K/G 5000", &neo_hooke}};

  double worst_tangent = 0., worst_gradient = 0.;
  for (const Case &c : cases)
    {
      elements::MixedUPElements mixed;
      mixed.initialize(dof_handler,
                       partitioner,
                       {{{0}, c.law, elements::Formulation::mixed_up}});
      check(mixed.n_elements() == 2, "two elements");
      VectorType  u(u0), f(partitioner);
      double      energy = 0.;
      const auto &force  = [&](const VectorType &displacement) {
        elements::ElementStepResult result;
        f = 0.;
        mixed.compute_residual(displacement, f, result);
        check(!result.failure.failed, "no element fails");
        energy = result.internal_energy;
        return f;
      };

      FullMatrix<double> K(n, n), K_fd(n, n);
      mixed.compute_tangents(u,
                             [&](const unsigned int *dofs, const double *Ke) {
                               for (unsigned int i = 0; i < 81; ++i)
                                 for (unsigned int j = 0; j < 81; ++j)
                                   K(dofs[i], dofs[j]) += Ke[81 * i + j];
                             });
      const VectorType f0(force(u));
      double           max_f = f0.linfty_norm(), gradient_error = 0.;
      for (unsigned int j = 0; j < n; ++j)
        {
          const double saved = u[j];
          u[j]               = saved + 1e-6;
          const VectorType f_plus(force(u));
          u[j] = saved - 1e-6;
          const VectorType f_minus(force(u));
          for (unsigned int i = 0; i < n; ++i)
            K_fd(i, j) = (f_plus[i] - f_minus[i]) / 2e-6;
          u[j] = saved + 1e-5;
          force(u);
          const double e_plus = energy;
          u[j]                = saved - 1e-5;
          force(u);
          const double e_minus = energy;
          u[j]                 = saved;
          gradient_error =
            std::max(gradient_error,
                     std::abs((e_plus - e_minus) / 2e-5 - f0[j]));
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
      worst_tangent         = std::max(worst_tangent, relative);
      worst_gradient        = std::max(worst_gradient, gradient_error / max_f);

      // The homogeneous deformation: tilde J = det F, tilde p = the law's
      // Cauchy pressure tr(tau)/(3 J), zero force at interior nodes (of
      // the Q2 mesh: the dofs whose support point is off the boundary).
      Tensor<2, 3> F = H;
      for (unsigned int d = 0; d < 3; ++d)
        F[d][d] += 1.;
      materials::MaterialResponse<3> response;
      c.law->evaluate(F,
                      ArrayView<const double>(),
                      ArrayView<double>(),
                      false,
                      response);
      const double J           = determinant(F);
      const double p           = trace(response.kirchhoff_stress) / (3. * J);
      double       field_error = 0.;
      for (unsigned int e = 0; e < mixed.n_elements(); ++e)
        {
          std::array<double, 27> dilatation, pressure;
          mixed.condensed_fields(u_homogeneous, e, dilatation, pressure);
          for (unsigned int q = 0; q < 27; ++q)
            field_error = std::max({field_error,
                                    std::abs(dilatation[q] / J - 1.),
                                    std::abs(pressure[q] / p - 1.)});
        }
      // The ParaView cell averages (cell_averages()): in the homogeneous
      // deformation every cell's Cauchy stress is the law's at F, tau / J,
      // its pressure -tr(sigma)/3 and its J det F.
      const Tensor<2, 3> sigma =
        Tensor<2, 3>(response.kirchhoff_stress) / J;
      const elements::CellAverages averages =
        mixed.cell_averages(u_homogeneous,
                            dof_handler.get_triangulation().n_active_cells());
      const unsigned int row[6] = {0, 1, 2, 0, 0, 1}, col[6] = {0, 1, 2, 1, 2, 2};
      double average_error = 0.;
      for (unsigned int cell = 0; cell < averages.jacobian.size(); ++cell)
        {
          for (unsigned int k = 0; k < 6; ++k)
            average_error =
              std::max(average_error,
                       std::abs(averages.cauchy_stress[k][cell] -
                                sigma[row[k]][col[k]]) /
                         sigma.norm());
          average_error =
            std::max({average_error,
                      std::abs(averages.pressure[cell] + p) / sigma.norm(),
                      std::abs(averages.jacobian[cell] / J - 1.)});
        }
      // (float output: 1e-6.)
      check(average_error < 1e-6,
            c.name + ": cell averages of the homogeneous deformation");
      const VectorType f_homogeneous(force(u_homogeneous));
      double           interior = 0.;
      const IndexSet   boundary = DoFTools::extract_boundary_dofs(dof_handler);
      for (unsigned int i = 0; i < n; ++i)
        if (!boundary.is_element(i))
          interior = std::max(interior, std::abs(f_homogeneous[i]));
      interior /= f_homogeneous.linfty_norm();

      out() << c.name << ": max |K| " << std::setprecision(6) << max_K
            << " kN/mm, symmetric: "
            << (asymmetry < 1e-10 * max_K ? "yes" : "no")
            << ", FD error below 1e-7: " << (relative < 1e-7 ? "yes" : "no")
            << ", force = energy gradient to 1e-7: "
            << (gradient_error < 1e-7 * max_f ? "yes" : "no")
            << ", homogeneous fields exact: "
            << (field_error < 1e-12 ? "yes" : "no")
            << ", cell averages = the law's stress to float precision: "
            << (average_error < 1e-6 ? "yes" : "no")
            << ", interior residual zero: " << (interior < 1e-12 ? "yes" : "no")
            << std::endl;
      std::cerr << c.name << ": tangent error " << sci(relative)
                << ", energy-gradient error " << sci(gradient_error / max_f)
                << ", asymmetry " << sci(asymmetry / max_K)
                << ", homogeneous field error " << sci(field_error)
                << ", interior residual " << sci(interior) << std::endl;
      check(asymmetry < 1e-10 * max_K, "symmetric tangent");
      check(field_error < 1e-12, "homogeneous condensed fields exact");
      check(interior < 1e-12, "interior residual of a homogeneous state");
    }
  std::cerr << "largest tangent error " << sci(worst_tangent)
            << ", largest energy-gradient error " << sci(worst_gradient)
            << std::endl;
  check(worst_tangent < 1e-7, "tangent = derivative of the residual to 1e-7");
  check(worst_gradient < 1e-7, "residual = gradient of the energy to 1e-7");
}
