// The weight with which a mortar segment enters its nodes' sums
// (contact::mortar_segment_weight(): 1 up to half the capture margin, 0
// from the margin on, a C1 cubic between) and the forces of that weight
// (MortarContactPair::Implementation::weight_forces()), which make the
// pair's forces the gradient of its springs' energy while a segment fades.
//
// The block of parameter_files/meshes/block_on_plate.msh (its 2 mm bottom
// facets the slaves), moved by (0.6, 0.7) mm so that no facet edge lies
// on one of the plate's (5 mm facets), over the plate, whose top is
// folded down beyond x = 10 with slope 1.5 (the plate's vertices there
// lowered by 1.5 (x - 10)): the slave facets over the fold see it 1.2 to
// 6.9 mm below them while those over the flat part press into it. The
// capture margin is half the facets' mean diagonal, 2.242 mm, so the
// slave facets from x = 11.6 to 13.6 (mean gap 3.9 - d at a depth d) fade
// in as the block sinks from d = 1.658 to 2.779 mm, beside the pressed
// facets from x = 9.6 to 11.6 of the same nodes (x = 11.6).
//
//  1. Conservation: the block is pushed straight down (along the slave
//     facets' normal: the overlaps, D, M and the normals stay as they
//     are, so the weight is all that changes the mortar integrals), from
//     d = 1 to 2.5 mm in 3000 equal steps, frictionless, and the pair's
//     work audit (trapezoidal work of its forces plus its springs' energy,
//     MortarContactPair::energy_error()) must stay below 1e-5 of the
//     springs' final energy. Without the weight's forces it reaches 7.4
//     times that energy (6.7e3 J of 913 J: the nodes' springs gain energy
//     as the far segments fade in, without work); with a hard cut at the
//     margin (before 2026-12-04) the energy jumped where a segment's mean
//     gap crossed the margin.
//  2. The tangent (add_tangents()) at d = 2 mm (mean gap 1.9 mm, inside
//     the blend) against central differences of the forces, as in
//     mortar_tangent.cc: to 1e-6 relative (1.35 without the weight's
//     forces in the tangent).
// Run on 1 and 2 ranks.
#include <deal.II/base/mpi.h>

#include <rubberdyn/contact/mortar_contact_pair.h>
#include <rubberdyn/model/model.h>

#include <algorithm>
#include <cmath>

#include "../model/model_fixtures.h"
#include "../tests.h"
#include "mortar_probe.h"

using namespace dealii;
using namespace rubberdyn;
using testing::check;
using testing::out;



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                   comm = MPI_COMM_WORLD;
  const bool root = Utilities::MPI::this_mpi_process(comm) == 0;

  model::Model model(comm);
  fixtures::make_block_on_plate(model, fixtures::steel_part("block", 1));

  VectorType          u(model.partitioner), w(model.partitioner);
  mortar_probe::Probe probe(model);
  // The block (material 1) moved off the plate's grid lines (no edges on
  // edges) and sunk by d along -z; the plate folded down beyond x = 10.
  const double slope = 1.5;
  const auto   place = [&](const double d) {
    const auto displacement = [&](const types::material_id id,
                                  const Point<3>          &X) {
      if (id == 1)
        return Tensor<1, 3>({0.6, 0.7, -d});
      return Tensor<1, 3>({0., 0., X[0] > 10. ? -slope * (X[0] - 10.) : 0.});
    };
    fixtures::set_vertex_displacements(model, u, displacement);
  };

  model::ContactPairDefinition definition;
  definition.name                = "pair";
  definition.slave_boundary_ids  = {1};
  definition.master_boundary_ids = {2};

  // 1. The work audit along the straight push.
  {
    contact::MortarContactPair pair(model, definition);
    const unsigned int         n_steps = 3000;
    const double               start = 1., end = 2.5;
    const double               largest_error =
      probe
        .walk(pair,
              u,
              n_steps,
              [&](const unsigned int step) {
                place(start + (end - start) * step / n_steps);
              })
        .largest_error;
    const double energy = Utilities::MPI::sum(pair.contact_energy(), comm);
    const unsigned int active =
      Utilities::MPI::sum(pair.last_statistics().active_nodes, comm);
    if (root)
      out() << "1. pushed from 1 to 2.5 mm: " << active
            << " active slave nodes, springs' energy " << testing::sci(energy)
            << " J, largest work audit error below 1e-5 of it: "
            << (largest_error < 1e-5 * energy ? "yes" : "no") << std::endl;
    check(active > 0 && energy > 0., "1. the block presses on the plate");
    check(largest_error < 1e-5 * energy,
          "1. work audit error " + testing::sci(largest_error) + " J of " +
            testing::sci(energy) + " J");
  }

  // 2. The tangent within the blend (w: a smooth field on both bodies).
  {
    contact::MortarContactPair pair(model, definition);
    place(2.);
    fixtures::set_vertex_displacements(
      model,
      w,
      [](const types::material_id id, const Point<3> &X) {
        return mortar_probe::wobble(X, id == 1 ? 2. : 3.);
      });
    const mortar_probe::TangentComparison c =
      probe.compare_tangent(pair, u, w, 0.);
    if (root)
      out() << "2. at 2 mm: K w equals the central difference to below "
            << "1e-6: " << (c.error < 1e-6 ? "yes" : "no") << std::endl;
    check(c.norm > 0., "2. a non-trivial tangent");
    check(c.error < 1e-6,
          "2. K w against the central difference (error " +
            testing::sci(c.error) + ")");
  }
  return 0;
}
