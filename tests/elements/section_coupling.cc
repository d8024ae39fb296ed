// A pretension section (SolidHexElements::cut_sections()) and its coupling
// terms for the quasi-static solver (compute_section_couplings()) are the
// exact derivatives of the elements' energy and forces with respect to the
// section's shortening delta (doc/theory.md, section 12):
//   N = dPi/d delta (the section force, ElementStepResult::section_force),
//   K g = d f / d delta,  K^T g = d N / d u,  g^T K g = dN / d delta,
// and the tangent (compute_tangents()) of a cut element is still d f / d u
// (its offset nodes included).
// Checked against central differences (h = 1e-6 mm; for N against the
// energy, h = 1e-4 mm) on the distorted block of 3 x 2 x 1 hexahedra, cut
// by an inclined plane through the middle column only, at a
// pre-deformation with shear and a random perturbation of every dof and
// delta = 0.3 mm. Laws: Yeoh with K/G = 1000, F-bar stabilised (beta 0.1)
// and displacement; finite-strain J2 plasticity past yield, F-bar (not an
// energy gradient: N against the energy is skipped, the couplings are not
// symmetric). Criterion 1e-7 of the largest entry (truncation ~h^2,
// rounding ~1e-16 |f| / h; measured 1e-10 to 1e-9, printed to stderr). The
// cut counts follow from the geometry: the plane x ~ 7.2 crosses the two
// cells of the middle column and no other; a plane through both the first
// and the second column's cells and a second plane through the second
// column are refused (an element cut twice).
#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/tria.h>

#include <rubberdyn/elements/solid_hex_elements.h>
#include <rubberdyn/materials/hardening_curve.h>
#include <rubberdyn/materials/j2_plasticity.h>
#include <rubberdyn/materials/yeoh.h>

#include <random>
#include <stdexcept>

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
  const fixtures::DistortedBlock   block(3, 2);
  const FESystem<3>               &fe          = block.fe;
  const DoFHandler<3>             &dof_handler = block.dof_handler;
  const auto                      &partitioner = block.partitioner;
  const unsigned int               n           = dof_handler.n_dofs();

  const double             C10 = 0.55e-3, C20 = -0.05e-3, C30 = 0.015e-3;
  const double             K_rubber = 1000. * 2. * C10;
  const materials::Yeoh<3> rubber(C10,
                                  C20,
                                  C30,
                                  std::array<double, 3>{{2. / K_rubber, 0., 0.}},
                                  1.1e-6);
  const materials::J2Plasticity<3> steel(
    210.,
    0.3,
    7.85e-6,
    materials::HardeningCurve::parse(0.3, "0.1:0.5", "test"));

  std::mt19937                           generator(11);
  std::uniform_real_distribution<double> jitter(-1., 1.);
  VectorType                             u0(partitioner);
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
            u0[dofs[i]] = (d == 0 ? 0.1 * X[2] : 0.) + (d == 2 ? -0.02 * X[2] : 0.);
          }
      }
    for (unsigned int i = 0; i < n; ++i)
      u0[i] += 0.05 * jitter(generator);
  }

  // The plane x ~ 7.2, tilted: crosses the middle column (x in [5, 10],
  // moved by at most 0.5 by the distortion) only.
  Tensor<1, 3> normal;
  normal[0] = 1.;
  normal[1] = 0.1;
  normal[2] = 0.05;
  normal /= normal.norm();
  const elements::SectionPlane plane{Point<3>(7.2, 4., 2.5), normal, 0};

  struct Case
  {
    std::string                        name;
    const materials::MaterialModel<3> *law;
    elements::Formulation              formulation;
    double                             stabilization;
  };
  const std::vector<Case> cases = {
    {"Yeoh K/G 1000, F-bar stabilised", &rubber, elements::Formulation::fbar, 0.1},
    {"Yeoh K/G 1000, displacement",
     &rubber,
     elements::Formulation::displacement,
     0.},
    {"J2 plasticity, F-bar", &steel, elements::Formulation::fbar, 0.}};

  double worst = 0.;
  for (const Case &c : cases)
    {
      elements::SolidHexElements hexes;
      hexes.initialize(dof_handler,
                       partitioner,
                       {{{0}, c.law, c.formulation, c.stabilization}},
                       {0.06, 1.5, 0.});
      const std::vector<unsigned int> n_cut = hexes.cut_sections({plane});
      out() << c.name << ": cut elements " << n_cut[0] << std::endl;
      check(n_cut[0] == 2, "the plane cuts the two cells of the middle column");

      const std::vector<double> no_scaling(hexes.n_elements(), 1.);
      VectorType                u(u0), v(partitioner), f(partitioner);
      double                    delta = 0.3;
      elements::ElementStepResult result;
      const auto                  evaluate = [&]() {
        hexes.set_section_shortenings({delta});
        f = 0.;
        hexes.compute_forces(u, v, no_scaling, f, result);
        check(!result.failure.failed, "no element fails");
      };

      // Tension: the cut layer is stretched by delta at u = 0.
      {
        const VectorType saved(u);
        u = 0.;
        evaluate();
        out() << "  force at u = 0 is a tension: "
              << (result.section_force[0] > 0. ? "yes" : "no") << std::endl;
        check(result.section_force[0] > 0., "N > 0 at u = 0, delta > 0");
        u = saved;
      }

      // The couplings at (u0, delta).
      hexes.set_section_shortenings({delta});
      Vector<double> K_g(n), KT_g(n);
      double         gKg = 0.;
      hexes.compute_section_couplings(u,
                                      [&](const unsigned int *dofs,
                                          const unsigned int  s,
                                          const double       *kg,
                                          const double       *ktg,
                                          const double        gkg) {
                                        check(s == 0, "one section");
                                        for (unsigned int i = 0; i < 24; ++i)
                                          {
                                            K_g(dofs[i]) += kg[i];
                                            KT_g(dofs[i]) += ktg[i];
                                          }
                                        gKg += gkg;
                                      });
      FullMatrix<double> K(n, n);
      hexes.compute_tangents(u, [&](const unsigned int *dofs, const double *Ke) {
        for (unsigned int i = 0; i < 24; ++i)
          for (unsigned int j = 0; j < 24; ++j)
            K(dofs[i], dofs[j]) += Ke[24 * i + j];
      });
      evaluate();
      const double N0 = result.section_force[0];

      const double h = 1e-6;
      // d f / d delta and dN / d delta.
      delta = 0.3 + h;
      evaluate();
      const VectorType f_plus(f);
      const double     N_plus = result.section_force[0];
      delta                   = 0.3 - h;
      evaluate();
      const VectorType f_minus(f);
      const double     N_minus = result.section_force[0];
      delta                    = 0.3;
      double max_Kg = 0., error_Kg = 0.;
      for (unsigned int i = 0; i < n; ++i)
        {
          max_Kg = std::max(max_Kg, std::abs(K_g(i)));
          error_Kg =
            std::max(error_Kg,
                     std::abs(K_g(i) - (f_plus[i] - f_minus[i]) / (2. * h)));
        }
      const double error_gKg =
        std::abs(gKg - (N_plus - N_minus) / (2. * h)) / std::abs(gKg);
      // dN / du and d f / du, column by column.
      double max_KTg = 0., error_KTg = 0., max_K = 0., error_K = 0.;
      for (unsigned int j = 0; j < n; ++j)
        {
          const double saved = u[j];
          u[j]               = saved + h;
          evaluate();
          const VectorType column_plus(f);
          const double     n_plus = result.section_force[0];
          u[j]                    = saved - h;
          evaluate();
          const double n_minus = result.section_force[0];
          u[j]                 = saved;
          max_KTg              = std::max(max_KTg, std::abs(KT_g(j)));
          error_KTg            = std::max(
            error_KTg, std::abs(KT_g(j) - (n_plus - n_minus) / (2. * h)));
          for (unsigned int i = 0; i < n; ++i)
            {
              max_K   = std::max(max_K, std::abs(K(i, j)));
              // (f holds the forces at u_j - h.)
              error_K = std::max(error_K,
                                 std::abs(K(i, j) -
                                          (column_plus[i] - f[i]) / (2. * h)));
            }
        }
      const double relative[4] = {error_Kg / max_Kg,
                                  error_KTg / max_KTg,
                                  error_gKg,
                                  error_K / max_K};
      std::cerr << c.name << ": K g " << sci(relative[0]) << ", K^T g "
                << sci(relative[1]) << ", g^T K g " << sci(relative[2])
                << ", K " << sci(relative[3]) << std::endl;
      for (const double r : relative)
        worst = std::max(worst, r);

      // N = dPi / d delta (hyperelastic laws: the force is an energy
      // gradient).
      if (c.law == &rubber)
        {
          const double H = 1e-4;
          delta          = 0.3 + H;
          evaluate();
          const double energy_plus = result.internal_energy;
          delta                    = 0.3 - H;
          evaluate();
          const double energy_minus = result.internal_energy;
          delta                     = 0.3;
          const double error =
            std::abs(N0 - (energy_plus - energy_minus) / (2. * H)) /
            std::abs(N0);
          std::cerr << "  N against dPi/d delta " << sci(error) << std::endl;
          out() << "  N = dPi/d delta to 1e-7: "
                << (error < 1e-7 ? "yes" : "no") << std::endl;
          worst = std::max(worst, error);
        }
      out() << "  couplings = derivatives to 1e-7: "
            << (std::max({relative[0], relative[1], relative[2], relative[3]}) <
                    1e-7 ?
                  "yes" :
                  "no")
            << std::endl;
    }
  check(worst < 1e-7, "section terms = derivatives to 1e-7");

  // An element cut by two sections is refused.
  {
    elements::SolidHexElements hexes;
    hexes.initialize(dof_handler,
                     partitioner,
                     {{{0}, &rubber, elements::Formulation::fbar}},
                     {0.06, 1.5, 0.});
    Tensor<1, 3> z;
    z[2] = 1.;
    bool refused = false;
    try
      {
        hexes.cut_sections({plane, {Point<3>(0., 0., 2.5), z, 0}});
      }
    catch (const std::invalid_argument &e)
      {
        refused = true;
        out() << "two sections through one element: " << e.what() << std::endl;
      }
    check(refused, "an element cut twice is refused");
  }
}
