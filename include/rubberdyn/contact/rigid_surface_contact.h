#ifndef rubberdyn_contact_rigid_surface_contact_h
#define rubberdyn_contact_rigid_surface_contact_h

#include <deal.II/base/partitioner.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

#include <rubberdyn/base/vector.h>
#include <rubberdyn/model/rigid_surface.h>

#include <functional>
#include <iosfwd>
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

    /* The rigid surfaces' geometry is part of the Model's definition
       (model/rigid_surface.h); contact uses it under these names. */
    using model::RigidSurface;
    using model::SurfacePose;

    /** What contact did in one evaluation. */
    struct ContactResult
    {
      /**
       * Force of the solid on each surface (kN), i.e. minus the sum of the
       * contact forces applied to the solid's nodes.
       */
      std::vector<Tensor<1, 3>> force_on_plane;
      /**
       * Moment of those forces (kN mm) about each surface's current
       * centre (SurfacePose: centre + displacement).
       */
      std::vector<Tensor<1, 3>> moment_on_plane;
      /**
       * Work done by the solid on the normal and tangential penalty springs
       * (J = kN mm): the energy they store less what the updates of their
       * stiffness to the current geometry put in
       * (RigidSurfaceContact::follow_geometry()).
       */
      double penalty_energy = 0.;
      /** Energy dissipated by Coulomb slip in this evaluation (J). */
      double friction_dissipation = 0.;
    };

    /**
     * Node-to-surface penalty contact of the boundary nodes of a solid with
     * rigid surfaces, frictionless or with Coulomb friction (the plates of
     * the drop test, walls, pins, holes).
     *
     * Normal: a boundary node that has crossed a surface by the gap $g < 0$
     * feels the force $-k g\,n$. Its stiffness collects, from every contact
     * face of the node, a quarter of the face stiffness $k = s K A^2 / V$
     * (LS-DYNA's choice for solids: $s$ the penalty scale factor, $K$ the
     * bulk modulus of the face's element, $A$ the face area, $V$ the element
     * volume), both of the current geometry: the stiffness per area, $s K
     * A / V = s K / h$, follows the element's thickness h normal to the
     * surface as the element's own stiffness does, so that the penetration
     * stays the same small fraction of the element's compression however
     * far a rubber element is squashed. (With the reference geometry the
     * stiffness per area fell as $A_0/A$ while the rubber spread under
     * compression: 8 % of the drop test's force at maximum compression sat
     * in the springs, doc/drop_test.md.) The stiffness is computed when
     * follow_geometry() asks for it, at the next add_forces(), and held
     * until the next request: the explicit solver asks at every step, the
     * quasi-static solver after each load step's predictor and when Newton
     * has converged in the run's last step (then it iterates on, if the
     * residual with the new stiffness is not converged: the state an
     * explicit run may start from), so that its tangent is the exact
     * derivative of forces whose stiffness is constant during the
     * iterations. The force is $-k g\,n$ with that stiffness (as in the
     * crash codes; not the gradient of $k g^2/2$, which would add
     * $-\tfrac12 g^2 \nabla k$ on the face's nodes): an update that
     * changes k under a node with the gap g adds $\tfrac12 \Delta k\,g^2$
     * to the spring without work. ContactResult::penalty_energy is
     * therefore the work done on the springs, the normal one's by the
     * trapezoidal rule over each step (as the central differences see the
     * force), not the energy they hold, so the energy balance closes (as
     * LS-DYNA's sliding interface energy); what the updates and the
     * sampling of a stiff spring put in or took shows as the work left
     * after the contact opens.
     *
     * Friction: an elastic-plastic tangential spring of the same stiffness
     * (regularised Coulomb law, e.g. Wriggers, Computational Contact
     * Mechanics, 2006, sect. 5.2). Each evaluation moves the tangential force
     * by $-k\,\Delta u_t$, the increment of the node's displacement
     * relative to the surface projected on the tangent plane; if it exceeds
     * $\mu |f_n|$ it is scaled back to the Coulomb cone (slip). The energy
     * dissipated in a slipping step is the work the node did on the spring,
     * $-\tfrac12 (f_t^{old} + f_t^{new}) \cdot \Delta u_t$ (the trapezoidal
     * rule, as the energy balance sees it), minus the increase of the
     * stored energy: $\mu |f_n| |\Delta u_t|$ in steady slip, and all the
     * energy released when the limit shrinks under a node that does not
     * move. The spring's stored energy $|f_t|^2/2k$ is part of
     * penalty_energy. A node that separates forgets its tangential force,
     * and the energy it held is dissipated.
     *
     * The critical time step of a node of mass $m$ on its penalty spring is
     * $2\sqrt{m/k}$, or $2\sqrt{m/(n k)}$ while it touches n surfaces at
     * once; the explicit solver combines it with the elements'.
     *
     * The friction state is kept twice: the accepted state (of the last
     * step taken) and the trial state of the last evaluation. add_forces()
     * starts from the accepted one and writes the trial one, accept()
     * makes the trial state current. The explicit solver evaluates once
     * per step and accepts; the quasi-static solver evaluates many times
     * (Newton iterations, line search) from the same accepted state and
     * accepts the converged one, as a return mapping must.
     *
     * For the quasi-static solver add_tangents() gives the exact
     * derivative of these forces (doc/theory.md, section 13), including
     * the curvature of a cylinder and, with friction, the rotation of the
     * old tangential force into the current tangent plane and the
     * derivative of the Coulomb cone. A closed gap ($g \le 0$, also $g = 0$
     * exactly) is active in the tangent: a body that rests on a surface
     * without load at the start gets the surface's normal stiffness and,
     * with friction, its sticking stiffness $k (1 - n \otimes n)$, so that
     * a body held only by contact can be solved.
     */
    class RigidSurfaceContact
    {
    public:
      /**
       * Find the boundary nodes (on faces with one of @p boundary_ids) and
       * their penalty stiffness in the reference configuration.
       *
       * @param bulk_modulus_by_material K (GPa) for each material id.
       */
      void
      initialize(const DoFHandler<3, 3> &dof_handler,
                 const std::shared_ptr<const Utilities::MPI::Partitioner>
                   &                                  partitioner,
                 const std::set<types::boundary_id> & boundary_ids,
                 const std::vector<double> &          bulk_modulus_by_material,
                 const double                         penalty_scale,
                 const std::vector<RigidSurface> &    surfaces);

      /**
       * Add the contact forces at displacement @p u (owned entries) with
       * the surfaces at @p pose into @p f (owned entries only), and the
       * forces of the solid on each surface and their moments about its
       * current centre into @p result, and advance the friction state to this
       * configuration: call once per time step.
       */
      void
      add_forces(const VectorType &              u,
                 const std::vector<SurfacePose> &pose,
                 VectorType &                    f,
                 ContactResult &                 result);

      /**
       * Make the friction state of the last add_forces() the accepted one
       * (no-op if there was no evaluation since the last accept()).
       */
      void
      accept();

      /**
       * Have the next add_forces() compute the penalty stiffness from its
       * displacement (the current face areas and element volumes), and hold
       * it until the next call. Collective: the nodes' stiffness gathers
       * the faces of the cells of every rank around them.
       */
      void
      follow_geometry();

      /**
       * Write (read) what a checkpoint needs beyond state(): the stiffness
       * of the accepted state and the energy its updates have added.
       */
      void
      save_stiffness(std::ostream &out) const;
      void
      load_stiffness(std::istream &in);

      /**
       * Receives the tangent of one node against one surface: the local
       * indices of its x, y, z dofs, the surface's index and the 3 x 3
       * derivative of the resisting force (minus the contact force on the
       * solid) with respect to the node's displacement (kN/mm). (With
       * respect to a translation of the surface it is the negative.)
       */
      using NodeTangent =
        std::function<void(const unsigned int (&dofs)[3],
                           const unsigned int  surface,
                           const Tensor<2, 3> &K)>;

      /**
       * The exact derivative of the forces add_forces() computes at @p u
       * and @p pose from the accepted friction state, node by node (this
       * rank's nodes), for every node with a closed gap (g <= 0).
       */
      void
      add_tangents(const VectorType               &u,
                   const std::vector<SurfacePose> &pose,
                   const NodeTangent              &add) const;

      /** Whether any surface has friction (then the tangent is unsymmetric). */
      bool
      has_friction() const;

      /**
       * Smallest stable time step of the penalty springs, 2 sqrt(m/k), for
       * the lumped masses @p mass.
       */
      double
      stable_time_step(const VectorType &mass) const;

      /** Number of locally owned contact nodes. */
      unsigned int
      n_nodes() const;

      /**
       * The accepted friction state (per node and surface: tangential force
       * and the node's position relative to the surface at the last
       * accepted evaluation), for checkpoints and the preload.
       */
      std::vector<double> &
      state();

      /**
       * Gap (mm, negative: penetration) and unit normal into the solid at
       * @p x (surface frame), and, if @p curvature is given, the
       * derivative of the normal with respect to x (1/mm; zero for a
       * plane).
       */
      static void
      gap_and_normal(const RigidSurface &surface,
                     const Point<3> &    x,
                     double &            gap,
                     Tensor<1, 3> &      normal,
                     Tensor<2, 3> *      curvature = nullptr);

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

      /** The contact of one node with one surface (surface frame). */
      struct NodeContact
      {
        /** Normal force k (-g) (kN, > 0 in contact). */
        double normal_force = 0.;
        /**
         * The accepted tangential force turned into the current tangent
         * plane, its magnitude kept (kN).
         */
        Tensor<1, 3> old_force;
        /** Tangential motion since the accepted state (mm). */
        Tensor<1, 3> increment;
        /** The new tangential force (kN), on the Coulomb cone if slip. */
        Tensor<1, 3> tangential_force;
        /** The whole force on the solid, normal and tangential (kN). */
        Tensor<1, 3> force;
        bool         slip = false;
      };

      /**
       * The force on a node at @p x (surface frame) with the gap @p gap
       * and normal @p normal, from the accepted tangential force
       * @p accepted_force and position @p accepted_position (NaN: none
       * yet), and, if @p jacobian is given, its derivative with respect
       * to x (needs @p curvature).
       */
      static void
      node_contact(const RigidSurface &surface,
                   const double        stiffness,
                   const Point<3>     &x,
                   const double        gap,
                   const Tensor<1, 3> &normal,
                   const Tensor<2, 3> &curvature,
                   const Tensor<1, 3> &accepted_force,
                   const Tensor<1, 3> &accepted_position,
                   NodeContact        &contact,
                   Tensor<2, 3>       *jacobian);

      /** A node's position in the frame of a surface at @p pose. */
      static Point<3>
      relative_position(const SurfacePose &pose, const Point<3> &x);

      /**
       * A contact face of a locally owned cell: what its penalty stiffness
       * $s K A^2/V$ needs in the current geometry.
       */
      struct Face
      {
        /** Local indices of the x, y, z dofs of the cell's 8 vertices. */
        unsigned int dofs[8][3];
        /** Reference positions of the cell's vertices (mm). */
        Point<3> X[8];
        /** The face's vertices (cell numbering) in cyclic order. */
        unsigned char corner[4];
        /** s K (GPa) of the cell's material. */
        double scaled_bulk_modulus;
      };

      /**
       * Each node's stiffness from the faces at displacement @p u (ghosted):
       * every rank its own cells' faces, summed at the nodes.
       */
      void
      compute_stiffness(const VectorType &u);

      std::vector<Node>         nodes;
      std::vector<Face>         faces;
      std::vector<RigidSurface> surfaces;
      /** Sums the faces' stiffness at the nodes (z dofs, with ghosts). */
      VectorType stiffness_sum;
      /** Whether the next add_forces() computes the stiffness. */
      bool follow_pending = false;
      /**
       * Each node's stiffness at the last accepted evaluation (empty: none
       * since the start, no update to book) (kN/mm).
       */
      std::vector<double> accepted_stiffness;
      /**
       * Energy the stiffness updates added to the springs up to the
       * accepted state, and in the last evaluation (J).
       */
      double accepted_stiffness_energy = 0., trial_stiffness_energy = 0.;
      /**
       * Per node n and surface s, at [(n * n_surfaces + s) * 6]: the
       * tangential force (kN, 3) and the node's position relative to the
       * surface (its frame) (mm, 3); of the last accepted evaluation, and
       * of the last evaluation.
       */
      std::vector<double> accepted_state, trial_state;
      /** Whether add_forces() ran since the last accept(). */
      bool trial_pending = false;
      /**
       * Number of surfaces each node penetrated at the last add_forces():
       * its springs act in parallel, which the stable step accounts for.
       */
      std::vector<unsigned char> n_touched;
    };
  } // namespace contact
} // namespace rubberdyn

#endif
