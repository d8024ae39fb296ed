// The stable step of the penalty springs counts every surface a node
// touches (contact::RigidSurfaceContact::stable_time_step): a node pressed
// by two rigid planes hangs on both springs in parallel, omega^2 =
// (k_1 + k_2) / m, and its step is 2 sqrt(m / (k_1 + k_2)), not the
// 2 sqrt(m / k) of one spring (central differences are stable for
// omega dt <= 2; issue "Reliability of the explicit engine").
//
// One 2 mm cube of steel (E = 210 GPa, nu = 0.3, 7.85e-6 kg/mm^3), lumped
// mass m = rho h^3 / 8 per node; contact on its faces x = 0 and z = 0,
// each face spring s K A^2 / V = s K h (s = 0.1 the penalty scale, K the
// bulk modulus) shared by its 4 nodes. The two nodes on the edge x = z = 0
// belong to both faces, k = 2 s K h / 4 = s K h / 2, the other contact
// nodes to one, k = s K h / 4. Three states of the planes z = d (normal
// +z) and x = d (normal +x), d = 0.01 mm inside the cube or 1 mm outside:
//   none pressing:  every node on one spring at most, the edge nodes
//                   stiffest: 2 sqrt(m / (s K h / 2));
//   z pressing:     the same;
//   both pressing:  the edge nodes on both, k_1 + k_2 = s K h:
//                   2 sqrt(m / (s K h)), 1/sqrt(2) of the others.
// Each must equal the closed form to 1e-14 relative (a few operations on
// exact data).
#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <rubberdyn/contact/rigid_surface_contact.h>
#include <rubberdyn/elements/solid_hex_elements.h>
#include <rubberdyn/materials/elastic.h>

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
  const double                     E = 210., nu = 0.3, rho = 7.85e-6;
  const double                     h = 2., s = 0.1;
  const double                     K = E / (3. * (1. - 2. * nu));
  const materials::Elastic<3>      steel(E, nu, rho);

  Triangulation<3> tria;
  // Colorized: x = 0 is boundary id 0, z = 0 boundary id 4.
  GridGenerator::hyper_cube(tria, 0., h, true);
  const FESystem<3> fe(FE_Q<3>(1), 3);
  DoFHandler<3>     dof_handler(tria);
  dof_handler.distribute_dofs(fe);
  const auto partitioner = std::make_shared<Utilities::MPI::Partitioner>(
    dof_handler.locally_owned_dofs(),
    MPI_COMM_SELF);

  elements::SolidHexElements hexes;
  hexes.initialize(dof_handler,
                   partitioner,
                   {{{0}, &steel, elements::Formulation::fbar}},
                   {});
  VectorType mass(partitioner);
  hexes.add_lumped_mass(mass, {1.});
  const double m = rho * h * h * h / 8.;
  check(std::abs(mass.local_element(0) - m) <= 1e-15 * m,
        "lumped mass rho h^3 / 8");

  const std::vector<double> bulk_modulus = {K};
  const double              k_face       = s * K * h;
  struct State
  {
    std::string name;
    double      d_z, d_x, expected;
  };
  const std::vector<State> states = {
    {"none pressing", -1., -1., 2. * std::sqrt(m / (k_face / 2.))},
    {"z pressing", 0.01, -1., 2. * std::sqrt(m / (k_face / 2.))},
    {"both pressing", 0.01, 0.01, 2. * std::sqrt(m / k_face)}};
  for (const State &state : states)
    {
      contact::RigidSurface plane_z, plane_x;
      plane_z.point  = Point<3>(0., 0., state.d_z);
      plane_z.normal = Tensor<1, 3>({0., 0., 1.});
      plane_x.point  = Point<3>(state.d_x, 0., 0.);
      plane_x.normal = Tensor<1, 3>({1., 0., 0.});
      contact::RigidSurfaceContact contact;
      contact.initialize(dof_handler,
                         partitioner,
                         {0, 4},
                         bulk_modulus,
                         s,
                         {plane_z, plane_x});
      VectorType             u(partitioner), f(partitioner);
      contact::ContactResult result;
      contact.add_forces(u, std::vector<contact::SurfacePose>(2), f, result);
      const double step  = contact.stable_time_step(mass);
      const double error = std::abs(step - state.expected) / state.expected;
      out() << state.name << ": contact step " << std::setprecision(8) << step
            << " ms, closed form " << state.expected
            << " ms, relative error below 1e-14: "
            << (error <= 1e-14 ? "yes" : "no") << std::endl;
      check(error <= 1e-14,
            state.name + ": the contact step is off by " + sci(error));
    }
}
