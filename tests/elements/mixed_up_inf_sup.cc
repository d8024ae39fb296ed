// The numerical inf-sup test of Chapelle and Bathe ("The inf-sup test",
// Computers & Structures 47 (1993) 537-545) for the pressure-displacement
// pairing of the mixed u-p element (MixedUPElements: Q2 displacement, P1
// pressure discontinuous per cell, linear in the reference coordinates,
// doc/theory.md section 11.4), and for the unstable Q1-P0 pairing with the
// same code, so that the test can fail.
//
// The problem: the unit cube, clamped on its whole boundary (u = 0), meshes
// of n x n x n cubes, n = 2, 3, 4, 6. With S the vector Laplacian
// (int grad u : grad v, the H1 seminorm, a norm on the clamped space), B the
// divergence (int q div v) and T the pressure mass matrix (int p q), the
// discrete inf-sup constant is
//   beta_h^2 = the smallest non-zero eigenvalue of B S^-1 B^T p = lambda T p
// (the smallest non-zero eigenvalue: the constant pressure, and any
// spurious pressure mode, is in the kernel of B^T and gives lambda = 0; an
// eigenvalue below 1e-10 of the largest counts as zero: the largest is at
// most 1 (|div v| <= |grad v| in L2 on the clamped space), those counted
// as zero are below 2e-15 and the smallest non-zero one is 8.9e-3, so the
// threshold is far from both; printed to stderr). Chapelle and Bathe's
// criterion: a pairing passes when log beta_h against log h levels off as h ->
// 0 and fails when it keeps decreasing. Criteria asserted (their reasons and
// measured values in the output):
// - Q2-P1: one zero eigenvalue (the constant pressure) on every mesh, and
//   the slope s = d log beta_h / d log h between the last two meshes
//   below 0.1 in magnitude, and beta_h(6) >= 0.9 beta_h(2): bounded away
//   from zero;
// - Q1-P0: spurious zero modes (checkerboards) beyond the constant, and
//   beta_h decaying with slope above 0.5 over n = 2 to 6: unstable. If the
//   test's assembly or eigen-solve were wrong (e.g. a pressure space too
//   small to see the decay, or a wrong B), one of the two would not hold.
// Measured: Q2-P1 beta_h = 0.3946, 0.3942, 0.3853, 0.3770 (slopes 0.003,
// 0.079, 0.054: levelling off at about 0.37); Q1-P0 beta_h = 0.433,
// 0.254, 0.177, 0.095 (slopes 1.3 to 1.6, 4 to 16 spurious zero modes).
// Run time: about 10 s of CPU, nearly all in the 864 direct solves of
// Q2-P1 at n = 6.
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_renumbering.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_dgp_nonparametric.h>
#include <deal.II/fe/fe_dgq.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

#include "../tests.h"

using namespace dealii;
using testing::check;
using testing::out;
using testing::sci;

namespace
{
  struct InfSup
  {
    double       beta;
    unsigned int n_zero;
    unsigned int n_pressure;
  };

  /**
   * beta_h and the number of zero eigenvalues for displacement FE_Q(degree)^3
   * and the pressure element @p pressure on the n^3 unit cube.
   */
  InfSup
  inf_sup(const unsigned int      n,
          const unsigned int      degree,
          const FiniteElement<3> &pressure)
  {
    Triangulation<3> tria;
    GridGenerator::subdivided_hyper_cube(tria, n, 0., 1.);
    FESystem<3>   fe(FE_Q<3>(degree), 3, pressure, 1);
    DoFHandler<3> dof_handler(tria);
    dof_handler.distribute_dofs(fe);
    DoFRenumbering::component_wise(dof_handler, {0, 0, 0, 1});
    const std::vector<types::global_dof_index> per_block =
      DoFTools::count_dofs_per_fe_block(dof_handler, {0, 0, 0, 1});
    const unsigned int n_u = per_block[0], n_p = per_block[1],
                       n_all = n_u + n_p;

    AffineConstraints<double> constraints;
    DoFTools::make_zero_boundary_constraints(dof_handler,
                                             constraints,
                                             ComponentMask(
                                               {true, true, true, false}));
    constraints.close();
    // A couples each component with itself only (the vector Laplacian
    // and the pressure mass), D the pressure with the displacement: with
    // these patterns the direct solver sees three scalar Laplacians.
    Table<2, DoFTools::Coupling> couple_A(4, 4), couple_D(4, 4);
    for (unsigned int c = 0; c < 4; ++c)
      for (unsigned int d = 0; d < 4; ++d)
        {
          couple_A(c, d) = c == d ? DoFTools::always : DoFTools::none;
          couple_D(c, d) = c == 3 && d < 3 ? DoFTools::always : DoFTools::none;
        }
    SparsityPattern pattern_A, pattern_D;
    {
      DynamicSparsityPattern dsp(n_all, n_all);
      DoFTools::make_sparsity_pattern(dof_handler,
                                      couple_A,
                                      dsp,
                                      constraints,
                                      true);
      pattern_A.copy_from(dsp);
    }
    {
      DynamicSparsityPattern dsp(n_all, n_all);
      DoFTools::make_sparsity_pattern(dof_handler,
                                      couple_D,
                                      dsp,
                                      constraints,
                                      true);
      pattern_D.copy_from(dsp);
    }
    // A = [S 0; 0 T] (S with the clamped rows eliminated), D = [0 0; B 0].
    SparseMatrix<double> A(pattern_A), D(pattern_D);

    const QGauss<3>    quadrature(degree + 1);
    FEValues<3>        fe_values(fe,
                          quadrature,
                          update_values | update_gradients | update_JxW_values |
                            update_quadrature_points);
    const unsigned int n_dofs = fe.n_dofs_per_cell();
    FullMatrix<double> local_A(n_dofs, n_dofs), local_D(n_dofs, n_dofs);
    std::vector<types::global_dof_index> dofs(n_dofs);
    const FEValuesExtractors::Vector     u(0);
    const FEValuesExtractors::Scalar     p(3);
    std::vector<Tensor<2, 3>>            grad_u(n_dofs);
    std::vector<double>                  div_u(n_dofs), value_p(n_dofs);
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        fe_values.reinit(cell);
        local_A = 0.;
        local_D = 0.;
        for (unsigned int q = 0; q < quadrature.size(); ++q)
          {
            const double w = fe_values.JxW(q);
            for (unsigned int i = 0; i < n_dofs; ++i)
              {
                grad_u[i]  = fe_values[u].gradient(i, q);
                div_u[i]   = fe_values[u].divergence(i, q);
                value_p[i] = fe_values[p].value(i, q);
              }
            for (unsigned int i = 0; i < n_dofs; ++i)
              for (unsigned int j = 0; j < n_dofs; ++j)
                {
                  local_A(i, j) += w * (scalar_product(grad_u[i], grad_u[j]) +
                                        value_p[i] * value_p[j]);
                  local_D(i, j) += w * value_p[i] * div_u[j];
                }
          }
        cell->get_dof_indices(dofs);
        constraints.distribute_local_to_global(local_A, dofs, A);
        constraints.distribute_local_to_global(local_D, dofs, D);
      }

    const auto          start = std::chrono::steady_clock::now();
    SparseDirectUMFPACK solver;
    solver.initialize(A);
    const auto factored = std::chrono::steady_clock::now();
    // G = B S^-1 B^T column by column, and T, on the pressure dofs.
    LAPACKFullMatrix<double> G(n_p, n_p), T(n_p, n_p);
    Vector<double>           e(n_all), rhs(n_all), x(n_all), y(n_all);
    for (unsigned int k = 0; k < n_p; ++k)
      {
        e          = 0.;
        e[n_u + k] = 1.;
        D.Tvmult(rhs, e);
        for (unsigned int i = 0; i < n_all; ++i)
          if (constraints.is_constrained(i))
            rhs[i] = 0.;
        solver.vmult(x, rhs);
        D.vmult(y, x);
        for (unsigned int l = 0; l < n_p; ++l)
          {
            G(l, k) = y[n_u + l];
            T(l, k) = A.el(n_u + l, n_u + k);
          }
      }
    const auto solved = std::chrono::steady_clock::now();
    // Symmetrise the round-off of the solves before LAPACK's symmetric
    // generalised eigen-solver.
    for (unsigned int k = 0; k < n_p; ++k)
      for (unsigned int l = 0; l < k; ++l)
        G(l, k) = G(k, l) = 0.5 * (G(l, k) + G(k, l));
    std::vector<Vector<double>> eigenvectors(n_p, Vector<double>(n_p));
    G.compute_generalized_eigenvalues_symmetric(T, eigenvectors);
    std::vector<double> lambda(n_p);
    for (unsigned int k = 0; k < n_p; ++k)
      lambda[k] = G.eigenvalue(k).real();
    std::sort(lambda.begin(), lambda.end());
    std::cerr << "n = " << n << ", degree " << degree << ": solves "
              << std::chrono::duration<double>(solved - start).count()
              << " s (factorisation "
              << std::chrono::duration<double>(factored - start).count()
              << " s), eigenvalues "
              << std::chrono::duration<double>(
                   std::chrono::steady_clock::now() - solved)
                   .count()
              << " s" << std::endl;
    const double largest = lambda.back();
    InfSup       result{0., 0, n_p};
    double       largest_zero = 0.;
    for (const double l : lambda)
      if (l < 1e-10 * largest)
        {
          ++result.n_zero;
          largest_zero = std::max(largest_zero, std::abs(l));
        }
      else
        {
          result.beta = std::sqrt(l);
          break;
        }
    std::cerr << "  largest eigenvalue " << largest
              << ", largest of those counted as zero " << largest_zero
              << std::endl;
    return result;
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::vector<unsigned int>  meshes = {2, 3, 4, 6};
  const FE_DGPNonparametric<3>     p1(1);
  const FE_DGQ<3>                  p0(0);

  struct Pairing
  {
    std::string             name;
    unsigned int            degree;
    const FiniteElement<3> *pressure;
    std::vector<InfSup>     results;
  };
  std::vector<Pairing> pairings = {{"Q2-P1 (mixed u-p)", 2, &p1, {}},
                                   {"Q1-P0", 1, &p0, {}}};
  for (Pairing &pairing : pairings)
    {
      out() << pairing.name << ":" << std::endl;
      for (unsigned int m = 0; m < meshes.size(); ++m)
        {
          const InfSup r =
            inf_sup(meshes[m], pairing.degree, *pairing.pressure);
          pairing.results.push_back(r);
          out() << "  n = " << meshes[m] << ": " << r.n_pressure
                << " pressures, " << r.n_zero << " zero eigenvalues, beta_h "
                << std::fixed << std::setprecision(4) << r.beta;
          if (m > 0)
            out() << ", slope d log beta / d log h "
                  << std::log(r.beta / pairing.results[m - 1].beta) /
                       std::log(double(meshes[m - 1]) / meshes[m]);
          out() << std::defaultfloat << std::endl;
        }
    }

  const std::vector<InfSup> &stable   = pairings[0].results,
                            &unstable = pairings[1].results;
  const unsigned int last             = meshes.size() - 1;
  const double       stable_slope =
    std::log(stable[last].beta / stable[last - 1].beta) /
    std::log(double(meshes[last - 1]) / meshes[last]);
  const double unstable_slope =
    std::log(unstable[last].beta / unstable[0].beta) /
    std::log(double(meshes[0]) / meshes[last]);
  bool one_zero = true, spurious = true;
  for (unsigned int m = 0; m < meshes.size(); ++m)
    {
      one_zero = one_zero && stable[m].n_zero == 1;
      spurious = spurious && unstable[m].n_zero > 1;
    }
  out() << "Q2-P1: only the constant pressure in the kernel: "
        << (one_zero ? "yes" : "no") << ", |slope| of the last pair below 0.1: "
        << (std::abs(stable_slope) < 0.1 ? "yes" : "no")
        << ", beta_h(6) >= 0.9 beta_h(2): "
        << (stable[last].beta >= 0.9 * stable[0].beta ? "yes" : "no")
        << std::endl;
  out() << "Q1-P0: spurious pressure modes: " << (spurious ? "yes" : "no")
        << ", slope over n = 2 to 6 above 0.5: "
        << (unstable_slope > 0.5 ? "yes" : "no") << std::endl;
  std::cerr << "Q2-P1 slope " << stable_slope << ", Q1-P0 slope "
            << unstable_slope << std::endl;
  check(one_zero, "Q2-P1: one zero eigenvalue");
  check(std::abs(stable_slope) < 0.1, "Q2-P1: beta_h levels off");
  check(stable[last].beta >= 0.9 * stable[0].beta, "Q2-P1: beta_h bounded");
  check(spurious, "Q1-P0: spurious modes");
  check(unstable_slope > 0.5, "Q1-P0: beta_h decays");
}
