#ifndef rubberdyn_time_integration_quasi_static_solver_h
#define rubberdyn_time_integration_quasi_static_solver_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/partitioner.h>
#include <deal.II/base/tensor.h>

#include <rubberdyn/base/vector.h>
#include <rubberdyn/model/rigid_body.h>
#include <rubberdyn/parameters/time_integration_parameters.h>

#include <functional>
#include <iosfwd>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace dealii
{
  template <int dim, int spacedim>
  class DoFHandler;
}

namespace rubberdyn
{
  namespace elements
  {
    class ImplicitElements;
  }
  namespace model
  {
    class ForceContribution;
  } // namespace model

  namespace time_integration
  {
    using namespace dealii;
    class KinematicConstraints;

    /**
     * A quasi-static run that could not go on: a load step did not converge
     * after the allowed cut-backs, or reached the minimum step. The state
     * of the last converged step is kept (QuasiStaticSolver::time(),
     * displacement()).
     */
    class QuasiStaticFailure : public std::runtime_error
    {
    public:
      using std::runtime_error::runtime_error;
    };

    /**
     * What one load step cost, for the log and the tests.
     */
    struct LoadStepRecord
    {
      /** Pseudo-time at the end of the step. */
      double time = 0.;
      /** Its size. */
      double step = 0.;
      /** Newton iterations of the converged attempt. */
      unsigned int iterations = 0;
      /** Linear-solver iterations of the converged attempt (0: direct). */
      unsigned int linear_iterations = 0;
      /** Cut-backs before it converged. */
      unsigned int cutbacks = 0;
      /**
       * Newton iterations spent in those cut-back attempts (the cost that
       * `iterations` does not show).
       */
      unsigned int cutback_iterations = 0;
    };

    /**
     * How a pretension section is loaded on the load path (its plane and
     * the elements it cuts are the elements' business:
     * elements::ImplicitElements::n_sections()). Until the lock time the
     * section is driven, from then on its shortening is held ("locked"),
     * as CalculiX's pretension node with a force in one step and
     * `*BOUNDARY,FIXED` in the next.
     */
    struct PretensionLoad
    {
      /**
       * Force control: the shortening is an unknown, and the force across
       * the section follows target_force t / lock_time (kN) up to the lock
       * time. Otherwise the shortening is prescribed, shortening
       * min(t / lock_time, 1) (mm).
       */
      bool force_control = true;
      /** Force at the lock time (kN, > 0: tension). */
      double target_force = 0.;
      /** Shortening at the lock time (mm, shortening control). */
      double shortening = 0.;
      /** Pseudo-time at which the target is reached and the section locked. */
      double lock_time = 1.;
    };

    /**
     * A rigid part whose free directions are unknowns of the static
     * equilibrium (`Parts/<name>/Quasi-static motion = equilibrium`): its
     * nodes move with it, x = C + d + R (X - C) about its centre C, and d
     * and R (in its free directions; the others held) are
     * found with the displacement so that the forces on it (of the solid
     * through its nodes, and of the loads on its faces) have no resultant
     * and no moment there. Its nodes must be constrained dofs of the
     * KinematicConstraints (held: their motion comes from the part).
     */
    struct RigidPartInEquilibrium
    {
      /** Name, for messages and the columns. */
      std::string name;
      /** The material ids of its cells. */
      std::set<types::material_id> material_ids;
      /**
       * The point it turns about, at t = 0 (mm): its centre of mass as
       * the explicit engine has it (setup::rigid_part_centre_of_mass()),
       * so that a held translation holds the same point in both schemes.
       */
      Point<3> centre;
      /** Free translations x, y, z, then rotations about x, y, z. */
      bool free[6] = {false, false, false, false, false, false};
    };

    /**
     * Static equilibrium $f_{int}(u) = f_{ext}$ by Newton-Raphson with load
     * stepping in the pseudo-time t of the boundary-condition functions
     * (Wriggers, Nonlinear Finite Element Methods (2008), sections 5.1 and
     * 5.2; Belytschko, Liu, Moran, Nonlinear Finite Elements (2000), section
     * 6.3). No inertia.
     *
     * The residual is the internal force of the elements, taken through
     * elements::ImplicitElements (elements::SolidHexElements: the explicit
     * engine's force at zero velocity, the very function the explicit
     * solver integrates; or elements::MixedUPElements: Q2 with condensed
     * pressure and dilatation on an FE_Q(2) dof handler), minus the loads
     * of the further force contributions (tractions and follower pressures
     * at the step's end time t_{n+1}), and the tangent its exact derivative
     * (the elements' compute_tangents() and each contribution's
     * add_tangents()), so that Newton converges quadratically.
     *
     * Each load step from t_n to t_{n+1}: the first iteration solves
     * $K \delta u = -r$ with $\delta u$ prescribed on the constrained dofs
     * to $g(t_{n+1}) - u_n$ (the linearised predictor), the following ones
     * with $\delta u = 0$ there. Constraints are eliminated with
     * AffineConstraints (rows and columns removed, their inhomogeneity moved
     * to the right-hand side): the reduced matrix keeps the tangent's
     * symmetry where it has one, and later linear constraints (inclined
     * symmetry, a rigid part's six dofs, a pretension section's dof) are
     * lines of the same object. A backtracking line search halves the
     * correction (at most 6 times) while an element inverts or the residual
     * norm grows. Converged when both
     * $\|r_{free}\| \le \epsilon_r \max(\|r_{constrained}\|,
     * \|f_{ext,free}\|)$ (the reactions, or the loads on the free dofs; or
     * below an absolute floor) and
     * $|\delta u_k \cdot r_k| \le \epsilon_E |\delta u_0 \cdot r_0|$ (the
     * energy norm). A step that inverts an element, diverges (the residual
     * grows in two iterations in a row from the third on) or uses up its
     * iterations is halved; a step that took at most 4 iterations lets the
     * next grow by 1.5, up to the maximum step. One log line per iteration.
     *
     * Pretension sections (PretensionLoad) add one unknown each, the
     * shortening $\delta_s$, with the equation $N_s(u, \delta) = F_s(t)$
     * while force-controlled, or $\delta_s$ prescribed. The linear system
     * is bordered: $K \Delta u + \sum_s k_s \Delta\delta_s = -r$,
     * $\hat k_s \cdot \Delta u + \kappa_s \Delta\delta_s = -r_s$, with
     * $k_s = K g_s$, $\hat k_s = K^T g_s$ and $\kappa_s = g_s^T K g_s$
     * from the elements (compute_section_couplings()). It is solved by
     * block elimination with the factorisation (or the preconditioner) of
     * K: $K a = -r$, $K b_s = k_s$, a small dense system for the
     * $\Delta\delta$ of the force-controlled sections, then $\Delta u = a
     * - \sum_s b_s \Delta\delta_s$ (the bordering algorithm of arc-length
     * methods; Wriggers 2008, section 7.2). A load step never steps over
     * a lock time.
     *
     * Rigid parts in equilibrium (RigidPartInEquilibrium) border the
     * system the same way, with one unknown per free direction whose mode
     * is the part's rigid motion (a translation, or a rotation about its
     * current centre), and their equations are the part's resultant and
     * moment (doc/theory.md, section 14). Their poses advance with the
     * finite rotation, and the nodes are placed exactly on them.
     *
     * Rigid surfaces (contact::RigidSurfaceForces among the contributions)
     * are carried by rigid bodies that the load path places: at
     * pseudo-time t each body is at
     * model::RigidBody::displacement_on_load_path(t), or stands still
     * (the bodies of a preload, whose motion is the explicit run's). A
     * contribution's friction state starts from the state at t = 0
     * (accepted by initialize()) and is accepted with every converged
     * step. A surface that moves in a load step is treated like a moving
     * constraint: the first iteration linearises about the converged
     * state with the bodies at their old places and takes their motion as
     * a load (model::ForceContribution::add_body_motion_load()), so that
     * nodes sticking to a surface follow it (doc/theory.md, 13.5).
     *
     * The linear systems: Trilinos Amesos MUMPS (or KLU), or CG (hyperelastic
     * laws: symmetric tangent) or GMRES (inelastic laws) with ML AMG whose
     * near-null space holds the six rigid-body modes of the nodal
     * coordinates (three translations, three rotations), aggregating
     * nodes (three equations per node).
     */
    class QuasiStaticSolver
    {
    public:
      /**
       * @param elements Initialised elements (their history is advanced at
       *   every converged step).
       * @param constraints The kinematic conditions: displacement groups
       *   follow their functions of t, velocity groups (fixed and symmetry
       *   conditions, whose velocity is zero) hold their dofs at zero.
       * @param loads Further force contributions (the surface loads,
       *   rigid-surface contact), evaluated at the load step's end time with
       *   their tangents (model::ForceContribution::add_tangents()); each
       *   must support the implicit solver (an ExcMessage naming it
       *   otherwise).
       * @param bodies The rigid bodies the contributions see (those of the
       *   rigid surfaces), at their reference place.
       * @param bodies_move Whether the bodies follow their load path
       *   (else they stand still).
       * @param rigid_parts The rigid parts in equilibrium.
       */
      QuasiStaticSolver(
        const DoFHandler<3, 3>                                   &dof_handler,
        const std::shared_ptr<const Utilities::MPI::Partitioner> &partitioner,
        elements::ImplicitElements                               &elements,
        const KinematicConstraints                               &constraints,
        const std::vector<model::ForceContribution *>            &loads,
        const parameters::QuasiStatic                            &settings,
        const MPI_Comm                                            comm,
        const std::vector<PretensionLoad>                        &sections = {},
        const std::vector<model::RigidBody>                      &bodies   = {},
        const bool bodies_move = true,
        const std::vector<RigidPartInEquilibrium> &rigid_parts = {});

      ~QuasiStaticSolver();

      /** Which linear solver the runs use ("direct" or "AMG"). */
      std::string
      linear_solver_name() const;

      /**
       * Set the round-off floor r_0 of the residual (kN, default 0): the
       * force criterion of a Newton iteration is met if
       * @f[
       *   \|r_\text{free}\| \le \text{tol}\,\max(\|R\|, \|F_\text{load}\|)
       *   \quad\text{or}\quad \|r_\text{free}\| \le \max(r_0,
       *   \text{Residual floor})
       * @f]
       * (tol the Residual tolerance, R the reactions, F_load the loads);
       * the energy criterion is required as well. Where the reactions and
       * loads are nearly zero (a contact gap that has just closed) the
       * relative criterion asks for a residual below what the element
       * and contact forces can resolve in floating point, which no
       * cut-back can reach. simulation::QuasiStaticSimulation sets
       * @f$ r_0 = \varepsilon\,\max_p (K_p + \tfrac43 G_p) h_p^2\,
       * \sqrt{N} @f$ (doc/quasi_static.md, "Convergence").
       */
      void
      set_roundoff_floor(const double roundoff_floor);

      /** The floor of set_roundoff_floor() (kN). */
      double
      roundoff_floor() const;

      /**
       * Evaluate the state at the current time (forces, reactions, energy)
       * without solving, and accept the contributions' state there (the
       * friction state the first load step starts from).
       */
      void
      initialize();

      /**
       * Step from the current time to @p end_time, logging each iteration
       * to @p log (rank 0) and calling @p on_step after every converged
       * step (all ranks).
       *
       * @throws QuasiStaticFailure if a step cannot converge.
       */
      void
      run(const double                 end_time,
          std::ostream                &log,
          const std::function<void()> &on_step);

      /** Pseudo-time of the last converged state. */
      double
      time() const
      {
        return current_time;
      }

      /** Displacement of the last converged state (ghosted, mm). */
      const VectorType &
      displacement() const
      {
        return u;
      }

      /**
       * Reaction of every constraint group (kN, summed over the ranks): the
       * force the constraint exerts on the solid in its direction, i.e. the
       * internal force at its dofs.
       */
      const std::vector<double> &
      reactions() const
      {
        return reaction;
      }

      /**
       * Moment of each group's reactions about its moment point (kN mm),
       * with the nodes' current positions.
       */
      const std::vector<Tensor<1, 3>> &
      reaction_moments() const
      {
        return reaction_moment;
      }

      /** Stored energy of the elements (J), summed over the ranks. */
      double
      internal_energy() const
      {
        return energy;
      }

      /** The same per element group (J). */
      const std::vector<double> &
      internal_energy_by_group() const
      {
        return energy_by_group;
      }

      /**
       * Force across each pretension section (kN, tension positive, summed
       * over the ranks) in the last converged state.
       */
      const std::vector<double> &
      section_forces() const
      {
        return section_force;
      }

      /** Shortening of each pretension section (mm), last converged state. */
      const std::vector<double> &
      section_shortenings() const
      {
        return shortening;
      }

      /**
       * The rigid bodies at the last converged state (their
       * displacement).
       */
      const std::vector<model::RigidBody> &
      bodies() const;

      /**
       * The rigid parts in equilibrium at the last converged state: name,
       * centre (reference_position, mm), displacement (mm) and rotation.
       */
      const std::vector<model::RigidBody> &
      rigid_part_poses() const
      {
        return part_poses;
      }

      /** The converged load steps so far. */
      const std::vector<LoadStepRecord> &
      steps() const
      {
        return records;
      }

    private:
      /**
       * Evaluate the state at the current time: reactions, energies,
       * section and body forces.
       */
      void
      evaluate_state();

      class Implementation;
      std::unique_ptr<Implementation> impl;
      /** One load step's Newton iterations (run(); source file only). */
      class LoadStep;

      VectorType                  u;
      double                      current_time = 0.;
      std::vector<double>         reaction;
      std::vector<Tensor<1, 3>>   reaction_moment;
      double                      energy = 0.;
      std::vector<double>         energy_by_group;
      std::vector<LoadStepRecord> records;
      std::vector<double>         section_force, shortening;
      std::vector<model::RigidBody> part_poses;
    };
  } // namespace time_integration
} // namespace rubberdyn

#endif
