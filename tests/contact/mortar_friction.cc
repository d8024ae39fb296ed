// The mortar contact pair (contact::MortarContactPair) with Coulomb friction
// against closed forms, with the motion prescribed (no dynamics): the steel
// block of parameter_files/meshes/block_on_plate.msh (10 x 10 mm bottom,
// 5 x 5 faces) on the plate (4 x 4 faces: non-matching), the block moved
// as a rigid body into the plate by delta = 1e-3 mm and then along x by
// a given increment per step (add_forces() then accept_step() at steps of
// dt = 1e-3 ms). FS = 0.3, FD = 0.15, DC = 1 ms/mm.
//  1. Patch test: a uniform penetration transmits a uniform pressure on the
//     non-matching meshes: every active node's pressure is eps delta (eps
//     the pair's penalty per area), so max_pressure = min_pressure and the
//     normal force is eps delta A, A = 100 mm^2 (relative 1e-11: the
//     gaps are means of 49-point sums over each overlap, at ~1e-13).
//  2. Momentum: the forces on all nodes sum to zero (1e-12 of the normal
//     force), and the pair's force on the slave side is (-T, 0, N).
//  3. Stick: a first increment of 1e-5 mm gives the elastic traction eps
//     1e-5 < mu p at every node: T = eps 1e-5 A (relative 1e-8: the
//     increment is a difference of positions of 10 mm), no node slipping,
//     no friction work (below 1e-9 of mu N 1e-5).
//  4. Slip and the decay law: at 1e-3 mm per step (v = 1 mm/ms) every node
//     slips, T / N = FD + (FS - FD) exp(-DC v) = 0.205182; at 0.5e-3 mm
//     per step 0.240980 (relative 1e-12, from the second sliding step on,
//     the first carries the change of speed).
//  5. Dissipation: in steady slip a step dissipates mu(v) N v dt (the
//     spring's energy does not change): the friction work grows by that to
//     relative 1e-10.
//  6. The ParaView fields (add_surface_fields()): at every slave node the
//     pressure eps delta, the gap -delta and the distance slipped, the sum
//     of the slipping steps' increments (6 of 1e-3 mm and 6 of 0.5e-3 mm:
//     9e-3 mm), relative 1e-10; zero at every other node.
// Run on 1 and 2 ranks (the columns' values summed over the ranks).
#include <deal.II/base/geometry_info.h>
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

namespace
{
  /** The pair's columns summed (or extremised) over the ranks. */
  struct Totals
  {
    Tensor<1, 3> force;
    double       normal, tangential, max_p, min_p, friction_work, force_sum;
    unsigned int active, slipping;
  };

  Totals
  totals(const contact::MortarContactPair &pair,
         const VectorType                 &f,
         const MPI_Comm                    comm)
  {
    const contact::ContactPairStatistics &s = pair.last_statistics();
    Totals                                t;
    for (unsigned int d = 0; d < 3; ++d)
      t.force[d] = Utilities::MPI::sum(s.force[d], comm);
    t.normal        = Utilities::MPI::sum(s.normal_force, comm);
    t.tangential    = Utilities::MPI::sum(s.tangential_force, comm);
    t.max_p         = Utilities::MPI::max(s.max_pressure, comm);
    t.min_p         = Utilities::MPI::min(s.min_pressure, comm);
    t.friction_work = Utilities::MPI::sum(pair.friction_work(), comm);
    t.active        = Utilities::MPI::sum(s.active_nodes, comm);
    t.slipping      = Utilities::MPI::sum(s.slipping_nodes, comm);
    t.force_sum     = fixtures::largest_force_sum(f, comm);
    return t;
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                   comm = MPI_COMM_WORLD;
  const bool root = Utilities::MPI::this_mpi_process(comm) == 0;

  model::Model model(comm);
  fixtures::make_block_on_plate(model, fixtures::steel_part("block", 1));

  model::ContactPairDefinition definition;
  definition.name                = "sliding";
  definition.slave_boundary_ids  = {1};
  definition.master_boundary_ids = {2};
  definition.type                = model::ContactPairDefinition::Type::coulomb;
  definition.static_friction     = 0.3;
  definition.dynamic_friction    = 0.15;
  definition.decay               = 1.;
  contact::MortarContactPair pair(model, definition);
  const double               eps = pair.penalty_stiffness();

  VectorType u(model.partitioner), v(model.partitioner),
    mass(model.partitioner), f(model.partitioner);
  mass = 1.;
  mass.update_ghost_values();
  const double delta = 1e-3, dt = 1e-3, area = 100.;
  // The block moved as a rigid body: along x, and into the plate.
  const auto move_block = [&](const double shift) {
    fixtures::set_vertex_displacements(
      model,
      u,
      [&](const types::material_id id, const Point<3> &) {
        return id == 1 ? Tensor<1, 3>({shift, 0., -delta}) : Tensor<1, 3>();
      });
  };
  std::vector<model::RigidBody> bodies;
  double                        time  = 0.;
  double                        shift = 0.;
  const auto                    step  = [&](const double increment) {
    shift += increment;
    move_block(shift);
    const model::EvaluationPoint point{u, v, mass, bodies, time};
    model::ContributionResults   results;
    results.reset(2, 0);
    f = 0.;
    pair.add_forces(point, f, results);
    const Totals t = totals(pair, f, comm);
    pair.accept_step();
    time += dt;
    return t;
  };

  // 1., 2. Pressed, at rest.
  Totals       t = step(0.);
  const double p = eps * delta, N = p * area;
  const double patch = std::max({std::abs(t.normal / N - 1.),
                                 std::abs(t.max_p / p - 1.),
                                 std::abs(t.min_p / p - 1.),
                                 std::abs(t.force[2] / N - 1.)});
  if (root)
    out() << "1. pressed: " << t.active << " active nodes, pressure " << t.min_p
          << " to " << t.max_p << " GPa (eps delta = " << p
          << "), normal force " << t.normal << " kN, largest deviation "
          << sci(patch) << "; sum of nodal forces " << sci(t.force_sum) << " kN"
          << std::endl;
  check(patch < 1e-11, "patch test: uniform pressure eps delta");
  check(t.force_sum < 1e-12 * N, "momentum: the forces sum to zero");

  // 3. Stick.
  t                  = step(1e-5);
  const double stick = std::abs(t.tangential / (eps * 1e-5 * area) - 1.);
  if (root)
    out() << "3. stick: T = " << t.tangential << " kN (eps 1e-5 A, "
          << sci(stick) << "), " << t.slipping
          << " slipping nodes, friction work below 1e-9 mu N 1e-5: "
          << (std::abs(t.friction_work) < 1e-9 * 0.3 * N * 1e-5) << std::endl;
  check(stick < 1e-8 && t.slipping == 0 &&
          std::abs(t.friction_work) < 1e-9 * 0.3 * N * 1e-5,
        "stick: the elastic traction");
  check(std::abs(t.force[0] + t.tangential) < 1e-12 * N,
        "stick: the force opposes the motion");

  // 4., 5. Slip at v = 1 and 0.5 mm/ms.
  for (const double speed : {1., 0.5})
    {
      const double mu          = 0.15 + 0.15 * std::exp(-speed);
      double       worst_ratio = 0., worst_work = 0.;
      unsigned int fewest_slipping = t.active;
      t                            = step(speed * dt); // the change of speed
      for (unsigned int s = 0; s < 5; ++s)
        {
          const double work_before = t.friction_work;
          t                        = step(speed * dt);
          worst_ratio =
            std::max(worst_ratio, std::abs(t.tangential / t.normal / mu - 1.));
          worst_ratio =
            std::max(worst_ratio, std::abs(-t.force[0] / t.force[2] / mu - 1.));
          worst_work      = std::max(worst_work,
                                std::abs((t.friction_work - work_before) /
                                           (mu * N * speed * dt) -
                                         1.));
          fewest_slipping = std::min(fewest_slipping, t.slipping);
        }
      if (root)
        out() << "4. v = " << speed << " mm/ms: mu(v) = " << mu
              << ", T / N = " << t.tangential / t.normal
              << " (largest deviation " << sci(worst_ratio) << "), "
              << fewest_slipping << " of " << t.active
              << " nodes slipping; 5. work per step / (mu N v dt) - 1: "
              << sci(worst_work) << std::endl;
      check(worst_ratio < 1e-12 && fewest_slipping == t.active,
            "slip follows the decay law");
      check(worst_work < 1e-10, "dissipation mu N v dt");
    }

  // 6. The ParaView fields.
  {
    VectorType fields(model.partitioner);
    pair.add_surface_fields(fields);
    fields.update_ghost_values();
    const double expected[3] = {p, -delta, 6e-3 + 6 * 0.5e-3};
    double       worst       = 0.;
    unsigned int n_slave     = 0;
    for (const auto &cell : model.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int vertex : GeometryInfo<3>::vertex_indices())
          {
            const bool on_slave = cell->material_id() == 1 &&
                                  std::abs(cell->vertex(vertex)[2] - 2.) < 1e-9;
            for (unsigned int d = 0; d < 3; ++d)
              {
                const double value = fields(cell->vertex_dof_index(vertex, d));
                worst              = std::max(worst,
                                 on_slave ? std::abs(value / expected[d] - 1.) :
                                                         std::abs(value));
              }
            n_slave += on_slave;
          }
    worst = Utilities::MPI::max(worst, comm);
    if (root)
      out() << "6. fields at the slave nodes: pressure, gap, slip within "
            << sci(worst) << " of " << p << " GPa, " << -delta << " mm, "
            << expected[2] << " mm; zero elsewhere" << std::endl;
    check(Utilities::MPI::sum(n_slave, comm) > 0 && worst < 1e-10,
          "the ParaView fields");
  }
  return 0;
}
