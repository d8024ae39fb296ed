// Tied mortar contact (contact::MortarContactPair, Type = tied) with the
// motion prescribed: the block of parameter_files/meshes/block_on_plate.msh
// (10 x 10 mm bottom, 5 x 5 faces) tied to the plate (4 x 4 faces:
// non-matching) where it stands on it (gap 0, Tie tolerance 0).
//  1. Patch test of the tying: a displacement field linear in X and the
//     same on both bodies (a homogeneous deformation, continuous across
//     the interface) leaves every tied gap at zero, so the pair exerts no
//     force (every nodal force below 1e-12 of eps |E| A h, eps the penalty
//     per area, A = 100 mm^2, h = 1 mm).
//  2. A rigid translation w of the block against the plate gives every
//     tied node the traction -eps w (uniform: the normal part, the nodal
//     "pressure", has max = min), and the pair's force on the block is -eps
//     w A (relative 1e-11), balanced by the force on the plate (sum of all
//     nodal forces below 1e-12 of it).
//  3. The tied nodes: the 36 nodes of the block's bottom.
// Run on 1 and 2 ranks.
#include <deal.II/base/mpi.h>
#include <deal.II/base/tensor.h>

#include <rubberdyn/contact/mortar_contact_pair.h>
#include <rubberdyn/model/force_contribution.h>
#include <rubberdyn/model/model.h>

#include <cmath>

#include "../model/model_fixtures.h"
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
  const MPI_Comm                   comm = MPI_COMM_WORLD;
  const bool root = Utilities::MPI::this_mpi_process(comm) == 0;

  model::Model model(comm);
  fixtures::make_block_on_plate(model, fixtures::rubber_part("block", 1));

  model::ContactPairDefinition definition;
  definition.name                = "glue";
  definition.slave_boundary_ids  = {1};
  definition.master_boundary_ids = {2};
  definition.type                = model::ContactPairDefinition::Type::tied;
  contact::MortarContactPair pair(model, definition);
  const double               eps = pair.penalty_stiffness(), area = 100.;

  VectorType u(model.partitioner), v(model.partitioner),
    mass(model.partitioner), f(model.partitioner);
  mass = 1.;
  mass.update_ghost_values();
  std::vector<model::RigidBody> bodies;

  // u(X) of every node: block nodes get @p block, plate nodes @p plate.
  const auto set_displacement =
    [&](const std::function<Tensor<1, 3>(const Point<3> &)> &block,
        const std::function<Tensor<1, 3>(const Point<3> &)> &plate) {
      fixtures::set_vertex_displacements(model,
                                         u,
                                         [&](const types::material_id id,
                                             const Point<3>          &X) {
                                           return id == 1 ? block(X) : plate(X);
                                         });
    };
  const auto evaluate = [&]() {
    const model::EvaluationPoint point{u, v, mass, bodies, 0.};
    model::ContributionResults   results;
    results.reset(2, 0);
    f = 0.;
    // As the explicit solver does before every step: the penalty of this
    // geometry (for the translation of case 2 the reference one, eps).
    pair.follow_geometry();
    pair.add_forces(point, f, results);
    double largest = 0.;
    for (unsigned int i = 0; i < f.locally_owned_size(); ++i)
      largest = std::max(largest, std::abs(f.local_element(i)));
    return std::make_pair(Utilities::MPI::max(largest, comm),
                          fixtures::largest_force_sum(f, comm));
  };

  // 1. A homogeneous deformation.
  Tensor<2, 3> E;
  E[0][0] = 0.01, E[0][1] = -0.02, E[0][2] = 0.03;
  E[1][0] = 0.015, E[1][1] = -0.01, E[1][2] = 0.005;
  E[2][0] = -0.025, E[2][1] = 0.02, E[2][2] = -0.03;
  const auto linear = [&](const Point<3> &X) { return Tensor<1, 3>(E * X); };
  set_displacement(linear, linear);
  const auto [largest_force, unused] = evaluate();
  (void)unused;
  const double       scale = eps * E.norm() * area;
  const unsigned int n_tied =
    Utilities::MPI::sum(pair.last_statistics().active_nodes, comm);
  if (root)
    out() << "1. homogeneous deformation: " << n_tied
          << " tied nodes, largest nodal force / (eps |E| A h) "
          << sci(largest_force / scale) << std::endl;
  check(n_tied == 36, "the block's bottom nodes are tied");
  check(largest_force < 1e-12 * scale, "patch test of the tying");

  // 2. A translation of the block.
  Tensor<1, 3> w;
  w[0] = 1e-4, w[1] = -2e-4, w[2] = 3e-4;
  set_displacement([&](const Point<3> &) { return w; },
                   [](const Point<3> &) { return Tensor<1, 3>(); });
  const auto [largest, balance] = evaluate();
  (void)largest;
  Tensor<1, 3> force;
  for (unsigned int d = 0; d < 3; ++d)
    force[d] = Utilities::MPI::sum(pair.last_statistics().force[d], comm);
  const double max_p =
    Utilities::MPI::max(pair.last_statistics().max_pressure, comm);
  const double min_p =
    Utilities::MPI::min(pair.last_statistics().min_pressure, comm);
  const Tensor<1, 3> expected = -eps * area * w;
  // The block's bottom has the normal -z: the "pressure" -t.n is -eps w_z.
  const double deviation =
    std::max({(force - expected).norm() / expected.norm(),
              std::abs(max_p / (-eps * w[2]) - 1.),
              std::abs(min_p / (-eps * w[2]) - 1.)});
  if (root)
    out() << "2. translation: force on the block " << force
          << " kN (-eps w A = " << expected << "), pressure " << min_p << " to "
          << max_p << " GPa, largest deviation " << sci(deviation)
          << "; sum of all nodal forces / |force| "
          << sci(balance / force.norm()) << std::endl;
  check(deviation < 1e-11, "uniform traction -eps w");
  check(balance < 1e-12 * force.norm(), "the forces balance");
  return 0;
}
