// The mortar contact pair's tangent (contact::MortarContactPair::
// add_tangents(), for the quasi-static solver) against central finite
// differences of its forces (add_forces()): the block of
// parameter_files/meshes/block_on_plate.msh (5 x 5 faces) pressed into the
// plate (4 x 4 faces: non-matching), shifted so that it overhangs the
// plate's edge (partly covered slave facets: the clipping's derivative),
// tilted, and with every vertex displaced by a smooth pseudo-random field
// of 2e-3 mm (warped, non-parallel facets: the derivatives of D, M, the
// nodal normal and the covered area all count). For a direction w (the
// same kind of field, on both bodies) the tangent's K w must equal
// -(f(u + h w) - f(u - h w)) / 2h over all dofs to 1e-6 relative
// (h = 1e-6 mm: truncation ~(h / 1e-2 mm)^2 = 1e-8, round-off ~1e-12;
// leaving out the derivative of any of D, M or the normal gives errors
// of 1e-3 to 1). Cases:
//  1. frictionless;
//  2. frictionless, two-pass (the plate's facets as slaves too);
//  3. Coulomb, sticking: accepted at u (slid there from the reference
//     place, every traction on the cone), evaluated after a motion back by
//     1e-4 mm in 1 ms (the elastic trial traction turns inside the cone);
//  4. Coulomb, slipping with the decay law (FS = 0.3, FD = 0.15, DC =
//     1 ms/mm): the same, 2e-3 mm on in 1e-3 ms (mu depends on the slip
//     rate);
//  5. tied (Tie tolerance 0.01 mm at the block's initial contact).
// The tangent must also be non-trivial (|K w| > 0) and its blocks must
// stay within the couplings of add_couplings() (after update_couplings(),
// as the solver calls them). Run on 1 and 2 ranks. And:
//  6. the couplings announced are only the live ones: none while the
//     block is 0.05 mm above the plate; pressed in, the closed nodes'
//     patches, with a new couplings_version().
#include <deal.II/base/mpi.h>

#include <rubberdyn/contact/mortar_contact_pair.h>
#include <rubberdyn/model/model.h>

#include "../model/model_fixtures.h"
#include "../tests.h"
#include "mortar_probe.h"

using namespace dealii;
using namespace rubberdyn;
using mortar_probe::wobble;
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
  // The block (material 1): over the plate's edge at x = 20 (block x from
  // 11 to 21), tilted about y, into the plate by 5e-3 to 1.5e-2 mm, warped.
  const auto place = [&](VectorType  &vector,
                         const double shift,
                         const double depth,
                         const double warp) {
    fixtures::set_vertex_displacements(
      model,
      vector,
      [&](const types::material_id id, const Point<3> &X) {
        Tensor<1, 3> d = warp * wobble(X, id == 1 ? 0. : 1.);
        if (id == 1)
          {
            d[0] += 6. + shift;
            d[2] += -depth - 1e-3 * (X[0] - 5.);
          }
        return d;
      });
  };
  fixtures::set_vertex_displacements(model,
                                     w,
                                     [&](const types::material_id id,
                                         const Point<3>          &X) {
                                       return wobble(X, id == 1 ? 2. : 3.);
                                     });
  // Compare K w with the central difference at u (at time t); the pair
  // has been evaluated (and its state accepted) as the case needs.
  const auto compare = [&](const std::string          &name,
                           contact::MortarContactPair &pair,
                           const double                time) {
    const mortar_probe::TangentComparison c =
      probe.compare_tangent(pair, u, w, time);
    const unsigned int active =
      Utilities::MPI::sum(pair.last_statistics().active_nodes, comm);
    if (root)
      out() << name << ": " << active << " active slave nodes, K w equals "
            << "the central difference to below 1e-6: "
            << (c.error < 1e-6 ? "yes" : "no") << "; blocks within the "
            << "announced couplings: " << (c.within_couplings ? "yes" : "no")
            << std::endl;
    check(c.norm > 0., name + ": a non-trivial tangent");
    check(c.error < 1e-6,
          name + ": K w against the central difference (error " +
            testing::sci(c.error) + ")");
    check(c.within_couplings, name + ": blocks within add_couplings()");
  };

  model::ContactPairDefinition definition;
  definition.name                = "pair";
  definition.slave_boundary_ids  = {1};
  definition.master_boundary_ids = {2};

  // 1., 2. Frictionless, one pass and two.
  for (const bool two_pass : {false, true})
    {
      definition.two_pass = two_pass;
      contact::MortarContactPair pair(model, definition);
      place(u, 0., 1e-2, 2e-3);
      compare(two_pass ? "2. frictionless, two-pass" : "1. frictionless",
              pair,
              0.);
    }
  definition.two_pass = false;

  // 6. Only live couplings are announced (update_couplings(), before
  // every assembly of the quasi-static solver): the block 0.05 mm above
  // the plate announces none, pressed in it announces the patches of its
  // closed nodes, and couplings_version() changes (the solver's cue to
  // build a new pattern). Before 2026-12-05 every slave node's patch was
  // announced, open or not.
  {
    contact::MortarContactPair pair(model, definition);
    VectorType                 rest(model.partitioner), unit(model.partitioner);
    unit = 1.;
    unit.update_ghost_values();
    const std::vector<model::RigidBody> no_bodies;
    // Evaluated at u (as the solver's residual), then the couplings there:
    // the number of dofs over all announced blocks, and whether
    // update_couplings() changed the version.
    const auto couplings_at = [&](const double depth) {
      place(u, 0., depth, 2e-3);
      probe.forces(pair, u, 0.);
      const unsigned int before = pair.couplings_version();
      pair.update_couplings({u, rest, unit, no_bodies, 0.});
      types::global_dof_index n = 0;
      pair.add_couplings([&](const std::vector<types::global_dof_index> &dofs) {
        n += dofs.size();
      });
      return std::make_pair(Utilities::MPI::sum(n, comm),
                            pair.couplings_version() != before);
    };
    const auto open   = couplings_at(-5e-2);
    const auto closed = couplings_at(1e-2);
    if (root)
      out() << "6. couplings: " << open.first
            << " dofs in blocks while open, version changed: "
            << (open.second ? "yes" : "no") << "; pressed in: "
            << (closed.first > 0 ? "blocks announced" : "none")
            << ", version changed: " << (closed.second ? "yes" : "no")
            << std::endl;
    check(open.first == 0 && !open.second, "6. no couplings while open");
    check(closed.first > 0 && closed.second,
          "6. the closed nodes' couplings, a new version");
  }

  // 3., 4. Coulomb: accepted at u, then moved along x.
  definition.type             = model::ContactPairDefinition::Type::coulomb;
  definition.static_friction  = 0.3;
  definition.dynamic_friction = 0.15;
  definition.decay            = 1.;
  for (const double motion : {-1e-4, 2e-3})
    {
      contact::MortarContactPair pair(model, definition);
      place(u, 0., 1e-2, 2e-3);
      probe.forces(pair, u, 0.);
      pair.accept_step();
      // (Slowly back, quickly on: the decay law barely shrinks the cone
      // for the first.)
      const double time = motion < 0. ? 1. : 1e-3;
      place(u, motion, 1e-2, 2e-3);
      probe.forces(pair, u, time);
      const unsigned int slipping =
        Utilities::MPI::sum(pair.last_statistics().slipping_nodes, comm);
      const unsigned int active =
        Utilities::MPI::sum(pair.last_statistics().active_nodes, comm);
      if (motion < 0.)
        check(slipping == 0, "3. every node sticks");
      else
        check(slipping == active, "4. every node slips");
      compare(motion < 0. ? "3. Coulomb, sticking" :
                            "4. Coulomb, slipping, decay law",
              pair,
              time);
    }

  // 5. Tied: the block tied where it stands on the plate, then moved.
  {
    definition.type          = model::ContactPairDefinition::Type::tied;
    definition.tie_tolerance = 1e-2;
    contact::MortarContactPair pair(model, definition);
    fixtures::set_vertex_displacements(model,
                                       u,
                                       [&](const types::material_id id,
                                           const Point<3>          &X) {
                                         return 2e-3 *
                                                wobble(X, id == 1 ? 0. : 1.);
                                       });
    compare("5. tied", pair, 0.);
  }
  return 0;
}
