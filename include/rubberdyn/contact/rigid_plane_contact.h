#ifndef rubberdyn_contact_rigid_plane_contact_h
#define rubberdyn_contact_rigid_plane_contact_h

#include <deal.II/base/partitioner.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>
#include <rubberdyn/base/vector.h>

#include <memory>
#include <set>
#include <vector>

namespace dealii
{
  template <int dim, int spacedim>
  class DoFHandler;
}

namespace rubberdyn
{
  /**
   * Contact between deformable surfaces and rigid or deformable partners.
   */
  namespace contact
  {
    using namespace dealii;

    /**
     * A rigid plane: the points x with n . (x - p) >= 0 are outside it.
     */
    struct RigidPlane
    {
      /** A point of the plane in the reference configuration (mm). */
      Point<3> point;
      /** Unit normal pointing away from the rigid body, into the solid. */
      Tensor<1, 3> normal;
    };

    /** What contact did in one evaluation. */
    struct ContactResult
    {
      /**
       * Force of the solid on each plane (kN), i.e. minus the sum of the
       * contact forces applied to the solid's nodes.
       */
      std::vector<Tensor<1, 3>> force_on_plane;
      /** Energy stored in the penalty springs (J = kN mm). */
      double penalty_energy = 0.;
    };

    /**
     * Frictionless node-to-plane penalty contact of the boundary nodes of a
     * solid with rigid planes (the plates of the drop test).
     *
     * A boundary node that has crossed a plane by the gap $g < 0$ feels the
     * force $-k g\,n$. Its stiffness collects, from every boundary face of
     * the node, a quarter of the face stiffness $k = s K A^2 / V$ (LS-DYNA's
     * choice for solids: $s$ the penalty scale factor, $K$ the bulk modulus
     * of the face's element, $A$ the face area, $V$ the element volume).
     * The critical time step of a node of mass $m$ on its penalty spring
     * is $2\sqrt{m/k}$; the explicit solver limits its step accordingly.
     */
    class RigidPlaneContact
    {
    public:
      /**
       * Find the boundary nodes (on faces with one of @p boundary_ids) and
       * their penalty stiffness.
       *
       * @param bulk_modulus_by_material K (GPa) for each material id.
       */
      void
      initialize(const DoFHandler<3, 3> &dof_handler,
                 const std::shared_ptr<const Utilities::MPI::Partitioner>
                   &                                        partitioner,
                 const std::set<types::boundary_id> &       boundary_ids,
                 const std::vector<double> &                bulk_modulus_by_material,
                 const double                               penalty_scale,
                 const std::vector<RigidPlane> &            planes);

      /**
       * Add the contact forces at displacement @p u (owned entries) with
       * the planes displaced by @p plane_displacement into @p f (owned
       * entries only).
       */
      void
      add_forces(const VectorType &               u,
                 const std::vector<Tensor<1, 3>> &plane_displacement,
                 VectorType &                     f,
                 ContactResult &                  result) const;

      /**
       * Smallest stable time step of the penalty springs, 2 sqrt(m/k), for
       * the lumped masses @p mass.
       */
      double
      stable_time_step(const VectorType &mass) const;

      /** Number of locally owned contact nodes. */
      unsigned int
      n_nodes() const;

    private:
      struct Node
      {
        /** Local indices of the x, y, z degrees of freedom. */
        unsigned int dofs[3];
        /** Reference position (mm). */
        Point<3> X;
        /** Penalty stiffness (kN/mm). */
        double stiffness;
      };
      std::vector<Node>       nodes;
      std::vector<RigidPlane> planes;
    };
  } // namespace contact
} // namespace rubberdyn

#endif
