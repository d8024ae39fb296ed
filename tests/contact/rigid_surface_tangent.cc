// The quasi-static tangent of rigid-surface contact
// (contact::RigidSurfaceContact::add_tangents()) is the exact derivative of
// its forces (add_forces(), from the accepted friction state), checked
// against central differences of those forces (step 1e-6 mm) node by node,
// on the bottom nodes of a 2 x 2 x 1 block of unit cubes pressed into:
//  - a plane, frictionless; a tilted plane with Coulomb friction (mu =
//    0.3), once with every node sticking and once with sticking and
//    slipping nodes;
//  - a rigid pin (cylinder, solid outside) and a rigid tube (solid inside),
//    frictionless and with friction (the curvature terms: the normal turns
//    with the node, and so does the old tangential force);
//  - a plane carried by a rotated and displaced body, with friction.
// Each case: the contact is evaluated at a displacement u0 and accepted
// (the tangential forces and reference points of a converged step), then
// the tangent at u1 = u0 + a tangential slide + a perturbation is compared
// with the differences, relative to the largest entry: bound 1e-6
// (central differences of smooth functions at h = 1e-6: error ~ h^2, and
// round-off ~ 1e-16 |f| / h ~ 1e-10 relative). Each node's force depends
// on its own position only, which is checked too (no entry outside the
// node's 3 x 3 block). A case meant to have stick and slip nodes must have
// both (|f_t| < mu f_n, and |f_t| = mu f_n to 1e-12).
// And the closed gap is active: the block resting on a plane at g = 0 with
// no load gets, at every bottom node, the normal stiffness and the
// sticking stiffness k (1 - n n), i.e. k 1 with k = s K A^2 / V shared
// over the face's four nodes: s K / 4 at a corner, s K / 2 at an edge
// midpoint, s K at the centre (s the penalty scale, K the bulk modulus,
// unit faces and cells).
#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>

#include <rubberdyn/base/partitioner.h>
#include <rubberdyn/contact/rigid_surface_contact.h>
#include <rubberdyn/model/rigid_body.h>

#include "../tests.h"

#include <cmath>
#include <map>

using namespace dealii;
using namespace rubberdyn;
using testing::check;
using testing::out;
using testing::sci;

namespace
{
  constexpr double penalty_scale = 0.5, bulk_modulus = 2.;

  struct Block
  {
    parallel::distributed::Triangulation<3> tria;
    FESystem<3>                             fe;
    DoFHandler<3>                           dof_handler;
    std::shared_ptr<const Utilities::MPI::Partitioner> partitioner;

    explicit Block(const MPI_Comm comm)
      : tria(comm)
      , fe(FE_Q<3>(1), 3)
    {
      // colorize: boundary id 4 is z = 0.
      GridGenerator::subdivided_hyper_rectangle(
        tria, {2, 2, 1}, Point<3>(0., 0., 0.), Point<3>(2., 2., 1.), true);
      for (const auto &cell : tria.active_cell_iterators())
        cell->set_material_id(0);
      dof_handler.reinit(tria);
      dof_handler.distribute_dofs(fe);
      partitioner = ghosted_partitioner(dof_handler);
    }
  };

  /** A deterministic pseudo-random number in [-1, 1]. */
  double
  wiggle(const unsigned int i, const unsigned int salt)
  {
    return std::sin(12.9898 * i + 78.233 * salt + 0.5) * 0.9 +
           0.1 * std::cos(4.1 * i * salt);
  }

  struct Case
  {
    std::string                  name;
    contact::RigidSurface        surface;
    contact::SurfacePose         pose;
    /** Displacement of the bottom nodes at u0 (plus a small wiggle). */
    Tensor<1, 3>                 u0;
    /** The slide from u0 to u1 (plus another wiggle of this size). */
    Tensor<1, 3>                 slide;
    double                       wiggle_1 = 0.01;
    /**
     * An accepted state before u0, at u0 - pre_slide: then u0's accepted
     * tangential forces are not zero.
     */
    Tensor<1, 3>                 pre_slide = Tensor<1, 3>({-0.005, 0.004, 0.});
    bool                         want_stick = false, want_slip = false;
  };

  void
  run(const Block &block, const Case &c)
  {
    const auto &partitioner = block.partitioner;
    contact::RigidSurfaceContact contact;
    contact.initialize(block.dof_handler,
                       partitioner,
                       {4},
                       {bulk_modulus},
                       penalty_scale,
                       {c.surface});
    const std::vector<contact::SurfacePose> pose = {c.pose};
    const unsigned int n_owned = partitioner->locally_owned_size();
    VectorType u_pre(partitioner), u0(partitioner), u1(partitioner),
      f(partitioner);
    // Every dof: the bottom nodes' offset where the block is (the
    // others do not touch), plus wiggles.
    for (unsigned int i = 0; i < n_owned; ++i)
      {
        const unsigned int d = i % 3; // (FE_Q^3 numbers x, y, z per node)
        u0.local_element(i)  = c.u0[d] + 0.02 * wiggle(i, 1);
        u_pre.local_element(i) = u0.local_element(i) - c.pre_slide[d];
        u1.local_element(i) =
          u0.local_element(i) + c.slide[d] + c.wiggle_1 * wiggle(i, 2);
      }
    contact::ContactResult result;
    contact.add_forces(u_pre, pose, f, result);
    contact.accept();
    contact.add_forces(u0, pose, f, result);
    contact.accept();

    // The tangent at u1, node block by node block.
    std::map<unsigned int, Tensor<2, 3>> blocks;
    std::map<unsigned int, std::array<unsigned int, 3>> dofs_of_node;
    contact.add_tangents(u1, pose, [&](const unsigned int (&dofs)[3],
                                       const unsigned int,
                                       const Tensor<2, 3> &K) {
      blocks[dofs[0]] += K;
      dofs_of_node[dofs[0]] = {dofs[0], dofs[1], dofs[2]};
    });

    // Forces at u1 (for stick and slip), then central differences.
    f = 0.;
    contact.add_forces(u1, pose, f, result);
    const VectorType f1 = f;
    double     largest = 0., error = 0., outside = 0.;
    unsigned int n_stick = 0, n_slip = 0;
    const double h = 1e-6;
    for (const auto &[first, dofs] : dofs_of_node)
      {
        const Tensor<2, 3> &K = blocks[first];
        for (unsigned int j = 0; j < 3; ++j)
          {
            VectorType up(u1), down(u1), f_up(partitioner),
              f_down(partitioner);
            up.local_element(dofs[j]) += h;
            down.local_element(dofs[j]) -= h;
            contact.add_forces(up, pose, f_up, result);
            contact.add_forces(down, pose, f_down, result);
            for (unsigned int i = 0; i < n_owned; ++i)
              {
                // The resisting force is minus the contact force.
                const double difference =
                  -(f_up.local_element(i) - f_down.local_element(i)) /
                  (2. * h);
                const auto row = std::find(dofs.begin(), dofs.end(), i);
                if (row == dofs.end())
                  outside = std::max(outside, std::abs(difference));
                else
                  {
                    const double entry = K[row - dofs.begin()][j];
                    largest = std::max(largest, std::abs(entry));
                    error   = std::max(error, std::abs(entry - difference));
                  }
              }
          }
        // Stick or slip: in the surface's frame, from the force.
        if (c.surface.friction_coefficient > 0.)
          {
            Tensor<1, 3> force;
            for (unsigned int d = 0; d < 3; ++d)
              force[d] = f1.local_element(dofs[d]);
            if (c.pose.rotated)
              force = transpose(c.pose.rotation) * force;
            // The normal: the direction of the normal force, from a
            // frictionless evaluation would need the geometry; for the
            // plane cases it is the surface's.
            if (c.surface.shape == contact::RigidSurface::Shape::plane)
              {
                const double normal = force * c.surface.normal;
                const double tangential =
                  (force - normal * c.surface.normal).norm();
                if (normal > 0.)
                  {
                    if (tangential <
                        c.surface.friction_coefficient * normal *
                          (1. - 1e-12))
                      ++n_stick;
                    else
                      ++n_slip;
                  }
              }
          }
      }
    // Nodes whose tangent is zero-free (active): every one counted.
    const double relative = error / largest;
    out() << c.name << ": " << dofs_of_node.size()
          << " active nodes, tangent vs differences " << sci(relative)
          << ", outside the node blocks " << sci(outside / largest);
    if (c.surface.friction_coefficient > 0. &&
        c.surface.shape == contact::RigidSurface::Shape::plane)
      out() << ", " << n_stick << " sticking, " << n_slip << " slipping";
    out() << std::endl;
    check(!dofs_of_node.empty(), c.name + ": some nodes in contact");
    check(relative < 1e-6, c.name + ": tangent matches the differences");
    check(outside == 0., c.name + ": forces are nodal");
    if (c.want_stick)
      check(n_stick > 0, c.name + ": some nodes stick");
    if (c.want_slip)
      check(n_slip > 0, c.name + ": some nodes slip");
    if (c.want_stick && !c.want_slip)
      check(n_slip == 0, c.name + ": no node slips");
  }



  // The closed gap: the block on the plane z = 0, no load, mu = 0.3.
  void
  closed_gap(const Block &block)
  {
    contact::RigidSurface floor;
    floor.normal               = Tensor<1, 3>({0., 0., 1.});
    floor.friction_coefficient = 0.3;
    contact::RigidSurfaceContact contact;
    contact.initialize(block.dof_handler,
                       block.partitioner,
                       {4},
                       {bulk_modulus},
                       penalty_scale,
                       {floor});
    VectorType                         u(block.partitioner), f(block.partitioner);
    const std::vector<contact::SurfacePose> pose(1);
    contact::ContactResult             result;
    contact.add_forces(u, pose, f, result);
    contact.accept();
    std::map<double, unsigned int> nodes_of_stiffness;
    double                         deviation = 0.;
    contact.add_tangents(u, pose, [&](const unsigned int (&)[3],
                                      const unsigned int,
                                      const Tensor<2, 3> &K) {
      const double k = K[0][0];
      ++nodes_of_stiffness[k];
      Tensor<2, 3> expected;
      for (unsigned int d = 0; d < 3; ++d)
        expected[d][d] = k;
      deviation = std::max(deviation, (K - expected).norm() / k);
    });
    out() << "closed gap, no load: " << f.l2_norm() << " kN of force;";
    for (const auto &[k, n] : nodes_of_stiffness)
      out() << " " << n << " nodes with k 1, k = " << k << " kN/mm;";
    out() << " largest deviation from k 1 " << sci(deviation) << std::endl;
    const double sK = penalty_scale * bulk_modulus;
    check(f.l2_norm() == 0., "closed gap: no force");
    check(nodes_of_stiffness.size() == 3 &&
            nodes_of_stiffness[sK / 4.] == 4 &&
            nodes_of_stiffness[sK / 2.] == 4 && nodes_of_stiffness[sK] == 1,
          "closed gap: 4 corners s K / 4, 4 edges s K / 2, 1 centre s K");
    check(deviation < 1e-15, "closed gap: the block is k 1");
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const Block block(MPI_COMM_WORLD);

  std::vector<Case> cases;
  {
    Case c;
    c.name           = "plane, frictionless";
    c.surface.point  = Point<3>(0., 0., 0.05);
    c.surface.normal = Tensor<1, 3>({0., 0., 1.});
    c.slide          = Tensor<1, 3>({0.02, -0.01, -0.01});
    cases.push_back(c);
  }
  {
    // A plane tilted by about 0.1 rad about y and x.
    Case c;
    c.name                         = "tilted plane, mu 0.3, sticking";
    Tensor<1, 3> n({0.1, -0.05, 1.});
    c.surface.normal               = n / n.norm();
    c.surface.point                = Point<3>(1., 1., 0.1);
    c.surface.friction_coefficient = 0.3;
    // A tiny slide: the tangential springs stay inside the cone.
    c.slide                        = Tensor<1, 3>({1e-4, 0., -0.02});
    c.wiggle_1                     = 1e-4;
    c.pre_slide                    = Tensor<1, 3>();
    c.want_stick                   = true;
    cases.push_back(c);
    c.name  = "tilted plane, mu 0.3, sticking and slipping";
    c.wiggle_1  = 0.01;
    c.pre_slide = Tensor<1, 3>({-0.005, 0.004, 0.});
    c.u0    = Tensor<1, 3>({0., 0., -0.02});
    c.slide = Tensor<1, 3>({0.006, 0.003, 0.});
    c.want_slip = true;
    cases.push_back(c);
  }
  for (const double mu : {0., 0.3})
    {
      Case c;
      c.name = std::string("pin (cylinder, solid outside), mu ") +
               (mu > 0. ? "0.3" : "0");
      c.surface.shape  = contact::RigidSurface::Shape::cylinder_solid_outside;
      c.surface.point  = Point<3>(0.7, 0., -2.95);
      c.surface.normal = Tensor<1, 3>({0., 1., 0.});
      c.surface.radius = 3.;
      c.surface.friction_coefficient = mu;
      c.slide = Tensor<1, 3>({0.01, 0.005, -0.02});
      cases.push_back(c);
      c.name = std::string("tube (cylinder, solid inside), mu ") +
               (mu > 0. ? "0.3" : "0");
      c.surface.shape = contact::RigidSurface::Shape::cylinder_solid_inside;
      c.surface.point = Point<3>(1.2, 0., 3.1);
      c.surface.radius = 3.05;
      cases.push_back(c);
    }
  {
    // The tilted plane on a body turned by 0.3 rad about a skew axis and
    // displaced: the force is turned back, the tangent R J R^T.
    Case c;
    c.name = "plane on a rotated body, mu 0.3";
    Tensor<1, 3> n({0.1, -0.05, 1.});
    c.surface.normal               = n / n.norm();
    c.surface.friction_coefficient = 0.3;
    c.pose.rotated                 = true;
    c.pose.rotation = model::rotation_of_vector(Tensor<1, 3>({0.2, -0.1, 0.2}));
    c.pose.centre   = Point<3>(1., 1., -1.);
    c.pose.displacement = Tensor<1, 3>({0.01, 0.02, 0.});
    // The surface's point, in its frame, where the turned plane cuts the
    // block's bottom near its centre.
    c.surface.point = c.pose.centre + transpose(c.pose.rotation) *
                                        (Point<3>(1., 1., 0.05) -
                                         c.pose.centre - c.pose.displacement);
    c.slide = Tensor<1, 3>({0.006, 0.003, 0.});
    cases.push_back(c);
  }
  for (const Case &c : cases)
    run(block, c);
  closed_gap(block);
  return 0;
}
