#ifndef rubberdyn_model_force_contribution_h
#define rubberdyn_model_force_contribution_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

#include <rubberdyn/base/vector.h>
#include <rubberdyn/model/rigid_body.h>

#include <functional>
#include <iosfwd>
#include <limits>
#include <string>
#include <vector>

namespace rubberdyn
{
  namespace model
  {
    using namespace dealii;

    /** Where and why the evaluation of a contribution failed. */
    struct EvaluationFailure
    {
      /** Whether anything failed in this evaluation. */
      bool failed = false;
      /** What failed and where (cell id, position, the law's message). */
      std::string message;
    };

    /**
     * What the contributions report besides their forces in one
     * evaluation. Every contribution adds to the terms that concern it and
     * leaves the others alone; the time integrator sums them over ranks and
     * books them in the energy balance.
     */
    struct ContributionResults
    {
      /** Strain energy stored in the elements (J = kN mm). */
      double internal_energy = 0.;
      /** The same per element group (J), indexed like the element groups. */
      std::vector<double> internal_energy_by_group;
      /** Energy in penalty springs (J). */
      double contact_energy = 0.;
      /** Power of the bulk viscosity forces (kN mm/ms). */
      double bulk_viscosity_power = 0.;
      /** The same per element group (kN mm/ms), like the element groups. */
      std::vector<double> bulk_viscosity_power_by_group;
      /** Energy dissipated by friction in this evaluation (J). */
      double friction_dissipation = 0.;
      /**
       * External work of the contribution's loads on the solid that is
       * due at this evaluation's time (J): a contribution with a load books
       * its own work (e.g. by the trapezoidal rule over the last step).
       */
      double external_work = 0.;
      /** Smallest stable step of the elements (ms). */
      double element_time_step = std::numeric_limits<double>::max();
      /**
       * Smallest element step without bulk viscosity (ms), and the
       * smallest ratio of an element's step with it to the one without
       * (-): the inputs of the assembled step estimate
       * (time_integration::AssembledStepEstimate).
       */
      double element_undamped_time_step = std::numeric_limits<double>::max();
      double element_damping_factor     = 1.;
      /** Smallest stable step of the penalty springs (ms). */
      double contact_time_step = std::numeric_limits<double>::max();
      /** Force of the solid on each rigid body (kN), indexed like the bodies.
       */
      std::vector<Tensor<1, 3>> force_on_body;
      /**
       * Moment of those forces about each body's current reference point
       * (kN mm), indexed like the bodies.
       */
      std::vector<Tensor<1, 3>> moment_on_body;
      /** Set if an element inverted or another evaluation failed. */
      EvaluationFailure failure;

      /** Zero every term, with room for @p n_groups and @p n_bodies. */
      void
      reset(const unsigned int n_groups, const unsigned int n_bodies);
    };

    /**
     * What a contribution sees: the solid's displacement at t_n and
     * velocity at t_{n-1/2} (both ghosted), the lumped masses, the rigid
     * bodies and the time t_n.
     */
    struct EvaluationPoint
    {
      const VectorType &displacement;
      const VectorType &velocity;
      /** Lumped nodal masses (kg, with mass scaling; ghosted). */
      const VectorType             &mass;
      const std::vector<RigidBody> &bodies;
      double                        time;
    };

    /**
     * One source of nodal forces on the solid: the elements, contact with
     * rigid surfaces, distributed loads; later mortar pairs. The time
     * integrators loop over contributions and know no concrete class.
     *
     * A contribution writes its forces in one of two ways, which it
     * declares with accumulation(): as internal forces (the resisting
     * force $f_{int}$, sign as the elements') into owned and ghost entries,
     * which the integrator then compresses and negates, or as external
     * forces (acting on the solid) into owned entries only, added after
     * that. Elements are the first kind; node-based contact the second.
     */
    class ForceContribution
    {
    public:
      /** How add_forces() writes into the force vector. */
      enum class Accumulation
      {
        /** Resisting forces into owned and ghost entries (compressed). */
        internal_ghosted,
        /** Forces acting on the solid into owned entries only. */
        external_owned
      };

      virtual ~ForceContribution() = default;

      /** A short name for logs and error messages. */
      virtual std::string
      name() const = 0;

      /** How add_forces() writes (see the class documentation). */
      virtual Accumulation
      accumulation() const = 0;

      /**
       * Add the forces at @p point into @p f and the energies, stable
       * steps, body forces and failures into @p results. Called once per
       * time step; a contribution with a history (plasticity, friction)
       * computes the new one here and keeps it until accept_step().
       */
      virtual void
      add_forces(const EvaluationPoint &point,
                 VectorType            &f,
                 ContributionResults   &results) = 0;

      /**
       * @name Split evaluation (explicit solver)
       *
       * A contribution whose forces need data from other ranks (a mortar
       * pair: the positions of the surface nodes that others own, and the
       * forces it computes on their nodes) may split add_forces() in three,
       * so that its messages travel while the ranks compute and the ranks
       * meet once a step rather than twice per contribution (where each
       * meeting would cost the slower rank's lead). The explicit solver
       * calls start_forces() before the elements' forces, compute_forces()
       * while their sums travel, and add_forces() last, all at the same
       * @p point; add_forces() then only completes the exchange and adds.
       * The defaults do nothing, and add_forces() alone does all, as the
       * quasi-static solver calls it.
       */
      /** @{ */
      /** Start sending what the forces at @p point need from this rank. */
      virtual void
      start_forces(const EvaluationPoint &point)
      {
        (void)point;
      }

      /**
       * Compute the forces at @p point into the contribution's own storage
       * and the energies, stable steps and failures into @p results, and
       * start sending the shares of other ranks' nodes.
       */
      virtual void
      compute_forces(const EvaluationPoint &point, ContributionResults &results)
      {
        (void)point;
        (void)results;
      }
      /** @} */

      /**
       * Have the next add_forces() take the parameters that follow the
       * geometry (a contact's penalty stiffness, from the current face
       * areas) from the displacement it is given, and hold them until the
       * next call, so that add_tangents() is the exact derivative of forces
       * with those parameters fixed. The explicit solver calls it before
       * every step, the quasi-static solver at the start of a load step,
       * after its predictor and, in the run's last step, on convergence
       * (then it iterates on if the residual is no longer converged).
       * Returns whether the contribution has such parameters; the default
       * has none.
       */
      virtual bool
      follow_geometry()
      {
        return false;
      }

      /**
       * Whether the explicit solver's assembled step estimate
       * (time_integration::AssembledStepEstimate) takes this
       * contribution's stiffness by finite differences of its add_forces():
       * true for the elements, whose add_forces() may be called at a
       * probed displacement and again at the step's own (it keeps nothing
       * of an evaluation before accept_step() but what the next one
       * overwrites). Contact springs are combined with the estimate
       * instead (doc/theory.md section 8.3); the default is no.
       */
      virtual bool
      in_assembled_step_estimate() const
      {
        return false;
      }

      /** The step was taken: make the history of the last evaluation current.
       */
      virtual void
      accept_step()
      {}

      /**
       * Add this contribution's lumped masses (kg) into @p mass (with mass
       * scaling) and @p physical_mass (without), owned and ghost entries.
       */
      virtual void
      add_lumped_mass(VectorType &mass, VectorType &physical_mass) const
      {
        (void)mass;
        (void)physical_mass;
      }

      /**
       * Receives one block of a tangent (add_tangents()): the global dof
       * indices of its n dofs and the n x n derivative of the resisting
       * force with respect to their displacements, row-major (kN/mm).
       * Global, because a contact block may couple dofs that are neither
       * owned nor ghosts of the solver's partition (a master facet on a
       * third rank); such couplings must have been announced by
       * add_couplings().
       */
      using TangentBlock =
        std::function<void(const std::vector<types::global_dof_index> &dofs,
                           const std::vector<double>                  &K)>;

      /**
       * Receives a set of global dofs (add_couplings()) whose tangent blocks
       * may couple every dof of the set with every other.
       */
      using CouplingBlock =
        std::function<void(const std::vector<types::global_dof_index> &dofs)>;

      /**
       * Whether the implicit (quasi-static) solver can use this
       * contribution: its forces at @p point are those of a static state
       * (no velocity or mass enters) and add_tangents() gives their exact
       * derivative. The default is no: a contribution that has not been
       * made implicit is refused by name rather than solved with a wrong
       * tangent.
       */
      virtual bool
      supports_implicit() const
      {
        return false;
      }

      /** Whether the blocks of add_tangents() make a symmetric matrix. */
      virtual bool
      symmetric_tangent() const
      {
        return true;
      }

      /**
       * For the implicit solver: add the derivative of the forces that
       * add_forces() writes at @p point (resisting forces for
       * Accumulation::internal_ghosted: minus the load for a load) with
       * respect to the nodal displacements, block by block. Blocks are
       * written from this rank's share of the contribution (its own faces or
       * cells), like its forces. The default adds nothing: right for
       * forces that do not depend on the displacement (dead loads).
       */
      virtual void
      add_tangents(const EvaluationPoint &point, const TangentBlock &add) const
      {
        (void)point;
        (void)add;
      }

      /**
       * For the implicit solver's sparsity pattern: the couplings that
       * add_tangents() may write beyond those of the elements (which share
       * a cell) and beyond a node with itself, from this rank's share. The
       * default adds none: right for face and node blocks. The solver asks
       * again whenever couplings_version() changed.
       */
      virtual void
      add_couplings(const CouplingBlock &add) const
      {
        (void)add;
      }

      /**
       * For the implicit solver, before each assembly at @p point: make
       * add_couplings() cover every block add_tangents() writes at
       * @p point, changing couplings_version() if that needs more. Lets a
       * contribution announce only the couplings that are live (a contact
       * pair's closed nodes) rather than every one that might become so.
       * Collective. The default does nothing: right for contributions whose
       * couplings are known in advance.
       */
      virtual void
      update_couplings(const EvaluationPoint &point)
      {
        (void)point;
      }

      /**
       * A number that changes whenever the couplings of add_couplings()
       * change (a contact search found new candidates, update_couplings()
       * found new live ones). The solver compares it before each assembly
       * and rebuilds its pattern on a change.
       */
      virtual unsigned int
      couplings_version() const
      {
        return 0;
      }

      /**
       * For the implicit solver's predictor: add into @p load (owned
       * entries) the linearised change of the forces on the solid that
       * the rigid bodies' motion from their places in @p point to
       * @p moved causes at fixed nodes, $-(\partial r/\partial q)\,\Delta q$
       * (kN). Used as a moving constraint's prescribed increment is: the
       * first iteration of a load step linearises about the converged
       * state, so that a node sticking to a surface follows it. The
       * default adds nothing: right for contributions that no body moves.
       */
      virtual void
      add_body_motion_load(const EvaluationPoint        &point,
                           const std::vector<RigidBody> &moved,
                           VectorType                   &load) const
      {
        (void)point;
        (void)moved;
        (void)load;
      }

      /** Write the contribution's state (history) for a checkpoint. */
      virtual void
      save(std::ostream &out) const
      {
        (void)out;
      }

      /** Read what save() wrote. */
      virtual void
      load(std::istream &in)
      {
        (void)in;
      }
    };
  } // namespace model
} // namespace rubberdyn

#endif
