// F-bar collapse detection (doc/theory.md section 8.1): an F-bar element
// fails when a Gauss point's volume ratio r_q = J_q / J_0 falls below
// ElementSettings::fbar_collapse_ratio (default 0.25), with a message that
// names the entry to change. On one 2 mm cube of rubber, default settings:
// - uniform compression to 30 % of the height (lateral stretch 1/sqrt(0.3),
//   J = 1): r_q = 1 at every Gauss point, no failure;
// - the cube pinched: its corner (2, 2, 2) pushed towards the centre by
//   1 mm in each direction, so the Gauss point next to it keeps
//   r = 0.11 while the centre keeps 62 % of its volume: fails as an F-bar
//   collapse, naming the cell and its centre, with
//   "Time integration/F-bar stabilization" in the message;
// - a milder pinch (0.6 mm, r ~ 0.57) does not fail;
// - the pinched cube does not fail with the check off (ratio 0) nor with
//   the displacement element (the check is F-bar's).
// The reported smallest ratio is checked against J_q / J_0 from deal.II's
// own MappingQ1 Jacobians of the deformed cell (1e-12).
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <rubberdyn/elements/solid_hex_elements.h>
#include <rubberdyn/materials/yeoh.h>

#include "../tests.h"

using namespace dealii;
using namespace rubberdyn;
using testing::check;
using testing::out;
using testing::sci;

namespace
{
  // Smallest J_q / J_0 of the cell deformed by the vertex displacements
  // du, from a mapping of the deformed vertices.
  double
  independent_min_ratio(const std::vector<Point<3>> &X,
                        const std::vector<Tensor<1, 3>> &du)
  {
    Triangulation<3> deformed;
    std::vector<Point<3>> x(8);
    for (unsigned int a = 0; a < 8; ++a)
      x[a] = X[a] + du[a];
    std::vector<CellData<3>> cells(1);
    for (unsigned int a = 0; a < 8; ++a)
      cells[0].vertices[a] = a;
    deformed.create_triangulation(x, cells, SubCellData());
    const FE_Q<3>       fe(1);
    const MappingQ1<3>  mapping;
    const QGauss<3>     gauss(2);
    const Quadrature<3> centre(Point<3>(0.5, 0.5, 0.5));
    FEValues<3>         at_gauss(mapping, fe, gauss, update_jacobians);
    FEValues<3>         at_centre(mapping, fe, centre, update_jacobians);
    at_gauss.reinit(deformed.begin_active());
    at_centre.reinit(deformed.begin_active());
    // J = det(dx/dxi) / det(dX/dxi); the reference cube's det(dX/dxi) is
    // the same at every point (h^3).
    const double J0 = determinant(Tensor<2, 3>(at_centre.jacobian(0)));
    double       r  = 1e300;
    for (unsigned int q = 0; q < gauss.size(); ++q)
      r = std::min(r, determinant(Tensor<2, 3>(at_gauss.jacobian(q))) / J0);
    return r;
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double                     h = 2.;
  Triangulation<3>                 tria;
  GridGenerator::hyper_cube(tria, 0., h);
  FESystem<3>   fe(FE_Q<3>(1), 3);
  DoFHandler<3> dof_handler(tria);
  dof_handler.distribute_dofs(fe);
  const auto partitioner = std::make_shared<Utilities::MPI::Partitioner>(
    dof_handler.locally_owned_dofs(), MPI_COMM_SELF);
  const auto cell = dof_handler.begin_active();
  std::vector<Point<3>> X(8);
  for (unsigned int a = 0; a < 8; ++a)
    X[a] = cell->vertex(a);

  // The shipped rubber (nu = 0.499).
  const double G = 1.1e-3, nu = 0.499;
  const double K = 2. * G * (1. + nu) / (3. * (1. - 2. * nu));
  const materials::Yeoh<3> rubber(0.55e-3,
                                  -0.05e-3,
                                  0.015e-3,
                                  std::array<double, 3>{{2. / K, 0., 0.}},
                                  1.1e-6);

  struct Case
  {
    std::string               name;
    std::vector<Tensor<1, 3>> du;
  };
  std::vector<Case> cases;
  {
    Case uniform{"uniform compression to 30 %", std::vector<Tensor<1, 3>>(8)};
    const double lambda = 0.3, lateral = 1. / std::sqrt(lambda);
    for (unsigned int a = 0; a < 8; ++a)
      uniform.du[a] = Tensor<1, 3>({(lateral - 1.) * X[a][0],
                                    (lateral - 1.) * X[a][1],
                                    (lambda - 1.) * X[a][2]});
    cases.push_back(uniform);
    for (const double pinch : {1.0, 0.6})
      {
        Case pinched{"corner pinched by " + std::to_string(pinch).substr(0, 3) +
                       " mm",
                     std::vector<Tensor<1, 3>>(8)};
        pinched.du[7] = Tensor<1, 3>({-pinch, -pinch, -pinch});
        cases.push_back(pinched);
      }
  }

  bool all_right = true;
  for (const Case &c : cases)
    {
      VectorType u(partitioner), v(partitioner);
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      cell->get_dof_indices(dofs);
      for (unsigned int i = 0; i < dofs.size(); ++i)
        {
          const auto ci = fe.system_to_component_index(i);
          u[dofs[i]]    = c.du[ci.second][ci.first];
        }
      const double r_exact = independent_min_ratio(X, c.du);
      const bool   collapse_expected = (r_exact < 0.25);
      out() << c.name << ": smallest J_q/J_0 " << std::setprecision(4)
            << r_exact << std::endl;

      // The advice is the caller's (simulation::setup::element_groups
      // composes it from the input entries); the element layer appends it.
      struct Variant
      {
        std::string                 name;
        elements::Formulation       formulation;
        double                      beta;
        elements::ElementSettings   settings;
        bool                        check_on;
      };
      elements::ElementSettings defaults, off;
      off.fbar_collapse_ratio = 0.;
      for (const Variant &variant :
           std::vector<Variant>{
             {"F-bar, defaults", elements::Formulation::fbar, 0., defaults, true},
             {"F-bar, beta 0.03", elements::Formulation::fbar, 0.03, defaults, true},
             {"F-bar, check off", elements::Formulation::fbar, 0., off, false},
             {"displacement", elements::Formulation::displacement, 0., defaults, false}})
        {
          const std::string advice =
            variant.beta < 0.03 ?
              "set Time integration/F-bar stabilization to 0.03 or more" :
              "raise Time integration/F-bar stabilization above 0.03";
          elements::SolidHexElements hexes;
          hexes.initialize(
            dof_handler,
            partitioner,
            {{{0}, &rubber, variant.formulation, variant.beta, advice}},
            variant.settings);
          VectorType                  f(partitioner);
          elements::ElementStepResult result;
          hexes.compute_forces(u, v, {1.}, f, result);
          const bool should_fail = variant.check_on && collapse_expected;
          bool       right       = (result.failure.failed == should_fail);
          if (should_fail)
            right = right &&
                    result.failure.kind == elements::FailureKind::fbar_collapse &&
                    result.failure.cell_id == cell->id().to_string() &&
                    result.failure.position.distance(cell->center()) < 1e-12 &&
                    result.failure.message.size() > advice.size() &&
                    result.failure.message.compare(
                      result.failure.message.size() - advice.size(),
                      advice.size(),
                      advice) == 0;
          if (variant.formulation == elements::Formulation::fbar)
            {
              const double error =
                std::abs(result.min_volume_ratio - std::min(r_exact, 1.));
              std::cerr << c.name << ", " << variant.name
                        << ": reported ratio error " << sci(error) << std::endl;
              right = right && error < 1e-12;
            }
          out() << "  " << variant.name << ": "
                << (result.failure.failed ?
                      "fails: cell " + result.failure.cell_id + ", " +
                        result.failure.message :
                      std::string("no failure"))
                << " (as expected: " << (right ? "yes" : "no") << ")"
                << std::endl;
          all_right = all_right && right;
        }
    }
  check(all_right, "collapse detected exactly where expected");
}
