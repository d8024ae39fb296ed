// Stable time step of single hexahedra against the closed form
// dt = l / c, c = sqrt((K + 4G/3) / rho), with the length of the bound of
// Flanagan and Belytschko (doc/theory.md section 8.3), which for a
// parallelepiped with edge vectors a, b, c is l = V / sqrt(|a x b|^2 +
// |b x c|^2 + |c x a|^2), V = |a . (b x c)| (its centre gradients are the
// dual basis b x c / V etc. divided by 4, and every node carries an eighth
// of the mass), for a cube (l = h / sqrt3), a brick and a skewed
// parallelepiped. Both the reference-configuration estimate (used for mass
// scaling) and the one of a force evaluation at rest (no bulk viscosity
// without a volume rate) must agree with it to 1e-12 relative.
#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <rubberdyn/elements/solid_hex_elements.h>
#include <rubberdyn/materials/elastic.h>

#include "../tests.h"

using namespace dealii;
using testing::check;
using testing::out;
using testing::sci;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double E = 210., nu = 0.3, rho = 7.85e-6;
  const rubberdyn::materials::Elastic<3> steel(E, nu, rho);
  const double G = E / (2. * (1. + nu)), K = E / (3. * (1. - 2. * nu));
  const double c = std::sqrt((K + 4. / 3. * G) / rho);
  out() << "wave speed of steel: " << std::setprecision(8) << c
        << " mm/ms" << std::endl;

  const std::vector<std::pair<std::string, std::array<Tensor<1, 3>, 3>>>
    shapes = {
      {"cube 2 mm", {{Tensor<1, 3>({2., 0., 0.}), Tensor<1, 3>({0., 2., 0.}),
                      Tensor<1, 3>({0., 0., 2.})}}},
      {"brick 1 x 2 x 3 mm",
       {{Tensor<1, 3>({1., 0., 0.}), Tensor<1, 3>({0., 2., 0.}),
         Tensor<1, 3>({0., 0., 3.})}}},
      {"skewed parallelepiped",
       {{Tensor<1, 3>({1.5, 0., 0.}), Tensor<1, 3>({0.4, 1.2, 0.}),
         Tensor<1, 3>({0.3, -0.2, 0.9})}}}};

  double worst = 0.;
  for (const auto &shape : shapes)
    {
      const auto &[a, b, d] = shape.second;
      Triangulation<3> tria;
      Point<3>         corners[3] = {Point<3>(a), Point<3>(b), Point<3>(d)};
      GridGenerator::parallelepiped(tria, corners);
      FESystem<3>   fe(FE_Q<3>(1), 3);
      DoFHandler<3> dof_handler(tria);
      dof_handler.distribute_dofs(fe);
      const auto partitioner = std::make_shared<Utilities::MPI::Partitioner>(
        dof_handler.locally_owned_dofs(), MPI_COMM_SELF);

      const double volume = std::abs(a * cross_product_3d(b, d));
      const double areas = std::sqrt(cross_product_3d(a, b).norm_square() +
                                     cross_product_3d(b, d).norm_square() +
                                     cross_product_3d(d, a).norm_square());
      const double exact = volume / areas / c;

      rubberdyn::elements::SolidHexElements elements;
      elements.initialize(dof_handler, partitioner, {{{0}, &steel, rubberdyn::elements::Formulation::fbar}}, {});
      const double reference = elements.reference_time_steps()[0];

      rubberdyn::VectorType u(partitioner), v(partitioner),
        f(partitioner);
      rubberdyn::elements::ElementStepResult result;
      elements.compute_forces(u, v, {1.}, f, result);

      const double error = std::max(std::abs(reference - exact),
                                    std::abs(result.min_time_step - exact)) /
                           exact;
      worst = std::max(worst, error);
      out() << shape.first << ": closed form " << std::setprecision(10)
            << exact << " ms, relative error " << sci(error) << std::endl;
    }
  check(worst < 1e-12, "stable step equals the closed form to 1e-12");
  out() << "all within 1e-12: yes" << std::endl;
}
