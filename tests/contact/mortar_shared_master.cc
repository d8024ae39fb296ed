// One master surface shared by two slave surfaces, in parallel (the case
// that broke 4C's redistribution, 4C-multiphysics/4C#158, and Tribol's
// pairing, llnl/smith#1201): the two rubber blocks of
// parameter_files/meshes/two_blocks_on_plate.msh on one steel plate, two
// Coulomb pairs (mu = 0.2) with the plate's top as master for both. On two
// ranks the plate's cells are split between the ranks (checked: each rank
// owns some), so each block's facets meet master facets of both ranks.
// The blocks are pressed into the plate by a penetration that grows along
// x and y (a tilt: the pressure is not uniform) and slid in opposite
// directions for three steps, with the motion prescribed (no dynamics).
// Printed per pair and step with 10 digits: the normal and tangential
// force, the force on the slave side, the largest pressure and
// penetration, the numbers of active and slipping nodes, the friction
// work. The 1- and 2-rank outputs are the same file (numdiff's relative
// tolerance 1e-8: the bound for 1 against 2 ranks); also checked:
// the forces on all nodes of the model sum to zero (1e-12 of the normal
// forces' sum).
#include <deal.II/base/mpi.h>
#include <deal.II/base/tensor.h>

#include <rubberdyn/contact/mortar_contact_pair.h>
#include <rubberdyn/model/force_contribution.h>
#include <rubberdyn/model/model.h>

#include <cmath>
#include <iomanip>
#include <memory>

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
  const bool         root    = Utilities::MPI::this_mpi_process(comm) == 0;
  const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);

  model::Model model(comm);
  io::read_gmsh_mesh(model.triangulation,
                     fixtures::mesh_directory() + "two_blocks_on_plate.msh",
                     "Mesh/Mesh file");
  model.parts.push_back(fixtures::rubber_part("block_a", 1));
  model.parts.push_back(fixtures::rubber_part("block_b", 2));
  model.parts.push_back(fixtures::steel_part("plate", 3));
  model.setup();

  unsigned int own_plate_cells = 0;
  for (const auto &cell : model.dof_handler.active_cell_iterators())
    if (cell->is_locally_owned() && cell->material_id() == 3)
      ++own_plate_cells;
  const bool split =
    Utilities::MPI::min(own_plate_cells, comm) > 0 || n_ranks == 1;
  if (root)
    out() << "plate cells on every rank: " << (split ? "yes" : "no")
          << std::endl;
  check(split, "the master surface is split between the ranks");

  std::vector<std::unique_ptr<contact::MortarContactPair>> pairs;
  for (const unsigned int slave : {1u, 2u})
    {
      model::ContactPairDefinition definition;
      definition.name                = slave == 1 ? "left" : "right";
      definition.slave_boundary_ids  = {types::boundary_id(slave)};
      definition.master_boundary_ids = {3};
      definition.type            = model::ContactPairDefinition::Type::coulomb;
      definition.static_friction = definition.dynamic_friction = 0.2;
      pairs.push_back(
        std::make_unique<contact::MortarContactPair>(model, definition));
    }

  VectorType u(model.partitioner), v(model.partitioner),
    mass(model.partitioner), f(model.partitioner);
  mass = 1.;
  mass.update_ghost_values();
  std::vector<model::RigidBody> bodies;
  if (root)
    out() << std::setprecision(10);
  for (unsigned int step = 0; step < 4; ++step)
    {
      // Block A slides along +x, block B along -x, 2e-3 mm per step; both
      // are pressed in by 1e-3 (1 + 0.02 x + 0.01 y) mm and turned a
      // little about z.
      const double slide = 2e-3 * step;
      fixtures::set_vertex_displacements(
        model,
        u,
        [&](const types::material_id id, const Point<3> &X) {
          if (id == 3)
            return Tensor<1, 3>();
          const double sign = id == 1 ? 1. : -1.;
          const double turn = 1e-4 * step;
          return Tensor<1, 3>({sign * slide - turn * (X[1] - 10.),
                               turn * (X[0] - 20.),
                               -1e-3 * (1. + 0.02 * X[0] + 0.01 * X[1])});
        });
      const model::EvaluationPoint point{u, v, mass, bodies, 1e-3 * step};
      model::ContributionResults   results;
      results.reset(3, 0);
      f                 = 0.;
      double normal_sum = 0.;
      for (const auto &pair : pairs)
        {
          pair->add_forces(point, f, results);
          const contact::ContactPairStatistics &s = pair->last_statistics();
          Tensor<1, 3>                          force;
          for (unsigned int d = 0; d < 3; ++d)
            force[d] = Utilities::MPI::sum(s.force[d], comm);
          const double normal = Utilities::MPI::sum(s.normal_force, comm);
          normal_sum += normal;
          const double tangential =
            Utilities::MPI::sum(s.tangential_force, comm);
          const double max_p = Utilities::MPI::max(s.max_pressure, comm);
          const double max_g = Utilities::MPI::max(s.max_penetration, comm);
          const unsigned int active = Utilities::MPI::sum(s.active_nodes, comm);
          const unsigned int slipping =
            Utilities::MPI::sum(s.slipping_nodes, comm);
          const double work = Utilities::MPI::sum(pair->friction_work(), comm);
          if (root)
            out() << "step " << step << " " << pair->name() << ": N " << normal
                  << " kN, T " << tangential << " kN, force " << force
                  << " kN, max pressure " << 1e3 * max_p
                  << " MPa, max penetration " << 1e3 * max_g << " um, "
                  << active << " active, " << slipping
                  << " slipping, friction work " << 1e6 * work << " uJ"
                  << std::endl;
          pair->accept_step();
        }
      check(fixtures::largest_force_sum(f, comm) < 1e-12 * normal_sum,
            "the forces sum to zero");
    }
  return 0;
}
