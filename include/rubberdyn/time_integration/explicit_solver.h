#ifndef rubberdyn_time_integration_explicit_solver_h
#define rubberdyn_time_integration_explicit_solver_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/tensor.h>

#include <rubberdyn/base/vector.h>
#include <rubberdyn/model/force_contribution.h>
#include <rubberdyn/model/rigid_body.h>
#include <rubberdyn/time_integration/assembled_step_estimate.h>
#include <rubberdyn/time_integration/kinematic_constraints.h>

#include <array>
#include <chrono>
#include <functional>
#include <iosfwd>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace dealii
{
  template <int dim, int spacedim>
  class DoFHandler;
}

namespace rubberdyn
{
  /**
   * Time integrators. They move the model state in time and know nothing
   * of materials, elements or contact beyond the forces these return.
   */
  namespace time_integration
  {
    using namespace dealii;
    using model::RigidBody;

    class SelectiveMassScaling;

    /** Energies of the whole model (J = kN mm), summed over all ranks. */
    struct EnergyBalance
    {
      double kinetic              = 0.;
      double internal             = 0.;
      double external_work        = 0.;
      double contact              = 0.;
      double bulk_viscosity_work  = 0.;
      /** Energy dissipated by Coulomb friction. */
      double friction_work        = 0.;
      double initial              = 0.;
      /** Largest current_scale() of the run so far. */
      double largest_energy = 0.;
      /**
       * Kinetic energy of the rigid bodies (rigid surfaces' carriers and
       * rigid parts), part of `kinetic` (J).
       */
      double rigid_kinetic = 0.;
      /** Largest deformable_scale() of the run so far. */
      double largest_deformable = 0.;
      /**
       * |E_kin + E_int + E_contact + W_bulk viscosity + W_friction - E_0 -
       * W_ext| divided by the largest energy of the run so far
       * (largest_energy, or current_scale() if larger). Dividing by the
       * current energies instead would make a body that starts at rest
       * report 100 % in its first steps, where all terms are O(dt^2).
       */
      double
      relative_error() const;

      /**
       * |E_kin + E_int + E_contact + W_bulk viscosity + W_friction - E_0 -
       * W_ext| (J). A run's largest error is best judged as the largest of
       * these over the run divided by the largest energy of the whole run:
       * early on, when everything is O(dt^2), relative_error() is noisy.
       */
      double
      absolute_error() const;

      /**
       * The size of the energies now: max(sum of the magnitudes of the
       * present terms, |E_0| + |W_ext|).
       */
      double
      current_scale() const;

      /**
       * The energy that flows through the deformable parts now: their
       * kinetic energy (all but the rigid bodies'), internal, contact,
       * bulk-viscosity and friction energy (J).
       */
      double
      deformable_scale() const;

      /**
       * absolute_error() divided by the largest energy that has flowed
       * through the deformable parts so far (largest_deformable, or
       * deformable_scale() if larger), but at least 1 % of the largest
       * energy so far (so that round-off before any deformation is not
       * divided by nothing): never more lenient than relative_error(). A
       * 10 J impactor no longer hides the loss of a rubber part's 0.04 J.
       * The run is judged by DeformableErrorRecord, with the floor of the
       * whole run.
       */
      double
      deformable_relative_error() const;
    };

    /**
     * The run's energy error judged against the energy through its
     * deformable parts: $\max_t e(t) / \max(d(t), F)$, with $e$ the
     * absolute error, $d$ the largest deformable energy up to t
     * (EnergyBalance::largest_deformable) and the floor F known only at the
     * end (1 % of the run's largest energy: round-off and start-up errors
     * of a body starting at rest, 1e-12 J when everything is 1e-12 J, are
     * not judged against nothing). A loss early in an impact, when the
     * rubber holds 0.04 J and the impactor 10 J, is judged against the
     * 0.04 J.
     *
     * Since d never decreases, only the steps with a record error can
     * attain the maximum for some F: add() keeps those (d, e), thinned so
     * that each kept error exceeds the last by 0.1 % (value() is exact to
     * 0.1 %; a few thousand pairs at most).
     */
    class DeformableErrorRecord
    {
    public:
      /** Record the error @p error (J) with the deformable energy @p d (J). */
      void
      add(const double error, const double deformable);

      /** max over the recorded steps of error / max(d, @p floor). */
      double
      value(const double floor) const;

      /** The pairs (d, e), for checkpoints. */
      std::vector<double>
      state() const;

      /** Restore what state() returned. */
      void
      set_state(const std::vector<double> &state);

    private:
      std::vector<std::pair<double, double>> records;
    };

    /**
     * Kinetic energy and momentum of one group of nodes (a deformable
     * part), at the current time, summed over all ranks.
     */
    struct GroupMotion
    {
      /** Kinetic energy (J). */
      double kinetic_energy = 0.;
      /** Momentum (kg mm/ms = N s). */
      Tensor<1, 3> momentum;
    };

    /**
     * The work terms of one group of nodes (a part) up to the current time,
     * summed over all ranks, booked like the model's: with
     * GroupMotion::kinetic_energy and the part's internal energy they are
     * the part's share of every term of EnergyBalance (LS-DYNA's MATSUM).
     * A node shared by several parts is split between them by mass, like
     * its kinetic energy; a rigid part's nodes belong to it alone.
     */
    struct GroupWork
    {
      /** Energy dissipated by the part's bulk viscosity (J). */
      double bulk_viscosity = 0.;
      /** Work of gravity on the part's nodes (J). */
      double gravity = 0.;
    };

    /**
     * The energy terms of one rigid body up to the current time, summed
     * over all ranks: what it adds to EnergyBalance.
     */
    struct BodyEnergy
    {
      /**
       * Kinetic energy of translation and rotation (J). For a rigid part
       * it is also the part's GroupMotion::kinetic_energy.
       */
      double kinetic = 0.;
      /**
       * Work of gravity on the body (J); 0 for a rigid part, whose weight
       * acts on its nodes (GroupWork::gravity).
       */
      double gravity_work = 0.;
      /**
       * Work done on the solid through the body where its motion is
       * prescribed (held or driven directions): minus the solid's force on
       * the body times the body's displacement, by the trapezoidal rule per
       * step like the constraints' work (J).
       */
      double drive_work = 0.;
    };

    /**
     * Wall time (s) spent in each part of the time steps of a run, on this
     * rank, for the benchmark breakdown.
     */
    struct StepTimings
    {
      /** Internal forces, energies and stable steps of the elements. */
      double element_forces = 0.;
      /** Contact forces and their stable step. */
      double contact = 0.;
      /** Velocity and displacement updates, constraints, rigid bodies. */
      double vector_updates = 0.;
      /** Ghost exchange, force compression and the two collectives. */
      double communication = 0.;
      /** The monitor: history rows, field output, progress line. */
      double output = 0.;
      /**
       * The solve of selective mass scaling (part of vector_updates and
       * communication above, not in addition).
       */
      double mass_scaling = 0.;
    };

    /** Settings of the central-difference integrator. */
    struct ExplicitSettings
    {
      /** Factor on the smallest element and contact stable step. */
      double time_step_scale = 0.9;
      /** The run stops with an error below this step (ms). */
      double minimum_time_step = 1e-8;
      /**
       * Whether the elements' step comes from the assembled model's
       * largest frequency (AssembledStepEstimate, `Stable time step
       * estimate = assembled`) instead of the element bound alone.
       */
      bool assembled_step_estimate = false;
      /** Its settings (refresh interval). */
      AssembledStepSettings assembled_step;
      /** Gravitational acceleration (mm/ms^2), on solid and bodies. */
      Tensor<1, 3> gravity;
      /**
       * Number of element groups (parts) for the per-group internal
       * energy, kinetic energy and momentum.
       */
      unsigned int n_groups = 1;
    };

    /**
     * The locally owned nodes of a rigid part (LS-DYNA's MAT_RIGID): they
     * move with one rigid body, $x = c + R (X - C)$.
     */
    struct RigidPartNodes
    {
      /** Index of the part's body among the solver's bodies. */
      unsigned int body = 0;
      /** The part's element group (for the per-group sums). */
      unsigned int group = 0;
      /** Local indices of the x, y, z dofs of each locally owned node. */
      std::vector<std::array<unsigned int, 3>> dofs;
      /** Reference position of each node (mm). */
      std::vector<Point<3>> X;
    };

    /** Raised when the run cannot go on (inverted element, tiny step). */
    class SolverFailure : public std::runtime_error
    {
    public:
      using std::runtime_error::runtime_error;
    };

    /**
     * Explicit central-difference integration (reference study eqs.
     * 2.7-2.10) with lumped mass: velocities at half steps, displacements
     * at full steps,
     * @f[
     *   v^{n+1/2} = v^{n-1/2} + \Delta t^n M^{-1} (f^n_{ext} - f^n_{int}
     *     + f^n_{contact}),\qquad u^{n+1} = u^n + \Delta t^{n+1/2} v^{n+1/2},
     * @f]
     * $\Delta t^n = (\Delta t^{n-1/2} + \Delta t^{n+1/2})/2$, and the first
     * half step starts from the initial velocity ($\Delta t^0 =
     * \Delta t^{1/2}/2$).
     *
     * The forces come from a list of model::ForceContribution (elements,
     * rigid-surface contact, loads); the solver knows none of them
     * concretely. The step is re-evaluated every step from the
     * contributions' element and penalty-spring steps, times the scale
     * factor. A contact node is held by its elements and its penalty spring
     * in parallel, so the step is limited by $1/\Delta t^2 = 1/\Delta
     * t_e^2 + 1/\Delta t_c^2$ with the smallest element and contact steps
     * of the whole model: both minima are reduced over the ranks first and
     * combined after, so that the step does not depend on the partition
     * (conservative: the two minima need not be at the same node). Per
     * step there are exactly two MPI collectives: the minimum (the two
     * steps and the failure flag) and one sum (contact forces on rigid
     * bodies, reactions of kinematic constraints and energy terms).
     *
     * Kinematic constraints overwrite the half-step velocities of their
     * dofs; their reaction $r = M(v^{n+1/2} - v^{n-1/2})/\Delta t^n - f^n$
     * is what the constraint applies to the solid, and its work is external
     * work, by the trapezoidal rule on each step like the energies at $t_n$:
     * $\tfrac12 (r^{n-1} + r^n) \cdot v^{n-1/2} \Delta t^{n-1/2}$ from
     * $t_{n-1}$ to $t_n$ (on the first step $r^0 \cdot \tfrac12 (v^0 +
     * v^{1/2}) \Delta t^0$, exact for a jump from the initial velocity).
     * The constraints are given to the constructor and applied at the
     * first step (or kept from a checkpoint), so that no call order can
     * overwrite a loaded state.
     *
     * A rigid body with mass 0, or in a held direction, moves with its
     * prescribed velocity; the work it does on the solid,
     * $-F_{solid\to body} \cdot \Delta x_{body}$, is external work.
     *
     * Rigid parts (set_rigid_parts()): the nodes of a rigid part move with
     * its body. The forces on them (from neighbouring deformable elements,
     * contact, loads, gravity) are summed into the body's force and moment
     * about its centre; the body advances (translation by central
     * differences, rotation by Euler's equations, model::RigidBody) and
     * the nodes get the half-step velocity that takes them exactly to the
     * body's pose at $t_{n+1}$. Their kinetic energy and momentum are the
     * body's (counted for the part's group).
     */
    class ExplicitSolver
    {
    public:
      /**
       * Set up on a distributed DoFHandler (FESystem(FE_Q(1), 3)).
       *
       * @param contributions The force contributions (kept by reference).
       * @param bodies The rigid bodies (kept by reference).
       * @param constraints Prescribed velocities, or nullptr (kept by
       *   reference).
       * @param dof_group Element group of each locally owned node's dofs
       *   (settings.n_groups for a node shared by several groups, or none),
       *   empty: one group.
       */
      ExplicitSolver(
        const DoFHandler<3, 3> &                          dof_handler,
        const std::vector<model::ForceContribution *> &   contributions,
        std::vector<RigidBody> &                          bodies,
        const KinematicConstraints *                      constraints,
        const std::shared_ptr<const Utilities::MPI::Partitioner> &partitioner,
        const ExplicitSettings &                          settings,
        const MPI_Comm                                    comm);

      /**
       * Out of line: the owned SelectiveMassScaling is an incomplete type
       * here, so users that only include this header can destroy a solver.
       */
      ~ExplicitSolver();

      /** Set a uniform initial velocity of the solid (mm/ms). */
      void
      set_initial_velocity(const Tensor<1, 3> &velocity);

      /**
       * Set the initial velocity of the solid per dof (mm/ms; owned entries
       * are read). Before the first step only.
       */
      void
      set_initial_velocity(const VectorType &velocity);

      /**
       * Start from the displacement @p displacement (mm; owned entries are
       * read), e.g. the converged state of a quasi-static preload, instead
       * of zero. Before the first step only. The energy at the start then
       * holds the stored energy of that state (EnergyBalance::initial).
       */
      void
      set_initial_displacement(const VectorType &displacement);

      /**
       * Group of each node for the per-group kinetic energy and momentum:
       * @p group_mass[g] is the lumped physical mass of group g per dof
       * (compressed), g < settings.n_groups. A dof with mass in one group
       * only counts for it; a dof shared by several is split in proportion
       * to their masses.
       */
      void
      set_group_masses(const std::vector<VectorType> &group_mass);

      /**
       * Make the nodes of @p parts move with their bodies (before the first
       * step). Each body must have its mass, centre (reference_position),
       * inertia, free directions and initial velocity set; its weight is
       * summed here from the nodes' gravity forces. The nodes start with
       * the body's velocity.
       */
      void
      set_rigid_parts(const std::vector<RigidPartNodes> &parts);

      /**
       * Add mass to the deformation modes of some elements (selective mass
       * scaling, SelectiveMassScaling): from now on each step solves for
       * the accelerations of their nodes. Before the first step, after
       * set_rigid_parts() (no rigid part's node may be in a scaled
       * element). Collective.
       */
      void
      set_selective_mass_scaling(
        std::unique_ptr<SelectiveMassScaling> mass_scaling);

      /** The selective mass scaling, or nullptr. */
      const SelectiveMassScaling *
      selective_mass_scaling() const
      {
        return mass_scaling.get();
      }

      /**
       * Advance until @p end_time. After every step @p monitor is called
       * (it decides itself whether to write output).
       *
       * @throws SolverFailure naming the element, position, time and step.
       */
      void
      run(const double end_time, const std::function<void()> &monitor);

      /**
       * The state at the time run() stopped at, for its last history row:
       * the forces, reactions and energies at t_N are those of the step
       * that would follow, so this does that step's first half (forces,
       * the stable step, the velocities to t_{N+1/2}, the energies at t_N)
       * and calls @p monitor once, but leaves the displacements and the
       * time at t_N. Afterwards the velocities are past t_N: run() may
       * not be called again (it throws), save() is not meaningful.
       *
       * @throws SolverFailure as run() does.
       */
      void
      monitor_end_state(const std::function<void()> &monitor);

      /**
       * Time (ms), last step size (ms) and step count. Inside the monitor:
       * the time t_n of the state it sees, the step about to be taken.
       */
      double       time() const { return current_time; }
      double       time_step() const { return last_time_step; }
      unsigned int step() const { return step_number; }

      /** Displacement at the current time (ghosted). */
      const VectorType &displacement() const { return u; }
      /** Velocity at the last half step (ghosted). */
      const VectorType &velocity() const { return v; }
      /** Lumped mass with mass scaling (ghosted). */
      const VectorType &lumped_mass() const { return mass; }
      /** Energies at the current time. */
      const EnergyBalance &energies() const { return energy; }
      /** Internal energy of each element group at the current time (J). */
      const std::vector<double> &internal_energy_by_group() const
      {
        return group_internal_energy;
      }
      /** Kinetic energy and momentum of each group at the current time. */
      const std::vector<GroupMotion> &motion_by_group() const
      {
        return group_motion;
      }
      /** Bulk-viscosity and gravity work of each group (GroupWork). */
      const std::vector<GroupWork> &work_by_group() const
      {
        return group_work;
      }
      /** Energy terms of each rigid body, in the order of the bodies. */
      const std::vector<BodyEnergy> &body_energies() const
      {
        return body_energy;
      }
      /** Total added mass of mass scaling (kg). */
      double added_mass() const { return total_added_mass; }
      /** Physical mass of the solid (kg). */
      double physical_mass() const { return total_physical_mass; }
      /**
       * Reaction force (kN) of each group of the kinematic constraints on
       * the solid at the current time, summed over all ranks.
       */
      const std::vector<double> &reactions() const { return reaction; }
      /**
       * Reaction moment (kN mm) of each group about its moment point, with
       * the nodes' current positions, summed over all ranks.
       */
      const std::vector<Tensor<1, 3>> &reaction_moments() const
      {
        return reaction_moment;
      }
      /**
       * Work (J) each group of the kinematic constraints has done on the
       * solid up to the current time (its share of the external work; the
       * trapezoidal rule of the energy balance), summed over all ranks.
       */
      const std::vector<double> &reaction_works() const
      {
        return reaction_work;
      }
      /**
       * Write this rank's part of the complete model state between two
       * steps (time, step, displacements, velocities, energies, rigid
       * bodies, reactions, every contribution's state) to @p out, binary.
       * run() may be called again afterwards, or another solver of the
       * same model (same mesh, partition, laws, contact surfaces and
       * bodies) can load() it and continue: the continuation is identical
       * to the last bit (tests/explicit/restart_is_identical).
       */
      void
      save(std::ostream &out) const;

      /**
       * Read what save() wrote, on the same number of ranks.
       *
       * @throws SolverFailure naming what does not fit (ranks, sizes).
       */
      void
      load(std::istream &in);

      /**
       * The assembled step estimate (`Stable time step estimate =
       * assembled`), or nullptr (the element bound; also before the first
       * step).
       */
      const AssembledStepEstimate *
      assembled_step_estimate() const
      {
        return step_estimate.get();
      }

      /** Time spent in each part of the steps so far (s, this rank). */
      const StepTimings &timings() const { return timing; }

    private:
      /**
       * The sizes of one step: the new step dt^{n+1/2} (ms), the velocity
       * update's dt^n = (dt^{n-1/2} + dt^{n+1/2}) / 2 (ms; half the new
       * step at the start), and the weights of the old and new half-step
       * velocities in the velocity at t_n. At t_0 the velocity is the
       * initial one itself (old 1, next 0): it is known there, and the work
       * that leads to v^{1/2} is booked at t_1. The weights are powers of
       * two: 1/8 m (a + b)^2 and 1/2 m (a/2 + b/2)^2 are the same to the
       * last bit.
       */
      struct StepWeights
      {
        double new_step = 0., average_step = 0., old = 0., next = 0.;
      };

      /**
       * The first half of a step from t_n, which every step and
       * monitor_end_state() share: forces at u^n, the new stable step, the
       * velocities to t_{n+1/2} with the constraints' reactions, the sums
       * over ranks, the energies at t_n and the rigid bodies to t_{n+1/2};
       * then @p monitor. Returns the step's weights.
       */
      /**
       * Size the step's sums (StepSums) for the bodies, constraint groups,
       * element groups and shared dofs; at the start of run() and of
       * monitor_end_state() (which a restart at its end time calls alone).
       */
      void
      size_step_sums();

      StepWeights
      state_at_current_time(std::chrono::steady_clock::time_point &clock,
                            const std::function<void()>           &monitor);

      /**
       * One step's sums: this rank's terms, and the vector that collective
       * 2 sums over all ranks, laid out as: ten energy terms (kinetic,
       * internal, contact, bulk-viscosity power, gravity work, the
       * constraints' work up to t_n and ahead, friction work, the
       * contributions' external work, a spare), then per body its force
       * and moment, per constraint group its reaction, moment, work up to
       * t_n and ahead, and per element group its internal energy, kinetic
       * energy and momentum, bulk-viscosity power and gravity work.
       */
      struct StepSums
      {
        static constexpr unsigned int n_energy_sums = 10;
        unsigned int body_offset = 0, reaction_offset = 0, group_offset = 0;
        /** Collective 2's vector (summed over all ranks by sum_over_ranks()).
         */
        std::vector<double> values;
        /** Per constraint group: reaction, moment (3), work, work ahead. */
        std::vector<double> local_reaction;
        /** The shared dofs' velocities before the update. */
        std::vector<double> shared_velocity;
        /** Kinetic energy and momentum per group, one more bucket for the
         * shared dofs (split by mass afterwards). */
        std::vector<double> group_kinetic, group_momentum;
        /** This rank's kinetic energy and constraint work (and ahead). */
        double kinetic = 0., constraint_work = 0., constraint_work_next = 0.;

        /** Size for the model (zeros). */
        void
        reinit(const unsigned int n_bodies,
               const unsigned int n_constraint_groups,
               const unsigned int n_groups,
               const unsigned int n_shared_dofs);
      };

      /**
       * Before the first step: the constrained dofs' initial velocities
       * and the initial energy.
       */
      void
      start();

      /** Evaluate all contributions at u^n into f; fills `results`. */
      void
      evaluate_forces();

      /**
       * Collective 1: the new stable step, scaled (ms), from the elements'
       * and the contacts' smallest; a failed element or a step below the
       * minimum throws SolverFailure. Books the collective's time from
       * @p clock.
       */
      double
      next_time_step(std::chrono::steady_clock::time_point &clock);

      /**
       * The assembled step estimate: made (before the first step, or
       * loaded) with the free dofs known, after set_rigid_parts().
       */
      void
      make_step_estimate();

      /**
       * A new assembled estimate at u^n, if one is due: the elements'
       * internal forces at u^n + eps x by finite differences (before the
       * step's own evaluation, which overwrites what they leave).
       */
      void
      refresh_step_estimate();

      /** The solid's owned velocities to t_{n+1/2}; its kinetic energy at
       * t_n, per group too (into `sums`). */
      void
      advance_velocities(const StepWeights &w);

      /** The constrained dofs' velocities, reactions and their work (into
       * `sums`). */
      void
      apply_constraints(const StepWeights &w);

      /**
       * Selective mass scaling: the accelerations of the scaled elements'
       * nodes (their prescribed ones from the constraints), solved.
       */
      void
      solve_scaled_accelerations(const StepWeights &w);

      /** Selective mass scaling: the added mass's kinetic energy at t_n. */
      void
      add_scaled_kinetic_energy(const StepWeights &w);

      /** The kinetic energy and momentum of dofs shared by groups. */
      void
      add_shared_dofs_motion(const StepWeights &w);

      /** Collective 2: the step's sums over all ranks. */
      void
      sum_over_ranks();

      /** The energies, reactions and group sums at t_n from the sums. */
      void
      book_sums(const double new_step);

      /** The rigid bodies' velocities to t_{n+1/2}, their kinetic energy
       * and their nodes' velocities. */
      void
      advance_bodies(const StepWeights &w);

      /** Displacements and bodies to t_{n+1}, with the drives' and
       * gravity's work. */
      void
      advance_displacements(const double new_step);

      std::vector<model::ForceContribution *>            contributions;
      std::vector<RigidBody> &                           bodies;
      const KinematicConstraints *                       constraints;
      std::shared_ptr<const Utilities::MPI::Partitioner> partitioner;
      ExplicitSettings                                   settings;
      MPI_Comm                                           comm;

      VectorType u, v, f, mass, inverse_mass, gravity_force;
      /** Direction (0, 1, 2) of each locally owned dof. */
      std::vector<unsigned char> dof_component;
      /** Reference coordinate of each locally owned dof's node (mm). */
      std::vector<double> dof_coordinate;
      /**
       * For the per-group sums: per locally owned dof its group, or
       * n_groups if it is shared by several groups (then `shared_dofs`
       * splits it by mass).
       */
      std::vector<unsigned int> dof_group;
      struct SharedDof
      {
        unsigned int        dof;
        std::vector<double> mass_by_group;
      };
      std::vector<SharedDof> shared_dofs;
      /** The rigid parts' owned nodes, and a flag per owned dof. */
      std::vector<RigidPartNodes> rigid_parts;
      std::vector<bool>           rigid_dof;

      /**
       * Give the owned nodes of the rigid parts the half-step velocity
       * that takes them to their bodies' poses after a step @p step.
       */
      void
      set_rigid_node_velocities(const double step);

      double       current_time = 0., last_time_step = 0.;
      unsigned int step_number  = 0;
      EnergyBalance energy;
      std::vector<double>      group_internal_energy;
      std::vector<GroupMotion> group_motion;
      std::vector<GroupWork>   group_work;
      /** Each group's share of viscous_work_ahead (summed over all ranks). */
      std::vector<double> group_viscous_work_ahead;
      /**
       * Gravity work of the last displacement update per group on this
       * rank (one more entry for the dofs shared by several groups, split
       * by mass afterwards), booked next step like gravity_work_increment.
       */
      std::vector<double>     group_gravity_increment;
      std::vector<BodyEnergy> body_energy;
      double        total_added_mass = 0., total_physical_mass = 0.;
      bool          started = false;
      /** monitor_end_state() has run: the velocities are past the time. */
      bool end_state_monitored = false;
      /** Gravity work of the last displacement update, booked next step. */
      double                      gravity_work_increment = 0.;
      std::vector<double>         reaction;
      std::vector<Tensor<1, 3>>   reaction_moment;
      /** Work of each constraint group up to t_n, and its share ahead. */
      std::vector<double> reaction_work, reaction_work_ahead;
      /**
       * The constraints' reactions' share of their work on [t_n, t_{n+1}]
       * (summed over all ranks): it belongs to the energies at t_{n+1}.
       */
      double constraint_work_ahead = 0.;
      /**
       * The work of the bulk-viscosity forces at t_n on [t_n, t_{n+1/2}]
       * (summed over all ranks): booked with the energies at t_{n+1}.
       */
      double viscous_work_ahead = 0.;
      model::ContributionResults  results;
      StepSums                    sums;
      StepTimings                 timing;

      /** The assembled step estimate, or nullptr. */
      std::unique_ptr<AssembledStepEstimate> step_estimate;
      /**
       * Its probes: the displacement u^n + eps x (ghosted), the elements'
       * forces there and at u^n, their results, and the probe's size
       * eps max|x| (mm): 1e-8 of the model's extent.
       */
      VectorType                 probe_displacement, probe_force, base_force;
      /**
       * The estimate's first start vector: pseudo-random in the owned
       * dofs' node positions and directions (the same on any partition).
       */
      std::vector<double> estimate_start;
      model::ContributionResults probe_results;
      double                     probe_size = 0.;

      /** Selective mass scaling, or nullptr. */
      std::unique_ptr<SelectiveMassScaling> mass_scaling;
      /**
       * With selective mass scaling: the accelerations of the last step
       * (ghosted; the next solve's start), A a (owned: the added mass's
       * force on prescribed dofs, in their reactions), the velocities
       * before the update and the velocities at t_n (ghosted).
       */
      VectorType acceleration, added_inertia, velocity_before, mean_velocity;
      /**
       * Whether some prescribed dof is a node of a scaled element (on any
       * rank): only then do the reactions need added_inertia.
       */
      bool reactions_need_added_mass = false;
    };
  } // namespace time_integration
} // namespace rubberdyn

#endif
