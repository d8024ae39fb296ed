#ifndef rubberdyn_source_time_integration_rigid_part_unknowns_h
#define rubberdyn_source_time_integration_rigid_part_unknowns_h

// The unknowns of the rigid parts in equilibrium on a quasi-static load
// path (private to source/time_integration: the quasi-static solver's
// bordered system; doc/theory.md, section 14).

#include <deal.II/base/mpi.h>
#include <deal.II/base/partitioner.h>
#include <deal.II/lac/full_matrix.h>

#include <rubberdyn/base/vector.h>
#include <rubberdyn/model/rigid_body.h>
#include <rubberdyn/time_integration/quasi_static_solver.h>

#include <array>
#include <string>
#include <vector>

namespace rubberdyn
{
  namespace time_integration
  {
    /**
     * The free directions of rigid parts as unknowns of a Newton system.
     *
     * A rigid part's nodes (every dof of its cells: the Q1 vertices, or
     * the Q2 support points) are eliminated as constrained dofs, and move
     * with the part's pose: $x_i = C + d + R (X_i - C)$, C its centre
     * (RigidPartInEquilibrium::centre), d its displacement and R its rotation
     * (model::RigidBody's reference_position, displacement and rotation).
     * Linearised, a node moves by $\delta x_i = T_i \delta q = \delta d +
     * \delta\theta \times (x_i - c)$, c = C + d, with one unknown per free
     * direction (translations x, y, z; rotations about axes through c). The
     * unknown's mode g_j is column j of T on the part's dofs, zero
     * elsewhere.
     *
     * The solver borders its system with these modes as it does with the
     * pretension sections: k_j = K g_j, k^_j = K^T g_j (add_block(), on
     * every element and contribution block, before the constraints
     * eliminate the nodes' rows and columns), the part's equilibrium
     * $T^T r = 0$ (project()), and its block $g_k^T K g_j$ plus the
     * geometric stiffness of the turning lever arms,
     * $\sum_i [a_i r_i^T - (a_i \cdot r_i) 1]$ with $a_i = x_i - c$
     * (add_geometric_stiffness()).
     */
    class RigidPartUnknowns
    {
    public:
      /**
       * Find the nodes of @p parts (owned and ghost cells with their
       * material ids).
       *
       * @throws ExcMessage if a node is in two of them.
       */
      RigidPartUnknowns(
        const DoFHandler<3, 3>                                   &dof_handler,
        const std::shared_ptr<const Utilities::MPI::Partitioner> &partitioner,
        const std::vector<RigidPartInEquilibrium>                &parts,
        const MPI_Comm                                            comm);

      /** The number of unknowns (free directions of all parts). */
      unsigned int
      n_unknowns() const
      {
        return unknowns.size();
      }

      /**
       * The parts at their reference place: name, centre
       * (reference_position), zero displacement, unit rotation.
       */
      std::vector<model::RigidBody>
      reference_poses() const;

      /** "the rigid part 'plate' in its free direction ry", for messages. */
      std::string
      describe(const unsigned int j) const;

      /** Whether the local dof @p i is a node of one of the parts. */
      bool
      contains(const unsigned int i) const
      {
        return part_of_dof[i] >= 0;
      }

      /** Whether unknown @p j is a rotation (its equation is a moment). */
      bool
      is_rotation(const unsigned int j) const
      {
        return unknowns[j].direction >= 3;
      }

      /**
       * The length that turns a part's moment into a force for the
       * residual norm: the root mean square distance of its nodes from
       * its centre (mm).
       */
      double
      length_scale(const unsigned int j) const
      {
        return parts[unknowns[j].part].length;
      }

      /**
       * Set the owned entries of @p u at the parts' nodes from @p poses
       * (exactly, with the finite rotation).
       */
      void
      place_nodes(const std::vector<model::RigidBody> &poses,
                  VectorType                          &u) const;

      /**
       * Advance @p poses by @p alpha times the increments @p dq:
       * $d \leftarrow d + \alpha \delta d$,
       * $R \leftarrow \exp(\alpha [\delta\theta]_\times) R$.
       */
      void
      advance(std::vector<model::RigidBody> &poses,
              const std::vector<double>     &dq,
              const double                   alpha) const;

      /**
       * Take the nodes' current positions from @p u (ghosted) and the
       * centres from @p poses: the point about which the modes, the
       * projections and the geometric stiffness are taken.
       */
      void
      set_linearisation_point(const VectorType                    &u,
                              const std::vector<model::RigidBody> &poses);

      /**
       * Add K g_j and K^T g_j of the block @p K (n x n, row-major, on the
       * local dofs @p dofs) to @p column[j] and @p row[j] (at all the
       * block's dofs, constrained or not), and keep the block if it
       * touches a part (for add_curvature_force()). Call clear_blocks()
       * before an assembly.
       */
      void
      add_block(const unsigned int      *dofs,
                const unsigned int       n,
                const double            *K,
                std::vector<VectorType> &column,
                std::vector<VectorType> &row);

      /** Forget the blocks kept by add_block(). */
      void
      clear_blocks()
      {
        blocks.clear();
      }

      /**
       * Add to @p force (local entries, to be compressed) K e, with the
       * kept blocks and e the part of the nodes' motion from @p poses to
       * the poses advanced by @p dq that the linearised motion T dq
       * misses: its curvature, $(\exp([\delta\theta]_\times) - 1 -
       * [\delta\theta]_\times)(x_i - c)$, second order in the rotation.
       * In a nearly incompressible solid bonded to the part, that
       * mismatch between the exactly placed nodes and the linearly
       * predicted free dofs around them is a volumetric strain times the
       * bulk modulus; the solver takes it out of the free dofs' update.
       */
      void
      add_curvature_force(const std::vector<model::RigidBody> &poses,
                          const std::vector<double>           &dq,
                          VectorType                          &force) const;

      /**
       * $T^T v$: each unknown's generalised component of the owned entries
       * of @p v (a force on the nodes: its resultant in a translation, its
       * moment about c in a rotation), summed over the ranks.
       */
      std::vector<double>
      project(const VectorType &v) const;

      /**
       * Add the geometric stiffness of the rotations, with the nodal
       * residual @p r (owned entries), to @p block (n_unknowns square;
       * summed over the ranks).
       */
      void
      add_geometric_stiffness(const VectorType   &r,
                              FullMatrix<double> &block) const;

      /** Add $T \delta q$ to the owned entries of @p du. */
      void
      add_linear_motion(const std::vector<double> &dq, VectorType &du) const;

    private:
      /** One part's nodes. */
      struct PartNodes
      {
        std::string name;
        /** Local indices of the x, y, z dofs of each node (owned, ghost). */
        std::vector<std::array<unsigned int, 3>> dofs;
        /** Reference positions, and whether this rank owns the node. */
        std::vector<Point<3>> X;
        std::vector<bool>     owned;
        /** Its centre (mm), and the length scale (mm). */
        Point<3> centre;
        double   length = 1.;
        /** Current positions and centre (set_linearisation_point()). */
        std::vector<Point<3>> x;
        Point<3>              c;
      };
      /** One unknown: a part and a direction (0-2 x, y, z; 3-5 rx, ry, rz). */
      struct Unknown
      {
        unsigned int part, direction;
      };

      /**
       * Call @p action(local dof, g_j there) for every owned dof of the
       * part of unknown @p j.
       */
      template <typename Action>
      void
      for_each_owned_entry(const unsigned int j, const Action &action) const;

      /** Column j of T at node @p n of its part (current positions). */
      Tensor<1, 3>
      mode(const unsigned int j, const unsigned int n) const;

      std::shared_ptr<const Utilities::MPI::Partitioner> partitioner;
      MPI_Comm                                           comm;
      std::vector<PartNodes>                             parts;
      std::vector<Unknown>                               unknowns;
      /** The unknowns of each part. */
      std::vector<std::vector<unsigned int>> unknowns_of_part;
      /**
       * Per local dof (owned and ghost): its part (-1: none), its node in
       * that part and its component.
       */
      std::vector<int>           part_of_dof;
      std::vector<unsigned int>  node_of_dof;
      std::vector<unsigned char> component_of_dof;
      /** The blocks of the last assembly that touch a part. */
      struct Block
      {
        std::vector<unsigned int> dofs;
        std::vector<double>       K;
      };
      std::vector<Block> blocks;
    };
  } // namespace time_integration
} // namespace rubberdyn

#endif
