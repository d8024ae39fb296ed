// The ParaView field `equivalent_plastic_strain` (SolidHexElements::
// cell_averages()): a 3 x 2 x 2 block of 5 mm cells, the first two columns
// J2 steel (bolt grade 10.9: E = 210 GPa, nu = 0.3, yield 0.94 GPa, linear
// hardening to 1.04 GPa at alpha = 0.08), F-bar; the last column elastic
// steel, displacement element. A homogeneous isochoric stretch F =
// diag(l, l^-1/2, l^-1/2) is applied through the explicit element's force
// evaluation (compute_forces, then accept_history, as a time step does):
//
// 1. l = 1.02: every J2 cell's field equals the exact radial return of
//    Simo's model for this F, computed here from its closed form (b_e =
//    diag(l^2, 1/l, 1/l), s = G dev b_e, q = sqrt(3/2) |s|, mu_bar = G
//    tr(b_e)/3, alpha = (q - k0) / (3 mu_bar + H)); the elastic column
//    shows 0;
// 2. l = 1.0199 (unloading by 1e-4, below the elastic strain 0.94/210):
//    the field keeps the value of step 1;
// 3. l = 1.04: the field grows again, by the return from the accepted
//    history, equal to MaterialModel::evaluate() of the J2 law from that
//    history.
// The field is written in single precision: the values are compared to
// 1e-6 relative.
#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <rubberdyn/elements/solid_hex_elements.h>
#include <rubberdyn/materials/elastic.h>
#include <rubberdyn/materials/finite_strain_j2.h>
#include <rubberdyn/materials/hardening_curve.h>
#include <rubberdyn/materials/j2_plasticity.h>

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
  Triangulation<3>                 tria;
  GridGenerator::subdivided_hyper_rectangle(tria,
                                            {3, 2, 2},
                                            Point<3>(0., 0., 0.),
                                            Point<3>(15., 10., 10.));
  for (const auto &cell : tria.active_cell_iterators())
    cell->set_material_id(cell->center()[0] < 10. ? 1 : 2);
  FESystem<3>   fe(FE_Q<3>(1), 3);
  DoFHandler<3> dof_handler(tria);
  dof_handler.distribute_dofs(fe);
  const auto partitioner = std::make_shared<Utilities::MPI::Partitioner>(
    dof_handler.locally_owned_dofs(), MPI_COMM_SELF);

  const double E = 210., nu = 0.3, yield = 0.94, k_end = 1.04,
               alpha_end = 0.08;
  const double                       H = (k_end - yield) / alpha_end;
  const double                       G = E / (2. * (1. + nu));
  const materials::J2Plasticity<3>   bolt(E,
                                        nu,
                                        7.85e-6,
                                        materials::HardeningCurve(yield,
                                                                  {alpha_end},
                                                                  {k_end},
                                                                  "test"));
  const materials::Elastic<3>        steel(E, nu, 7.85e-6);
  elements::SolidHexElements         hexes;
  const elements::ElementSettings    settings;
  hexes.initialize(dof_handler,
                   partitioner,
                   {{{1}, &bolt, elements::Formulation::fbar},
                    {{2}, &steel, elements::Formulation::displacement}},
                   settings);

  // The field's values: J2 cells, elastic cells.
  const auto field = [&](const double stretch) {
    VectorType u(partitioner), v(partitioner), f(partitioner);
    const double F[3] = {stretch, 1. / std::sqrt(stretch),
                         1. / std::sqrt(stretch)};
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < dofs.size(); ++i)
          {
            const auto ci     = fe.system_to_component_index(i);
            const unsigned d  = ci.first;
            u[dofs[i]]        = (F[d] - 1.) * cell->vertex(ci.second)[d];
          }
      }
    elements::ElementStepResult result;
    hexes.compute_forces(
      u, v, std::vector<double>(hexes.n_elements(), 1.), f, result);
    check(!result.failure.failed, "no element fails");
    hexes.accept_history();
    const auto averages = hexes.cell_averages(u, tria.n_active_cells());
    std::vector<double> j2, elastic;
    for (const auto &cell : tria.active_cell_iterators())
      (cell->material_id() == 1 ? j2 : elastic)
        .push_back(
          averages.equivalent_plastic_strain[cell->active_cell_index()]);
    return std::make_pair(j2, elastic);
  };
  // The largest relative difference of the J2 cells' values from @p exact,
  // and the largest elastic value.
  const auto report = [&](const std::string &what,
                          const double       exact,
                          const std::pair<std::vector<double>,
                                          std::vector<double>> &values) {
    double worst = 0., elastic = 0.;
    for (const double a : values.first)
      worst = std::max(worst, std::abs(a - exact) / exact);
    for (const double a : values.second)
      elastic = std::max(elastic, std::abs(a));
    // (The field is written in single precision.)
    out() << what << ": alpha = " << exact << ", J2 cells within 1e-6: "
          << (worst < 1e-6 ? "yes" : "no") << ", elastic cells "
          << elastic << std::endl;
    std::cerr << what << ": largest relative difference " << sci(worst)
              << std::endl;
    check(worst < 1e-6, what + ": the J2 cells' field");
    check(elastic == 0., what + ": the elastic cells' field is 0");
  };

  // 1. The closed-form return from the virgin state.
  const double l = 1.02;
  const double b[3] = {l * l, 1. / l, 1. / l};
  const double Ie   = (b[0] + b[1] + b[2]) / 3.;
  double       s_norm_square = 0.;
  for (const double bi : b)
    s_norm_square += (G * (bi - Ie)) * (G * (bi - Ie));
  const double q      = std::sqrt(1.5 * s_norm_square);
  const double alpha1 = (q - yield) / (3. * G * Ie + H);
  check(alpha1 > 0.001, "the first stretch yields");
  report("stretch 1.02 from the virgin state", alpha1, field(l));

  // 2. Elastic unloading keeps it.
  report("unloading to 1.0199", alpha1, field(1.0199));

  // 3. Further loading: the law from the accepted history (that of step
  //    2: C_p^{-1} and alpha of the first return).
  std::vector<double> state_virgin(
    materials::finite_strain_j2::n_state_variables),
    state_1(state_virgin.size()), state_2(state_virgin.size()),
    state_3(state_virgin.size());
  bolt.initialize_state(make_array_view(state_virgin));
  materials::MaterialResponse<3> response;
  const auto isochoric = [](const double stretch) {
    Tensor<2, 3> F;
    F[0][0] = stretch;
    F[1][1] = F[2][2] = 1. / std::sqrt(stretch);
    return F;
  };
  bolt.evaluate(isochoric(l), make_array_view(state_virgin),
                make_array_view(state_1), false, response);
  bolt.evaluate(isochoric(1.0199), make_array_view(state_1),
                make_array_view(state_2), false, response);
  bolt.evaluate(isochoric(1.04), make_array_view(state_2),
                make_array_view(state_3), false, response);
  const double alpha3 =
    bolt.equivalent_plastic_strain(make_array_view(state_3));
  check(std::abs(alpha1 - bolt.equivalent_plastic_strain(
                            make_array_view(state_1))) < 1e-12 * alpha1,
        "the law's first return is the closed form");
  check(alpha3 > 1.5 * alpha1, "the third stretch yields further");
  report("stretch 1.04 from the accepted history", alpha3, field(1.04));
}
