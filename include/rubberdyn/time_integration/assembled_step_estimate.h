#ifndef rubberdyn_time_integration_assembled_step_estimate_h
#define rubberdyn_time_integration_assembled_step_estimate_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/partitioner.h>

#include <rubberdyn/base/vector.h>

#include <functional>
#include <iosfwd>
#include <memory>
#include <vector>

namespace rubberdyn
{
  namespace time_integration
  {
    using namespace dealii;

    /** Settings of AssembledStepEstimate. */
    struct AssembledStepSettings
    {
      /** Steps between two estimates (`Stable time step refresh interval`). */
      unsigned int refresh_interval = 100;
      /**
       * Most Lanczos steps (products with the stiffness) of one estimate;
       * an estimate not converged by then is not used (the element bound
       * sets the step until the next one).
       */
      unsigned int max_iterations = 40;
      /**
       * Converged when the residual of the largest Ritz pair is at most
       * this fraction of its Ritz value, $|\beta_k s_k| \le \text{tol}\,
       * \theta$ (-).
       */
      double tolerance = 1e-2;
    };

    /**
     * The largest eigenvalue $\omega_{max}^2$ of $M^{-1}K$ of the assembled
     * model, by a few Lanczos steps every refresh_interval steps (Abaqus/
     * Explicit's "global estimation" beside the element-by-element one).
     *
     * Why: the element bound of doc/theory.md section 8.3, $\omega_{max}
     * \le \max_e \omega_e$, is attained by a single free element, but in a
     * mesh a node is shared by up to eight elements and carries their
     * masses, and the elements' breathing modes cannot all be excited at
     * once: for a uniform mesh of cubes of nearly incompressible rubber the
     * assembled $\omega_{max} = 2c/h$ against the element's $2\sqrt3\,c/h$.
     * The assembled value is the true limit of central differences
     * ($\omega_{max}\Delta t \le 2$).
     *
     * How: Lanczos on the symmetric $B = M^{-1/2} K M^{-1/2}$ (the same
     * eigenvalues as $M^{-1}K$, M the lumped mass) restricted to the free
     * dofs (not prescribed, not moving with a rigid body), with full
     * reorthogonalisation (at most max_iterations vectors, allocated once).
     * The product $K x$ is given by the caller (the solver: a directional
     * finite difference of the elements' internal forces at the current
     * state, i.e. the tangent including its geometric part). Each estimate
     * starts from the previous one's Ritz vector, so that it usually
     * converges in a few steps; the first starts from a pseudo-random
     * vector of the nodes' positions (the same on any partition, so that
     * the Lanczos steps are the same up to the sums' round-off).
     *
     * The margin: a Ritz value $\theta$ lies below $\lambda_{max}$
     * (Rayleigh quotient), and the residual $r = |\beta_k s_k|$ of its Ritz
     * pair bounds the distance to the nearest eigenvalue (Parlett, *The
     * Symmetric Eigenvalue Problem*, ch. 4). The estimate is
     * $\theta + r$, used only when $r \le$ tolerance $\theta$, rounded up
     * to 2^-11 relative (so that round-off of the sums on other partitions
     * does not change the step). It is an estimate, not a proof: a start
     * vector without a component in the top eigenvector would miss it; the
     * caller caps it with the element bound, which is one (and keeps the
     * element bound's step where it is larger).
     */
    class AssembledStepEstimate
    {
    public:
      /**
       * The product of the stiffness with a direction: @p product = K @p
       * direction, owned entries (kN/mm times mm). Collective. Returns
       * false if the evaluation failed (an element inverted under the
       * probe); the estimate is then not used.
       */
      using StiffnessProduct =
        std::function<bool(const VectorType &direction, VectorType &product)>;

      /**
       * @param inverse_mass The inverse lumped mass (1/kg), owned entries.
       * @param free_dof Per owned dof whether it moves freely (false: a
       *   prescribed dof or a rigid part's node, left out).
       * @param start The first estimate's start vector, owned entries: a
       *   function of the node's position and the direction, so that it is
       *   the same on any partition (the global dof numbering is not).
       */
      AssembledStepEstimate(
        const AssembledStepSettings                              &settings,
        const std::shared_ptr<const Utilities::MPI::Partitioner> &partitioner,
        const VectorType                                         &inverse_mass,
        const std::vector<bool>                                  &free_dof,
        const std::vector<double>                                &start,
        const MPI_Comm                                            comm);

      /** Whether an estimate is due before step @p step. */
      bool
      due(const unsigned int step) const;

      /**
       * A new estimate at the current state (collective). Afterwards
       * omega_squared() is the new value, or 0 if it did not converge.
       */
      void
      refresh(const unsigned int step, const StiffnessProduct &product);

      /**
       * The step of the elements (ms) from the estimate and the current
       * element bounds (all reduced over the ranks): @p element_step the
       * element bound with bulk viscosity (ms), @p undamped_step without it
       * (ms), @p damping_factor the smallest ratio of the two over the
       * elements, $\sqrt{1+\xi^2}-\xi$ with $\xi = Q/c$ (-). Between two
       * estimates $\omega$ follows the element bound where that grows
       * ($\omega = \omega_a \max(1, \Delta t_u^{ref}/\Delta t_u)$, never
       * more than $2/\Delta t_u$) and does not fall; the step is
       * $\phi\,2/\omega$, and never less than @p element_step.
       */
      double
      element_time_step(const double element_step,
                        const double undamped_step,
                        const double damping_factor);

      /** The estimate of omega_max^2 (1/ms^2), 0 if none is in use. */
      double
      omega_squared() const
      {
        return estimate;
      }

      /** Counts for the run summary. */
      struct Statistics
      {
        /** Estimates made, and how many did not converge. */
        unsigned int refreshes = 0, unconverged = 0;
        /** Products with the stiffness (element force evaluations). */
        unsigned long products = 0;
        /** The last step / element step (-), 0 before the first. */
        double last_gain = 0.;
        /** Largest and smallest gain of the run (-). */
        double largest_gain = 0., smallest_gain = 0.;
        /** Wall time of the estimates (s, this rank). */
        double seconds = 0.;
      };

      /** The counts so far. */
      const Statistics &
      statistics() const
      {
        return stats;
      }

      /** Write the state (warm vector, estimate, reference step). */
      void
      save(std::ostream &out) const;

      /** Read what save() wrote. */
      void
      load(std::istream &in);

    private:
      /** Dot product of the owned entries over all ranks. */
      double
      dot(const VectorType &a, const VectorType &b) const;

      AssembledStepSettings                              settings;
      std::shared_ptr<const Utilities::MPI::Partitioner> partitioner;
      MPI_Comm                                           comm;
      /** M^{-1/2} on the free dofs, 0 on the others (owned entries). */
      std::vector<double> scale;
      /** The first estimate's start vector (owned entries). */
      std::vector<double> start_vector;
      /** The Lanczos vectors (max_iterations + 1) and two work vectors. */
      std::vector<VectorType> basis;
      VectorType              direction, product_vector, warm;
      bool                    has_warm = false;
      /** The tridiagonal matrix, its eigenvectors and LAPACK's workspace. */
      std::vector<double> alpha, beta, d, e, z, work;
      /** omega_max^2 (1/ms^2), 0: none. */
      double estimate = 0.;
      /** The undamped element step when the estimate was made (ms), 0:
       * to be taken at the next element_time_step(). */
      double       reference_undamped_step = 0.;
      unsigned int last_refresh            = 0;
      bool         refreshed               = false;
      Statistics   stats;
    };
  } // namespace time_integration
} // namespace rubberdyn

#endif
