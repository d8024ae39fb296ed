#ifndef rubberdyn_time_integration_selective_mass_scaling_h
#define rubberdyn_time_integration_selective_mass_scaling_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/partitioner.h>

#include <rubberdyn/base/vector.h>

#include <array>
#include <iosfwd>
#include <memory>
#include <vector>

namespace rubberdyn
{
  namespace time_integration
  {
    using namespace dealii;

    /**
     * One element's added mass of selective mass scaling: the local indices
     * of the x, y, z dofs of its eight nodes (owned or ghost), the added
     * mass beta (kg), its element group (part), and its geometry: the
     * nodes' reference positions relative to their centroid (mm) and the
     * inverse of sum_a (|r_a|^2 I - r_a r_a^T) (1/mm^2), which project a
     * nodal vector onto the element's rigid rotations.
     */
    struct ScaledElement
    {
      std::array<std::array<unsigned int, 3>, 8> dofs;
      double                                     beta  = 0.;
      unsigned int                               group = 0;
      std::array<std::array<double, 3>, 8>       r;
      std::array<std::array<double, 3>, 3>       inverse_inertia;
      /** The element's share of each node's lumped mass (kg). */
      std::array<double, 8> node_mass;
      /**
       * For the preconditioner (set by SelectiveMassScaling::initialize()):
       * node_mass over the node's whole lumped mass, and the mean of
       * node_mass.
       */
      std::array<double, 8> weight;
      double                mean_mass = 0.;

      /**
       * Set r and inverse_inertia from the nodes' reference positions
       * @p X (mm).
       */
      void
      set_geometry(const std::array<std::array<double, 3>, 8> &X);
    };

    /**
     * What selective mass scaling did to one part (all ranks).
     */
    struct PartMassScaling
    {
      /** The part's target step (ms), 0: none. */
      double target_time_step = 0.;
      /** Its deformable elements, and how many of them got added mass. */
      unsigned long long n_elements = 0, n_scaled = 0;
      /**
       * Scaled elements' nodes shared with a rigid part: those elements
       * keep their mass (a rigid part's nodes move with its body).
       */
      unsigned long long n_next_to_rigid = 0;
      /**
       * The added mass per direction (kg): the trace of the added mass
       * matrix over one direction's dofs, sum of 6 beta_e. Rigid motions
       * of the elements get none of it.
       */
      double added_mass = 0.;
      /** The part's physical mass (kg). */
      double mass = 0.;
    };

    /** Settings of the per-step solve of selective mass scaling. */
    struct SelectiveMassScalingSettings
    {
      /**
       * Relative residual of the accelerations' solve, in the norm of the
       * inverse diagonal: |r|_{D^-1} <= tolerance |b|_{D^-1}.
       */
      double tolerance = 1e-4;
      /** The run stops with an error when a step needs more. */
      unsigned int max_iterations = 500;
    };

    /**
     * Selective mass scaling (Olovsson, Simonsson & Unosson 2005, IJNME 63,
     * 1436-1445; LS-DYNA IMSCL, OpenRadioss /DT/AMS): each scaled element
     * adds the mass matrix
     * @f[
     *   M^e_{add} = \beta_e P_e, \qquad P_e = I_{24} - \Phi_e (\Phi_e^T
     *   \Phi_e)^{-1} \Phi_e^T,
     * @f]
     * to the lumped mass, with Phi_e the element's six rigid modes
     * (translations, and rotations about its centroid in the reference
     * configuration): mass on the element's deformation modes only. Rigid
     * motions get none (M_add Phi = 0), so translational inertia, total
     * mass and momentum are the physical ones, and so is the rotation of
     * each element, which a beam's bending is made of; the deformation
     * modes, whose frequencies set the stable step, get beta more per node,
     * which lowers their frequencies by sqrt(m / (m + beta)) (doc/theory.md,
     * "Selective mass scaling").
     *
     * The mass matrix M = D + A (D the lumped masses, A the sum of the
     * elements' added masses) is no longer diagonal: each step solves
     * M a = f for the accelerations of the scaled elements' nodes by
     * conjugate gradients with the diagonal of M as preconditioner, from
     * the last step's accelerations. Dofs whose velocity is prescribed
     * (kinematic constraints) are known in the solve (their acceleration
     * is given); rigid parts' nodes must not be in a scaled element. A
     * last correction, uniform per direction over the unknown dofs, makes
     * the residual's sum vanish per direction: the momentum balance of the
     * scaled nodes is then exact to round-off whatever the tolerance.
     *
     */
    class SelectiveMassScaling
    {
    public:
      /**
       * @param elements The scaled elements of this rank (locally owned
       *   cells; beta > 0).
       * @param partitioner The dofs' partitioner (owned and ghost).
       * @param settings The solve's tolerance and iteration limit.
       */
      SelectiveMassScaling(
        std::vector<ScaledElement>                                elements,
        const std::shared_ptr<const Utilities::MPI::Partitioner> &partitioner,
        const SelectiveMassScalingSettings                       &settings,
        const MPI_Comm                                            comm);

      /**
       * Set the lumped masses @p lumped_mass (owned entries), the
       * direction (0, 1, 2) of each owned dof and which owned dofs have a
       * prescribed velocity. Collective.
       */
      void
      initialize(const VectorType                &lumped_mass,
                 const std::vector<unsigned int> &dof_component,
                 const std::vector<bool>         &prescribed);

      /** Whether owned dof @p i is a node of a scaled element. */
      bool
      scaled(const unsigned int i) const
      {
        return in_scaled_element[i];
      }

      /**
       * Solve M a = f for the accelerations of the scaled elements' free
       * dofs (mm/ms^2). On entry @p a holds, in its owned entries, the
       * prescribed dofs' accelerations and anything for the others (the
       * last step's are a good start); entries of dofs outside the scaled
       * elements are left alone. On exit the scaled free dofs hold the
       * solution and @p a's ghost entries are up to date. Collective.
       *
       * @return The number of iterations.
       * @throws std::runtime_error after SelectiveMassScalingSettings::
       *   max_iterations.
       */
      unsigned int
      solve(const VectorType &f, VectorType &a);

      /**
       * y = A x (owned entries; @p x ghosted, @p y's ghost entries are
       * used as scratch and zeroed). Collective.
       */
      void
      multiply_added_mass(const VectorType &x, VectorType &y) const;

      /**
       * Kinetic energy of the added mass, 1/2 v^T A v (J), of this rank's
       * elements for the ghosted velocity @p velocity, added per element
       * group into @p by_group (its size: the groups). Returns this rank's
       * sum. Not collective.
       */
      double
      added_kinetic_energy(const VectorType    &velocity,
                           std::vector<double> &by_group) const;

      /**
       * The added mass per direction, the trace of the added mass over
       * one direction's dofs: sum over the elements of 6 beta_e (P_e has
       * rank 18) (kg), per element group (this rank's elements; the caller
       * sums).
       */
      std::vector<double>
      added_mass_by_group(const unsigned int n_groups) const;

      /** Iterations of all solves so far, and the most in one. */
      unsigned long long
      total_iterations() const
      {
        return iterations_total;
      }
      unsigned int
      largest_iterations() const
      {
        return iterations_largest;
      }
      /** Iterations of the last solve. */
      unsigned int
      last_iterations() const
      {
        return iterations_last;
      }
      /** Number of solves so far. */
      unsigned long long
      n_solves() const
      {
        return solves;
      }

      /** The counters, for checkpoints. */
      void
      save(std::ostream &out) const;
      void
      load(std::istream &in);

    private:
      /**
       * z = B r, the preconditioner: an additive Schwarz method over the
       * elements with the nodes' mass shares as weights, each element's
       * mass inverted in closed form (doc/theory.md, "Selective mass
       * scaling"). @p r: owned entries, zero off the unknowns (its ghosts
       * are updated here); @p z: owned entries, zero off the unknowns.
       */
      void
      precondition(VectorType &r, VectorType &z) const;

      /** M x on the unknown dofs (owned), 0 elsewhere; x ghosted. */
      void
      multiply_unknowns(const VectorType &x, VectorType &y) const;

      /**
       * The scaled elements in blocks of four, one element per SIMD lane
       * (structure of arrays; padding lanes repeat the block's first
       * element with beta and weights zero, so that they add nothing).
       */
      struct ElementBlock
      {
        static constexpr unsigned int lanes = 4;
        unsigned int dofs[8][3][lanes];
        double       r[8][3][lanes];
        /** J^-1: xx, yy, zz, xy, xz, yz. */
        double       inverse_inertia[6][lanes];
        double       beta[lanes];
        double       weight[8][lanes];
        /** 1 / (mean mass + beta), 1 / mean mass (preconditioner). */
        double       deformation_inverse[lanes], rigid_inverse[lanes];
        unsigned int group[lanes];
        unsigned int n_active;
      };

      /** Fill `blocks` from `elements` (after the weights are known). */
      void
      make_blocks();

      std::vector<ScaledElement>                         elements;
      std::vector<ElementBlock>                          blocks;
      std::shared_ptr<const Utilities::MPI::Partitioner> partitioner;
      SelectiveMassScalingSettings                       settings;
      MPI_Comm                                           comm;

      /** Owned dofs: in a scaled element; unknown in the solve. */
      std::vector<bool> in_scaled_element, unknown;
      /** The owned unknown dofs' local indices and directions. */
      std::vector<unsigned int> unknown_dofs, unknown_component;
      /** Lumped mass and inverse diagonal of M (owned entries). */
      VectorType lumped, inverse_diagonal;
      /**
       * Per owned dof: the share of its lumped mass that no scaled element
       * holds, over the lumped mass (1/kg): the preconditioner's diagonal
       * part.
       */
      std::vector<double> rest_over_mass;
      /**
       * The inverse of W_{d'd} = sum over the unknown dofs of direction d'
       * of (M 1_d)_i, 1_d the unknowns' translation in d (momentum fix).
       */
      double inverse_translation_mass[3][3] = {};
      /** Scratch vectors of the solve. */
      mutable VectorType residual, search, product, preconditioned;
      /** Per block and lane: the added kinetic energy (no allocation a step). */
      mutable std::vector<double> energy_scratch;

      unsigned long long iterations_total   = 0;
      unsigned int       iterations_largest = 0;
      unsigned int       iterations_last    = 0;
      unsigned long long solves             = 0;
    };
  } // namespace time_integration
} // namespace rubberdyn

#endif
