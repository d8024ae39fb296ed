#include <deal.II/base/index_set.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <rubberdyn/elements/implicit_elements.h>
#include <rubberdyn/elements/solid_hex_elements.h>
#include <rubberdyn/model/force_contribution.h>
#include <rubberdyn/time_integration/kinematic_constraints.h>
#include <rubberdyn/time_integration/quasi_static_solver.h>

#include "rigid_part_unknowns.h"

#include <Epetra_MultiVector.h>
#include <Teuchos_ParameterList.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <limits>
#include <ostream>
#include <sstream>

namespace rubberdyn
{
  namespace time_integration
  {
    namespace
    {
      std::string
      short_number(const double x, const int digits = 3)
      {
        std::ostringstream s;
        s << std::setprecision(digits) << x;
        return s.str();
      }



      /**
       * Which limit ended a run whose load step failed for @p reason: the
       * cut-backs in a row (@p count_limit, `Maximum cut-backs`) or the
       * step that cannot be halved again (@p step_limit, `Minimum step`),
       * and which entries to change, named by their full path: more Newton
       * iterations if they ran out, and the limit that was hit. "the limit
       * ...; to go on, raise ...".
       */
      std::string
      cutback_limit_advice(const std::string             &reason,
                           const bool                     count_limit,
                           const bool                     step_limit,
                           const parameters::QuasiStatic &s)
      {
        const std::string path = "Time integration/Quasi-static/";
        std::string       hit, change;
        if (count_limit)
          {
            hit = path + "Maximum cut-backs = " +
                  std::to_string(s.max_cutbacks) + " (cut-backs in a row)";
            change = "raise " + path + "Maximum cut-backs";
          }
        if (step_limit)
          {
            hit += std::string(count_limit ? " and " : "") + path +
                   "Minimum step = " + short_number(s.minimum_step) +
                   " (half the step is below it)";
            change += std::string(count_limit ? " or " : "") + "lower " +
                      path + "Minimum step";
          }
        // (A step whose Newton iterations ran out may converge with more;
        // one that inverts an element or diverges needs a smaller step.)
        if (reason.rfind("no convergence in", 0) == 0)
          change = "raise " + path + "Maximum iterations (now " +
                   std::to_string(s.max_iterations) + ") or " + change;
        return "the limit " + hit + "; to go on, " + change;
      }
    } // namespace



    /**
     * The linear algebra and the element evaluations of the solver (kept
     * out of the header: Trilinos headers are heavy).
     */
    class QuasiStaticSolver::Implementation
    {
    public:
      Implementation(
        const DoFHandler<3, 3>                                   &dof_handler,
        const std::shared_ptr<const Utilities::MPI::Partitioner> &partitioner,
        elements::ImplicitElements                               &elements,
        const KinematicConstraints                               &constraints,
        const std::vector<model::ForceContribution *>            &loads,
        const parameters::QuasiStatic                            &settings,
        const MPI_Comm                                            comm,
        const std::vector<PretensionLoad>                        &sections,
        const std::vector<model::RigidBody>                      &bodies,
        const bool                                                bodies_move,
        const std::vector<RigidPartInEquilibrium>                &rigid_parts);

      /**
       * Ask every contribution to take its geometry-dependent parameters
       * (penalty stiffness) from the next evaluation's state; whether any
       * has such parameters.
       */
      bool
      follow_geometry();

      /** Place the rigid bodies where the load path has them at @p t. */
      void
      place_bodies(const double t);

      /** Whether a rigid body moves from @p t_old to @p t_new. */
      bool
      bodies_move_between(const double t_old, const double t_new) const;

      /**
       * The rigid bodies' motion from @p t_old to @p t_new at fixed nodes,
       * linearised about @p u (model::ForceContribution::
       * add_body_motion_load()), added to the assembled right-hand side on
       * the free dofs.
       */
      void
      add_body_motion_load(const VectorType &u,
                           const double      t_old,
                           const double      t_new);

      /** What one residual evaluation gives. */
      struct Residual
      {
        /**
         * The residual f_int - f_ext: the elements' internal force minus
         * the loads (ghosted, compressed: owned entries valid).
         */
        VectorType force;
        /** Whether an element failed, and the message. */
        bool        failed = false;
        std::string failure;
        /**
         * Norms of the free and constrained (reaction) parts, and of the
         * loads on the free dofs.
         */
        double              free_norm = 0., reaction_norm = 0., load_norm = 0.;
        double              energy = 0.;
        std::vector<double> energy_by_group;
        /**
         * Force across each pretension section (kN, all ranks), and the
         * residual N_s - F_s(t) of the force-controlled ones (0 for the
         * others).
         */
        std::vector<double> section_force, section_residual;
        /**
         * The rigid parts' equations T^T r (resultants and moments) in
         * their free directions.
         */
        std::vector<double> part_residual;
      };

      /**
       * The state of the pretension sections in one load step to @p t:
       * which are force-controlled (unknown shortening) and their target
       * force, and the prescribed shortening of the others given their
       * shortenings @p shortening at the start of the step (held: locked).
       */
      void
      set_section_targets(const double               t,
                          const std::vector<double> &shortening,
                          std::vector<double>       &prescribed);

      /**
       * f_int(u, delta) - f_ext(t) and its norms, with the section
       * shortenings @p delta, the rigid parts in equilibrium at @p poses
       * (u holds their nodes already) and the rigid bodies where the load
       * path has them at @p body_time (t, or t_n in a step's predictor);
       * u must have its ghosts updated.
       */
      void
      evaluate(const VectorType                    &u,
               const std::vector<double>           &delta,
               const std::vector<model::RigidBody> &poses,
               const double                         t,
               const double                         body_time,
               Residual                            &r);

      /**
       * Assemble the tangent at @p u (the bodies at @p body_time) and the
       * right-hand side -r on the free dofs, with the prescribed increments
       * @p increment of the constrained dofs (inhomogeneous elimination) if
       * @p predictor.
       */
      void
      assemble(const VectorType                    &u,
               const double                         t,
               const double                         body_time,
               const std::vector<model::RigidBody> &poses,
               const Residual                      &r,
               const VectorType                    &increment,
               const bool                           predictor);

      // The steps of assemble(), in its order.

      /**
       * Let the loads update their couplings at @p point, and rebuild the
       * pattern if any changed them.
       */
      void
      update_pattern(const model::EvaluationPoint &point);

      /**
       * The constraints of one assembly on the coupled dofs: the
       * prescribed increments @p increment if @p predictor, else
       * homogeneous.
       */
      void
      make_step_constraints(const VectorType          &increment,
                            const bool                 predictor,
                            AffineConstraints<double> &step_constraints);

      /** The elements' tangents at @p u into the matrix (and the parts'
       * borders). */
      void
      assemble_element_tangents(
        const VectorType                &u,
        const AffineConstraints<double> &step_constraints,
        const bool                       predictor);

      /** The loads' tangents at @p point into the matrix (and the parts'
       * borders). */
      void
      assemble_load_tangents(const model::EvaluationPoint    &point,
                             const AffineConstraints<double> &step_constraints,
                             const bool                       predictor);

      /**
       * One load's tangent block @p K on @p dofs into the rigid parts'
       * borders (@p block_local: scratch for its local indices).
       */
      void
      add_load_block_to_parts(const model::ForceContribution             &load,
                              const std::vector<types::global_dof_index> &dofs,
                              const std::vector<double>                  &K,
                              std::vector<unsigned int> &block_local);

      /** -r of @p r on the free owned dofs; compress matrix and rhs. */
      void
      assemble_residual(const Residual &r);

      /** A diagonal for the constrained rows no element touches. */
      void
      fill_empty_rows();

      /** The sections' columns, rows, diagonals and right-hand sides. */
      void
      assemble_section_couplings(const VectorType &u, const Residual &r);

      /** The bordered block and the rigid parts' right-hand side. */
      void
      assemble_border(const Residual &r);

      /**
       * What the Residual tolerance multiplies (kN): the larger of the
       * norms of the reactions and of the loads of @p r, at least the
       * Residual floor (no division by zero).
       */
      double
      residual_scale(const Residual &r) const
      {
        return std::max({r.reaction_norm, r.load_norm, settings.residual_floor});
      }

      /**
       * The force criterion: the residual of @p r at most @p tolerance
       * times residual_scale(), or at most the Residual floor, or at most
       * the round-off of the residual (roundoff_floor): where the
       * reactions and loads are nearly zero (a contact gap that has just
       * closed) the relative demand falls below what the element and
       * contact forces can resolve, and no cut-back can meet it.
       */
      bool
      residual_converged(const Residual &r, const double tolerance) const
      {
        return r.free_norm <= settings.residual_floor ||
               r.free_norm <= roundoff_floor ||
               r.free_norm <= tolerance * residual_scale(r);
      }

      /** Whether the assembled tangent is symmetric (CG may solve it). */
      bool
      symmetric() const;

      /**
       * Solve the assembled (bordered) system; the correction goes to
       * @p du (owned entries, constrained dofs set to @p increment if
       * @p predictor, else zero; a rigid part's nodes get its linearised
       * motion), the sections' to @p d_delta (the prescribed ones get
       * @p delta_increment if @p predictor, else zero) and the rigid parts'
       * to @p d_part, from their @p poses. Returns the linear iterations
       * (0 for the direct solver).
       *
       * @throws QuasiStaticFailure if a rigid part in equilibrium has no
       *   stiffness in a free direction.
       */
      unsigned int
      solve(VectorType                          &du,
            std::vector<double>                 &d_delta,
            std::vector<double>                 &d_part,
            const std::vector<model::RigidBody> &poses,
            const VectorType                    &increment,
            const std::vector<double>           &delta_increment,
            const bool                           predictor);

      // The steps of solve().

      /**
       * Factorise the matrix (direct solver: returned, with
       * @p direct_control as its control) or build the AMG preconditioner
       * (amg; null returned).
       */
      std::unique_ptr<TrilinosWrappers::SolverDirect>
      factorise(SolverControl &direct_control);

      /**
       * x = K^{-1} b with the factorisation @p direct or, without one, CG
       * or GMRES with amg; the linear iterations (0 for the direct solver).
       */
      unsigned int
      linear_solve(TrilinosWrappers::SolverDirect      *direct,
                   TrilinosWrappers::MPI::Vector       &x,
                   const TrilinosWrappers::MPI::Vector &b);

      /**
       * @throws QuasiStaticFailure if a rigid part's free direction has no
       *   stiffness.
       */
      void
      check_part_stiffness() const;

      /** k_k = K g_k and k^_k = K^T g_k of bordered unknown @p k (the
       * sections, then the parts' directions). */
      const VectorType &
      bordered_column(const unsigned int k) const;
      const VectorType &
      bordered_row(const unsigned int k) const;

      /**
       * The bordered unknowns' increments: the prescribed sections'
       * (@p delta_increment if @p predictor, else zero), and the others
       * from the Schur complement of the bordered system, given the
       * correction @p a without them and b_k = K^{-1} k_k.
       *
       * @throws QuasiStaticFailure if that complement is singular.
       */
      std::vector<double>
      bordered_increments(const VectorType              &a,
                          const std::vector<VectorType> &b,
                          const std::vector<double>     &delta_increment,
                          const bool                     predictor) const;

      /**
       * |du . rhs| over the free dofs, the force-controlled sections and
       * the rigid parts' free directions (all ranks). With @p before and
       * @p after (the predictor of a step: the residuals at its start and
       * at its end, both at the step's end time) the dofs' share is
       * instead du . (r_after - r_before) over all dofs, prescribed ones
       * included: du^T K du, the energy the increment puts into the
       * model. The right-hand side's share -K_fc du_c of the prescribed
       * increments would count a rigid motion of free nodes with their
       * prescribed ones as work (a steel block moved 0.3 mm: 10^3 J in a
       * model of 0.04 J).
       */
      double
      energy_increment(const VectorType          &du,
                       const std::vector<double> &d_delta,
                       const std::vector<double> &d_part,
                       const Residual            *before = nullptr,
                       const Residual            *after  = nullptr) const;

      const DoFHandler<3, 3>                            &dof_handler;
      std::shared_ptr<const Utilities::MPI::Partitioner> partitioner;
      elements::ImplicitElements                        &elements;
      const KinematicConstraints                        &constraints;
      /** The loads (and later contact): forces and tangents beside the
       * elements'. */
      std::vector<model::ForceContribution *> loads;
      parameters::QuasiStatic                 settings;
      /**
       * The round-off of the residual (kN): below it the force criterion
       * counts as met (QuasiStaticSolver::set_roundoff_floor()).
       */
      double roundoff_floor = 0.;
      MPI_Comm                                comm;
      bool                                    use_direct;

      /**
       * (Re)build the sparsity pattern and the matrix: the elements'
       * couplings and those the loads announce (add_couplings()), on the
       * owned dofs and every dof those reach (coupled_rows).
       */
      void
      build_pattern();

      /** Whether each local (owned and ghost) dof is constrained. */
      std::vector<bool> constrained;
      IndexSet          owned, relevant;
      /**
       * The relevant dofs and those the loads' couplings reach beyond them
       * (a contact pair's master facet on a third rank), with a partitioner
       * that ghosts them all: the constraints of an assembly live there.
       */
      IndexSet                                           coupled_rows;
      std::shared_ptr<const Utilities::MPI::Partitioner> coupled_partitioner;
      /** Whether each of coupled_partitioner's local dofs is constrained,
       * or a rigid part's node. */
      std::vector<bool> coupled_constrained, coupled_part_node;
      /** The prescribed increments on coupled_partitioner (predictor). */
      VectorType coupled_increment;
      /** The loads' couplings_version() when the pattern was built. */
      std::vector<unsigned int> pattern_versions;
      TrilinosWrappers::SparseMatrix matrix;
      TrilinosWrappers::MPI::Vector  rhs, solution;
      /** Rigid-body modes of the owned dofs, [mode][local dof]. */
      std::vector<double>                                rigid_body_modes;
      std::unique_ptr<TrilinosWrappers::PreconditionAMG> amg;
      /**
       * What the contributions see besides u and t: no velocity, no mass,
       * and the rigid bodies (place_bodies()).
       */
      VectorType                    zero;
      std::vector<model::RigidBody> bodies;
      bool                          bodies_move;

      /** The pretension sections' loads. */
      std::vector<PretensionLoad> sections;
      /** In the current step: force-controlled, and the target (kN). */
      std::vector<bool>   section_unknown;
      std::vector<double> section_target;
      /**
       * From the last assemble(): k_s = K g_s, k^_s = K^T g_s (ghosted,
       * compressed), kappa_s = g_s^T K g_s, and -r_s.
       */
      std::vector<VectorType> section_column, section_row;
      std::vector<double>     section_diagonal, section_rhs;

      /** The rigid parts in equilibrium (null if there are none). */
      std::unique_ptr<RigidPartUnknowns> parts;
      /**
       * From the last assemble(): k_j = K g_j, k^_j = K^T g_j of their
       * modes (ghosted, compressed), g_j^T K g_j alone (the stiffness,
       * whose absence makes the system singular), and -T^T r.
       */
      std::vector<VectorType> part_column, part_row;
      std::vector<double>     part_stiffness, part_rhs;
      /**
       * The bordered block of all bordered unknowns (the sections, then
       * the parts' directions): g_k^T K g_l, with the parts' geometric
       * stiffness.
       */
      FullMatrix<double> border;
    };



    QuasiStaticSolver::Implementation::Implementation(
      const DoFHandler<3, 3>                                   &dof_handler,
      const std::shared_ptr<const Utilities::MPI::Partitioner> &partitioner,
      elements::ImplicitElements                               &elements,
      const KinematicConstraints                               &constraints,
      const std::vector<model::ForceContribution *>            &loads,
      const parameters::QuasiStatic                            &settings,
      const MPI_Comm                                            comm,
      const std::vector<PretensionLoad>                        &sections,
      const std::vector<model::RigidBody>                      &bodies,
      const bool                                                bodies_move,
      const std::vector<RigidPartInEquilibrium>                &rigid_parts)
      : dof_handler(dof_handler)
      , partitioner(partitioner)
      , elements(elements)
      , constraints(constraints)
      , loads(loads)
      , settings(settings)
      , comm(comm)
      , bodies(bodies)
      , bodies_move(bodies_move)
      , sections(sections)
      , section_unknown(sections.size(), false)
      , section_target(sections.size(), 0.)
      , section_column(sections.size())
      , section_row(sections.size())
      , section_diagonal(sections.size(), 0.)
      , section_rhs(sections.size(), 0.)
    {
      AssertThrow(sections.size() == elements.n_sections(),
                  ExcMessage("The quasi-static solver got " +
                             std::to_string(sections.size()) +
                             " pretension loads for " +
                             std::to_string(elements.n_sections()) +
                             " sections of the elements"));
      for (unsigned int s = 0; s < sections.size(); ++s)
        {
          section_column[s].reinit(partitioner);
          section_row[s].reinit(partitioner);
        }
      for (const model::ForceContribution *load : loads)
        AssertThrow(load->supports_implicit(),
                    ExcMessage("The quasi-static solver cannot use the "
                               "force contribution '" +
                               load->name() + "'"));
      zero.reinit(partitioner);
      using LinearSolver = parameters::QuasiStatic::LinearSolver;
      use_direct         = settings.linear_solver == LinearSolver::direct ||
                   (settings.linear_solver == LinearSolver::automatic &&
                    dof_handler.n_dofs() <= settings.direct_solver_limit);

      owned    = partitioner->locally_owned_range();
      relevant = owned;
      relevant.add_indices(partitioner->ghost_indices());

      // Constrained flags of the owned dofs, then of the ghosts (a ghost
      // dof of an owned cell is constrained by its owner's groups).
      VectorType flag(partitioner);
      for (const KinematicConstraints::Entry &entry : constraints.entries())
        flag.local_element(entry.dof) = 1.;
      flag.update_ghost_values();
      const unsigned int n_local =
        partitioner->locally_owned_size() + partitioner->n_ghost_indices();
      constrained.assign(n_local, false);
      for (unsigned int i = 0; i < n_local; ++i)
        constrained[i] = flag.local_element(i) != 0.;

      if (!rigid_parts.empty())
        {
          parts = std::make_unique<RigidPartUnknowns>(dof_handler,
                                                      partitioner,
                                                      rigid_parts,
                                                      comm);
          for (unsigned int i = 0; i < n_local; ++i)
            AssertThrow(!parts->contains(i) || constrained[i],
                        ExcMessage("A rigid part's node is not constrained"));
          part_column.resize(parts->n_unknowns());
          part_row.resize(parts->n_unknowns());
          for (unsigned int j = 0; j < parts->n_unknowns(); ++j)
            {
              part_column[j].reinit(partitioner);
              part_row[j].reinit(partitioner);
            }
        }

      build_pattern();
      rhs.reinit(owned, comm);
      solution.reinit(owned, comm);

      if (!use_direct)
        {
          // The six rigid-body modes at the owned dofs, from the nodal
          // coordinates: translations e_d and rotations e_k x (X - X_c)
          // (centred to keep them well conditioned).
          std::map<types::global_dof_index, Point<3>> points;
          DoFTools::map_dofs_to_support_points(MappingQ1<3>(),
                                               dof_handler,
                                               points);
          Point<3> centre;
          for (const auto &p : points)
            centre += p.second;
          double count = points.size();
          for (unsigned int d = 0; d < 3; ++d)
            centre[d] = Utilities::MPI::sum(centre[d], comm);
          count = Utilities::MPI::sum(count, comm);
          centre /= count;
          const unsigned int n_owned = partitioner->locally_owned_size();
          rigid_body_modes.assign(6 * n_owned, 0.);
          // Component of each owned dof.
          std::vector<unsigned int>            component(n_owned, 0);
          std::vector<types::global_dof_index> dofs(
            dof_handler.get_fe().n_dofs_per_cell());
          for (const auto &cell : dof_handler.active_cell_iterators())
            if (cell->is_locally_owned())
              {
                cell->get_dof_indices(dofs);
                for (unsigned int i = 0; i < dofs.size(); ++i)
                  if (partitioner->in_local_range(dofs[i]))
                    component[partitioner->global_to_local(dofs[i])] =
                      dof_handler.get_fe().system_to_component_index(i).first;
              }
          for (unsigned int i = 0; i < n_owned; ++i)
            {
              const types::global_dof_index global =
                partitioner->local_to_global(i);
              const auto point = points.find(global);
              Assert(point != points.end(), ExcInternalError());
              const Tensor<1, 3> x              = point->second - centre;
              const unsigned int c              = component[i];
              rigid_body_modes[c * n_owned + i] = 1.;
              // Rotation about axis k: (e_k x x)_c.
              for (unsigned int k = 0; k < 3; ++k)
                {
                  Tensor<1, 3> axis;
                  axis[k]                 = 1.;
                  const Tensor<1, 3> mode = cross_product_3d(axis, x);
                  rigid_body_modes[(3 + k) * n_owned + i] = mode[c];
                }
            }
        }
    }



    void
    QuasiStaticSolver::Implementation::build_pattern()
    {
      std::vector<std::vector<types::global_dof_index>> blocks;
      pattern_versions.clear();
      for (const model::ForceContribution *load : loads)
        {
          load->add_couplings(
            [&](const std::vector<types::global_dof_index> &dofs) {
              blocks.push_back(dofs);
            });
          pattern_versions.push_back(load->couplings_version());
        }
      IndexSet ghosts = partitioner->ghost_indices();
      {
        std::vector<types::global_dof_index> reached;
        for (const auto &dofs : blocks)
          reached.insert(reached.end(), dofs.begin(), dofs.end());
        std::sort(reached.begin(), reached.end());
        reached.erase(std::unique(reached.begin(), reached.end()),
                      reached.end());
        IndexSet beyond(dof_handler.n_dofs());
        beyond.add_indices(reached.begin(), reached.end());
        beyond.subtract_set(owned);
        ghosts.add_indices(beyond);
      }
      coupled_partitioner =
        std::make_shared<Utilities::MPI::Partitioner>(owned, ghosts, comm);
      coupled_rows = owned;
      coupled_rows.add_indices(ghosts);
      // Which of them are constrained, or a rigid part's node: from their
      // owners.
      VectorType flag(coupled_partitioner), part_flag(coupled_partitioner);
      const unsigned int n_owned = partitioner->locally_owned_size();
      for (unsigned int i = 0; i < n_owned; ++i)
        {
          flag.local_element(i)      = constrained[i] ? 1. : 0.;
          part_flag.local_element(i) = parts && parts->contains(i) ? 1. : 0.;
        }
      flag.update_ghost_values();
      part_flag.update_ghost_values();
      const unsigned int n_coupled =
        n_owned + coupled_partitioner->n_ghost_indices();
      coupled_constrained.assign(n_coupled, false);
      coupled_part_node.assign(n_coupled, false);
      AffineConstraints<double> pattern_constraints(coupled_rows);
      for (unsigned int i = 0; i < n_coupled; ++i)
        {
          coupled_part_node[i] = part_flag.local_element(i) != 0.;
          if (flag.local_element(i) != 0.)
            {
              coupled_constrained[i] = true;
              pattern_constraints.add_line(
                coupled_partitioner->local_to_global(i));
            }
        }
      pattern_constraints.close();
      coupled_increment.reinit(coupled_partitioner);

      DynamicSparsityPattern dsp(coupled_rows);
      DoFTools::make_sparsity_pattern(dof_handler,
                                      dsp,
                                      pattern_constraints,
                                      false);
      // (A constrained dof keeps its diagonal: the constraints put a
      // value there, also in a row of another rank.)
      for (const auto &dofs : blocks)
        for (const types::global_dof_index i : dofs)
          if (!pattern_constraints.is_constrained(i))
            {
              for (const types::global_dof_index j : dofs)
                if (!pattern_constraints.is_constrained(j))
                  dsp.add(i, j);
            }
          else
            dsp.add(i, i);
      SparsityTools::distribute_sparsity_pattern(dsp,
                                                 owned,
                                                 comm,
                                                 coupled_rows);
      matrix.reinit(owned, owned, dsp, comm);
    }



    bool
    QuasiStaticSolver::Implementation::follow_geometry()
    {
      bool any = false;
      for (model::ForceContribution *load : loads)
        any = load->follow_geometry() || any;
      return any;
    }



    void
    QuasiStaticSolver::Implementation::place_bodies(const double t)
    {
      for (model::RigidBody &body : bodies)
        body.displacement =
          bodies_move ? body.displacement_on_load_path(t) : Tensor<1, 3>();
    }



    bool
    QuasiStaticSolver::Implementation::bodies_move_between(
      const double t_old,
      const double t_new) const
    {
      if (!bodies_move)
        return false;
      for (const model::RigidBody &body : bodies)
        if (body.displacement_on_load_path(t_new) !=
            body.displacement_on_load_path(t_old))
          return true;
      return false;
    }



    void
    QuasiStaticSolver::Implementation::add_body_motion_load(
      const VectorType &u,
      const double      t_old,
      const double      t_new)
    {
      place_bodies(t_old);
      std::vector<model::RigidBody> moved = bodies;
      for (model::RigidBody &body : moved)
        body.displacement = body.displacement_on_load_path(t_new);
      const model::EvaluationPoint point{u, zero, zero, bodies, t_new};
      VectorType                   load(partitioner);
      for (const model::ForceContribution *contribution : loads)
        contribution->add_body_motion_load(point, moved, load);
      std::vector<types::global_dof_index> indices;
      std::vector<double>                  values;
      for (unsigned int i = 0; i < partitioner->locally_owned_size(); ++i)
        if (!constrained[i] && load.local_element(i) != 0.)
          {
            indices.push_back(partitioner->local_to_global(i));
            values.push_back(load.local_element(i));
          }
      rhs.add(indices, values);
      rhs.compress(VectorOperation::add);
    }



    void
    QuasiStaticSolver::Implementation::set_section_targets(
      const double               t,
      const std::vector<double> &shortening,
      std::vector<double>       &prescribed)
    {
      prescribed.assign(sections.size(), 0.);
      for (unsigned int s = 0; s < sections.size(); ++s)
        {
          const PretensionLoad &load = sections[s];
          const double          ramp = std::min(t / load.lock_time, 1.);
          section_unknown[s] =
            load.force_control && t <= load.lock_time * (1. + 1e-12);
          section_target[s] = section_unknown[s] ? load.target_force * ramp : 0.;
          // A locked force-controlled section keeps its shortening.
          prescribed[s] = section_unknown[s] ? 0. :
                          load.force_control ? shortening[s] :
                                               load.shortening * ramp;
        }
    }



    void
    QuasiStaticSolver::Implementation::evaluate(
      const VectorType                    &u,
      const std::vector<double>           &delta,
      const std::vector<model::RigidBody> &poses,
      const double                         t,
      const double                         body_time,
      Residual                            &r)
    {
      if (!sections.empty())
        elements.set_section_shortenings(delta);
      r.force.reinit(partitioner);
      elements::ElementStepResult result;
      elements.compute_residual(u, r.force, result);
      // The loads' resisting forces (minus the loads) apart, for their norm.
      VectorType load_resistance(partitioner), external(partitioner);
      place_bodies(body_time);
      const model::EvaluationPoint point{u, zero, zero, bodies, t};
      // (Room for the forces on the bodies, which the residual ignores.)
      model::ContributionResults unused;
      unused.reset(0, bodies.size());
      for (model::ForceContribution *load : loads)
        load->add_forces(
          point,
          load->accumulation() ==
              model::ForceContribution::Accumulation::internal_ghosted ?
            load_resistance :
            external,
          unused);
      r.force.compress(VectorOperation::add);
      load_resistance.compress(VectorOperation::add);
      load_resistance -= external;
      r.force += load_resistance;

      r.failed = Utilities::MPI::logical_or(result.failure.failed, comm);
      r.failure.clear();
      if (r.failed)
        {
          const std::string message =
            result.failure.failed ?
              "cell " + result.failure.cell_id + ", " + result.failure.message :
              "";
          for (const std::string &m : Utilities::MPI::all_gather(comm, message))
            if (!m.empty() && r.failure.empty())
              r.failure = m;
          return;
        }
      double sums[3] = {0., 0., 0.};
      for (unsigned int i = 0; i < partitioner->locally_owned_size(); ++i)
        {
          sums[constrained[i] ? 1 : 0] += std::pow(r.force.local_element(i), 2);
          if (!constrained[i])
            sums[2] += std::pow(load_resistance.local_element(i), 2);
        }
      Utilities::MPI::sum(ArrayView<const double>(sums, 3),
                          comm,
                          ArrayView<double>(sums, 3));
      // The sections: a force-controlled one's residual is free, its
      // target a load; a held one's force is a reaction.
      r.section_force = result.section_force;
      r.section_force.resize(sections.size(), 0.);
      Utilities::MPI::sum(ArrayView<const double>(r.section_force),
                          comm,
                          ArrayView<double>(r.section_force));
      r.section_residual.assign(sections.size(), 0.);
      for (unsigned int s = 0; s < sections.size(); ++s)
        if (section_unknown[s])
          {
            r.section_residual[s] = r.section_force[s] - section_target[s];
            sums[0] += std::pow(r.section_residual[s], 2);
            sums[2] += std::pow(section_target[s], 2);
          }
        else
          sums[1] += std::pow(r.section_force[s], 2);
      // The rigid parts' resultants (kN) and moments, the latter over the
      // part's size to be forces too.
      r.part_residual.clear();
      if (parts)
        {
          parts->set_linearisation_point(u, poses);
          r.part_residual = parts->project(r.force);
          for (unsigned int j = 0; j < r.part_residual.size(); ++j)
            sums[0] += std::pow(r.part_residual[j] /
                                  (parts->is_rotation(j) ?
                                     parts->length_scale(j) :
                                     1.),
                                2);
        }
      r.free_norm     = std::sqrt(sums[0]);
      r.reaction_norm = std::sqrt(sums[1]);
      r.load_norm     = std::sqrt(sums[2]);
      if (!std::isfinite(r.free_norm) || !std::isfinite(r.reaction_norm))
        {
          r.failed  = true;
          r.failure = "the residual is not finite";
          return;
        }
      r.energy_by_group = result.internal_energy_by_group;
      Utilities::MPI::sum(ArrayView<const double>(r.energy_by_group),
                          comm,
                          ArrayView<double>(r.energy_by_group));
      r.energy = Utilities::MPI::sum(result.internal_energy, comm);
    }



    bool
    QuasiStaticSolver::Implementation::symmetric() const
    {
      if (elements.has_history())
        return false;
      for (const model::ForceContribution *load : loads)
        if (!load->symmetric_tangent())
          return false;
      return true;
    }



    void
    QuasiStaticSolver::Implementation::assemble(
      const VectorType                    &u,
      const double                         t,
      const double                         body_time,
      const std::vector<model::RigidBody> &poses,
      const Residual                      &r,
      const VectorType                    &increment,
      const bool                           predictor)
    {
      place_bodies(body_time);
      const model::EvaluationPoint point{u, zero, zero, bodies, t};
      update_pattern(point);
      matrix = 0.;
      rhs    = 0.;
      // The rigid parts' borders, block by block below (before the
      // constraints remove their nodes' rows and columns).
      if (parts)
        {
          parts->set_linearisation_point(u, poses);
          parts->clear_blocks();
          for (unsigned int j = 0; j < parts->n_unknowns(); ++j)
            {
              part_column[j] = 0.;
              part_row[j]    = 0.;
            }
        }
      AffineConstraints<double> step_constraints(coupled_rows);
      make_step_constraints(increment, predictor, step_constraints);

      assemble_element_tangents(u, step_constraints, predictor);
      assemble_load_tangents(point, step_constraints, predictor);
      assemble_residual(r);
      fill_empty_rows();

      assemble_section_couplings(u, r);
      assemble_border(r);
    }



    void
    QuasiStaticSolver::Implementation::update_pattern(
      const model::EvaluationPoint &point)
    {
      // A contact search found new candidates, or a contact closed that
      // was open at every assembly before: a new pattern first.
      for (model::ForceContribution *load : loads)
        load->update_couplings(point);
      bool changed = false;
      for (unsigned int l = 0; l < loads.size(); ++l)
        changed =
          changed || loads[l]->couplings_version() != pattern_versions[l];
      if (Utilities::MPI::logical_or(changed, comm))
        build_pattern();
    }



    void
    QuasiStaticSolver::Implementation::make_step_constraints(
      const VectorType          &increment,
      const bool                 predictor,
      AffineConstraints<double> &step_constraints)
    {
      // The constraints of this assembly: the prescribed increments as
      // inhomogeneities in the predictor, none after.
      // (On every dof the loads' couplings reach: the increments from
      // their owners.)
      if (predictor)
        {
          coupled_increment.copy_locally_owned_data_from(increment);
          coupled_increment.update_ghost_values();
        }
      for (unsigned int i = 0; i < coupled_constrained.size(); ++i)
        if (coupled_constrained[i])
          {
            const types::global_dof_index global =
              coupled_partitioner->local_to_global(i);
            step_constraints.add_line(global);
            if (predictor)
              step_constraints.set_inhomogeneity(
                global, coupled_increment.local_element(i));
          }
      step_constraints.close();
    }



    void
    QuasiStaticSolver::Implementation::assemble_element_tangents(
      const VectorType                &u,
      const AffineConstraints<double> &step_constraints,
      const bool                       predictor)
    {
      const unsigned int                   n = elements.n_dofs_per_element();
      FullMatrix<double>                   cell_matrix(n, n);
      Vector<double>                       cell_rhs(n);
      std::vector<types::global_dof_index> global(n);
      elements
        .compute_tangents(u, [&](const unsigned int *dofs, const double *K) {
          for (unsigned int i = 0; i < n; ++i)
            {
              global[i] = partitioner->local_to_global(dofs[i]);
              for (unsigned int j = 0; j < n; ++j)
                cell_matrix(i, j) = K[n * i + j];
            }
          cell_rhs = 0.;
          if (parts)
            parts->add_block(dofs, n, K, part_column, part_row);
          step_constraints.distribute_local_to_global(cell_matrix,
                                                      cell_rhs,
                                                      global,
                                                      matrix,
                                                      rhs,
                                                      predictor);
        });
    }



    void
    QuasiStaticSolver::Implementation::assemble_load_tangents(
      const model::EvaluationPoint    &point,
      const AffineConstraints<double> &step_constraints,
      const bool                       predictor)
    {
      // The loads' tangents (the pressures' load stiffness, contact),
      // block by block.
      FullMatrix<double>        block_matrix;
      Vector<double>            block_rhs;
      std::vector<unsigned int> block_local;
      for (const model::ForceContribution *load : loads)
        load->add_tangents(
          point,
          [&](const std::vector<types::global_dof_index> &dofs,
              const std::vector<double>                  &K) {
            const unsigned int n = dofs.size();
            block_matrix.reinit(n, n);
            block_rhs.reinit(n);
            for (unsigned int i = 0; i < n; ++i)
              for (unsigned int j = 0; j < n; ++j)
                block_matrix(i, j) = K[n * i + j];
            if (parts)
              add_load_block_to_parts(*load, dofs, K, block_local);
            step_constraints.distribute_local_to_global(block_matrix,
                                                        block_rhs,
                                                        dofs,
                                                        matrix,
                                                        rhs,
                                                        predictor);
          });
    }



    void
    QuasiStaticSolver::Implementation::add_load_block_to_parts(
      const model::ForceContribution             &load,
      const std::vector<types::global_dof_index> &dofs,
      const std::vector<double>                  &K,
      std::vector<unsigned int>                  &block_local)
    {
      // The parts' borders need the block on this rank's vectors: a block
      // that reaches beyond them may not touch a part.
      const unsigned int n      = dofs.size();
      bool               beyond = false, touches_part = false;
      block_local.resize(n);
      for (unsigned int i = 0; i < n; ++i)
        {
          AssertThrow(coupled_rows.is_element(dofs[i]),
                      ExcMessage("The tangent of '" + load.name() +
                                 "' reaches a dof it did not "
                                 "announce in add_couplings()"));
          touches_part =
            touches_part ||
            coupled_part_node[coupled_partitioner->global_to_local(dofs[i])];
          if (relevant.is_element(dofs[i]))
            block_local[i] = partitioner->global_to_local(dofs[i]);
          else
            beyond = true;
        }
      AssertThrow(!(beyond && touches_part),
                  ExcMessage("The tangent of '" + load.name() +
                             "' couples a rigid part's node with a node "
                             "of a third rank: the quasi-static solver's "
                             "rigid parts cannot border that block yet "
                             "(run on one rank)"));
      if (!beyond)
        parts->add_block(block_local.data(),
                         n,
                         K.data(),
                         part_column,
                         part_row);
    }



    void
    QuasiStaticSolver::Implementation::assemble_residual(const Residual &r)
    {
      // -r on the free owned dofs (the residual is already summed). The
      // constrained rows keep what distribute_local_to_global() put there
      // (their solution is overwritten in solve(), and their columns are
      // eliminated).
      std::vector<types::global_dof_index> indices;
      std::vector<double>                  values;
      for (unsigned int i = 0; i < partitioner->locally_owned_size(); ++i)
        if (!constrained[i])
          {
            indices.push_back(partitioner->local_to_global(i));
            values.push_back(-r.force.local_element(i));
          }
      rhs.add(indices, values);
      matrix.compress(VectorOperation::add);
      rhs.compress(VectorOperation::add);
    }



    void
    QuasiStaticSolver::Implementation::fill_empty_rows()
    {
      // A constrained dof that no element touches (a held rigid part's
      // nodes: its cells have no elements) has an empty row; give it a
      // diagonal of the matrix's mean scale (its solution is overwritten).
      // (Models without such rows skip the scale and the second compress.)
      const unsigned int n_owned = partitioner->locally_owned_size();
      std::vector<types::global_dof_index> empty_rows;
      for (unsigned int i = 0; i < n_owned; ++i)
        if (constrained[i] &&
            matrix.diag_element(partitioner->local_to_global(i)) == 0.)
          empty_rows.push_back(partitioner->local_to_global(i));
      if (Utilities::MPI::logical_or(!empty_rows.empty(), comm))
        {
          double sum = 0., count = 0.;
          for (unsigned int i = 0; i < n_owned; ++i)
            if (!constrained[i])
              {
                sum += std::abs(
                  matrix.diag_element(partitioner->local_to_global(i)));
                count += 1.;
              }
          sum                = Utilities::MPI::sum(sum, comm);
          count              = Utilities::MPI::sum(count, comm);
          const double scale = count > 0. && sum > 0. ? sum / count : 1.;
          for (const types::global_dof_index row : empty_rows)
            matrix.set(row, row, scale);
          // (Collective: every rank, whether it set anything.)
          matrix.compress(VectorOperation::insert);
        }
    }



    void
    QuasiStaticSolver::Implementation::assemble_section_couplings(
      const VectorType &u,
      const Residual   &r)
    {
      // The sections' border: k_s = K g_s, k^_s = K^T g_s, kappa_s.
      if (sections.empty())
        return;
      const unsigned int n = elements.n_dofs_per_element();
      for (unsigned int s = 0; s < sections.size(); ++s)
        {
          section_column[s]   = 0.;
          section_row[s]      = 0.;
          section_diagonal[s] = 0.;
          section_rhs[s]      = -r.section_residual[s];
        }
      elements.compute_section_couplings(
        u,
        [&](const unsigned int *dofs,
            const unsigned int  s,
            const double       *K_g,
            const double       *KT_g,
            const double        gKg) {
          for (unsigned int i = 0; i < n; ++i)
            {
              section_column[s].local_element(dofs[i]) += K_g[i];
              section_row[s].local_element(dofs[i]) += KT_g[i];
            }
          section_diagonal[s] += gKg;
        });
      for (unsigned int s = 0; s < sections.size(); ++s)
        {
          section_column[s].compress(VectorOperation::add);
          section_row[s].compress(VectorOperation::add);
        }
      Utilities::MPI::sum(ArrayView<const double>(section_diagonal),
                          comm,
                          ArrayView<double>(section_diagonal));
    }



    void
    QuasiStaticSolver::Implementation::assemble_border(const Residual &r)
    {
      // The bordered block: the sections' diagonal, the parts' g^T K g
      // with their geometric stiffness, and the couplings between the two.
      const unsigned int n_sections = sections.size();
      const unsigned int n_parts    = parts ? parts->n_unknowns() : 0;
      border.reinit(n_sections + n_parts, n_sections + n_parts);
      for (unsigned int s = 0; s < n_sections; ++s)
        border(s, s) = section_diagonal[s];
      if (!parts)
        return;
      for (unsigned int j = 0; j < n_parts; ++j)
        {
          part_column[j].compress(VectorOperation::add);
          part_row[j].compress(VectorOperation::add);
          // Column j of g_k^T K g_j: the modes' components of K g_j.
          const std::vector<double> column = parts->project(part_column[j]);
          for (unsigned int k = 0; k < n_parts; ++k)
            border(n_sections + k, n_sections + j) = column[k];
        }
      part_stiffness.resize(n_parts);
      for (unsigned int j = 0; j < n_parts; ++j)
        part_stiffness[j] = border(n_sections + j, n_sections + j);
      FullMatrix<double> geometric(n_parts, n_parts);
      parts->add_geometric_stiffness(r.force, geometric);
      for (unsigned int k = 0; k < n_parts; ++k)
        for (unsigned int j = 0; j < n_parts; ++j)
          border(n_sections + k, n_sections + j) += geometric(k, j);
      for (unsigned int s = 0; s < n_sections; ++s)
        {
          // g_j^T K g_s = g_j . k_s and g_s^T K g_j = g_j . k^_s.
          const std::vector<double> by_column =
            parts->project(section_column[s]);
          const std::vector<double> by_row = parts->project(section_row[s]);
          for (unsigned int j = 0; j < n_parts; ++j)
            {
              border(n_sections + j, s) = by_column[j];
              border(s, n_sections + j) = by_row[j];
            }
        }
      part_rhs = r.part_residual;
      for (double &value : part_rhs)
        value = -value;
    }



    unsigned int
    QuasiStaticSolver::Implementation::solve(
      VectorType                          &du,
      std::vector<double>                 &d_delta,
      std::vector<double>                 &d_part,
      const std::vector<model::RigidBody> &poses,
      const VectorType                    &increment,
      const std::vector<double>           &delta_increment,
      const bool                           predictor)
    {
      // One factorisation (or preconditioner) of K for every right-hand
      // side: -r, then each section's k_s.
      SolverControl direct_control(1, 0.);
      const std::unique_ptr<TrilinosWrappers::SolverDirect> direct =
        factorise(direct_control);
      unsigned int       n_iter  = linear_solve(direct.get(), solution, rhs);
      const unsigned int n_owned = partitioner->locally_owned_size();
      // a: the correction without the sections' (prescribed increments on
      // the constrained dofs).
      for (unsigned int i = 0; i < n_owned; ++i)
        du.local_element(i) = constrained[i] ?
                                (predictor ? increment.local_element(i) : 0.) :
                                solution[partitioner->local_to_global(i)];
      // The bordered unknowns: the sections' shortenings, then the rigid
      // parts' free directions, each with its column k_m = K g_m, its row
      // k^_m = K^T g_m and its right-hand side.
      const unsigned int n_sections = sections.size();
      const unsigned int n_parts    = parts ? parts->n_unknowns() : 0;
      const unsigned int m          = n_sections + n_parts;
      d_delta.assign(n_sections, 0.);
      d_part.assign(n_parts, 0.);
      if (m == 0)
        return n_iter;
      check_part_stiffness();

      // x = K^{-1} (factor v) on the free dofs, for a v on all local dofs.
      TrilinosWrappers::MPI::Vector column(rhs), b_k(rhs);
      const auto solve_free = [&](const VectorType &v, const double factor) {
        std::vector<types::global_dof_index> indices;
        std::vector<double>                  values;
        column = 0.;
        for (unsigned int i = 0; i < n_owned; ++i)
          if (!constrained[i])
            {
              indices.push_back(partitioner->local_to_global(i));
              values.push_back(factor * v.local_element(i));
            }
        column.set(indices, values);
        column.compress(VectorOperation::insert);
        return linear_solve(direct.get(), b_k, column);
      };
      // b_k = K^{-1} k_k on the free dofs (zero on the constrained ones).
      std::vector<VectorType> b(m);
      for (unsigned int k = 0; k < m; ++k)
        {
          n_iter += solve_free(bordered_column(k), 1.);
          b[k].reinit(partitioner);
          for (unsigned int i = 0; i < n_owned; ++i)
            b[k].local_element(i) =
              constrained[i] ? 0. : b_k[partitioner->local_to_global(i)];
        }
      const std::vector<double> dd =
        bordered_increments(du, b, delta_increment, predictor);
      for (unsigned int k = 0; k < m; ++k)
        if (dd[k] != 0.)
          du.add(-dd[k], b[k]);
      for (unsigned int s = 0; s < n_sections; ++s)
        d_delta[s] = dd[s];
      for (unsigned int j = 0; j < n_parts; ++j)
        d_part[j] = dd[n_sections + j];
      // The parts' nodes go exactly where the turned parts have them, not
      // to the linearised T dq: the free dofs follow that curvature too
      // (a further solve with the same factorisation; a nearly
      // incompressible layer bonded to a turning part would otherwise see
      // it as a volumetric strain).
      bool turns = false;
      for (unsigned int j = 0; j < n_parts; ++j)
        turns = turns || (parts->is_rotation(j) && d_part[j] != 0.);
      if (turns)
        {
          VectorType force(partitioner);
          parts->add_curvature_force(poses, d_part, force);
          force.compress(VectorOperation::add);
          n_iter += solve_free(force, -1.);
          for (unsigned int i = 0; i < n_owned; ++i)
            if (!constrained[i])
              du.local_element(i) += b_k[partitioner->local_to_global(i)];
        }
      if (parts)
        parts->add_linear_motion(d_part, du);
      return n_iter;
    }



    std::unique_ptr<TrilinosWrappers::SolverDirect>
    QuasiStaticSolver::Implementation::factorise(SolverControl &direct_control)
    {
      if (use_direct)
        {
          TrilinosWrappers::SolverDirect::AdditionalData data(
            false,
            settings.direct_solver);
          auto direct =
            std::make_unique<TrilinosWrappers::SolverDirect>(direct_control,
                                                             data);
          direct->initialize(matrix);
          return direct;
        }
      // ML with the six rigid-body modes as its near-null space: the
      // AdditionalData's list, then the modes by hand (deal.II 9.4's
      // constant_modes carry translations only).
      TrilinosWrappers::PreconditionAMG::AdditionalData data;
      data.elliptic              = true;
      data.higher_order_elements = false;
      data.smoother_sweeps       = 2;
      data.aggregation_threshold = 1e-4;
      Teuchos::ParameterList              list;
      std::unique_ptr<Epetra_MultiVector> unused_modes;
      data.set_parameters(list, unused_modes, matrix);
      list.set("null space: type", "pre-computed");
      list.set("null space: dimension", 6);
      list.set("null space: vectors", rigid_body_modes.data());
      // Aggregate nodes, not single dofs: the three displacement dofs of
      // a node are consecutive (deal.II's numbering of FESystem, never
      // renumbered here), and the six modes couple them. deal.II's list
      // leaves ML's default of one equation per node; with three, the
      // bonded tube (tube_16, K/G = 1250) takes 19 316 CG iterations
      // instead of 34 492, and half the time.
      list.set("PDE equations", 3);
      amg = std::make_unique<TrilinosWrappers::PreconditionAMG>();
      amg->initialize(matrix.trilinos_matrix(), list);
      return nullptr;
    }



    unsigned int
    QuasiStaticSolver::Implementation::linear_solve(
      TrilinosWrappers::SolverDirect      *direct,
      TrilinosWrappers::MPI::Vector       &x,
      const TrilinosWrappers::MPI::Vector &b)
    {
      x = 0.;
      if (use_direct)
        {
          direct->solve(x, b);
          return 0u;
        }
      if (b.l2_norm() == 0.)
        return 0u;
      SolverControl control(10000, settings.linear_tolerance * b.l2_norm());
      // CG where the tangent is symmetric (hyperelastic laws: the
      // element force is an energy gradient), GMRES otherwise, and
      // GMRES also when CG breaks down: away from equilibrium (a large
      // predictor, buckling) the symmetric tangent can be indefinite.
      const auto gmres = [&]() {
        x = 0.;
        TrilinosWrappers::SolverGMRES::AdditionalData gmres_data(false, 200);
        TrilinosWrappers::SolverGMRES solver(control, gmres_data);
        solver.solve(matrix, x, b, *amg);
        return control.last_step();
      };
      if (!symmetric())
        return gmres();
      try
        {
          TrilinosWrappers::SolverCG cg(control);
          cg.solve(matrix, x, b, *amg);
          return control.last_step();
        }
      catch (const std::exception &)
        {
          const unsigned int cg_iterations = control.last_step();
          return cg_iterations + gmres();
        }
    }



    void
    QuasiStaticSolver::Implementation::check_part_stiffness() const
    {
      // A part's direction that nothing stiffens cannot be solved: say
      // which, instead of a singular system's noise.
      const unsigned int n_parts = parts ? parts->n_unknowns() : 0;
      for (unsigned int j = 0; j < n_parts; ++j)
        if (!(part_stiffness[j] > 0.))
          throw QuasiStaticFailure(
            parts->describe(j) +
            " is an unknown of the equilibrium, but no element and no "
            "contact holds it there (g^T K g = " +
            short_number(part_stiffness[j]) +
            "); hold that direction (Rigid motion) or let the part stand "
            "still (Quasi-static motion = held)");
    }



    const VectorType &
    QuasiStaticSolver::Implementation::bordered_column(
      const unsigned int k) const
    {
      const unsigned int n_sections = sections.size();
      return k < n_sections ? section_column[k] : part_column[k - n_sections];
    }



    const VectorType &
    QuasiStaticSolver::Implementation::bordered_row(const unsigned int k) const
    {
      const unsigned int n_sections = sections.size();
      return k < n_sections ? section_row[k] : part_row[k - n_sections];
    }



    std::vector<double>
    QuasiStaticSolver::Implementation::bordered_increments(
      const VectorType              &a,
      const std::vector<VectorType> &b,
      const std::vector<double>     &delta_increment,
      const bool                     predictor) const
    {
      const unsigned int n_owned    = partitioner->locally_owned_size();
      const unsigned int n_sections = sections.size();
      const unsigned int m          = b.size();
      // The prescribed shortening increments; then the unknowns (the
      // force-controlled sections, the parts) from
      // k^_k . (a - sum_l b_l dd_l) + sum_l D_kl dd_l = rhs_k.
      std::vector<double>       dd(m, 0.);
      std::vector<unsigned int> unknown;
      for (unsigned int k = 0; k < m; ++k)
        if (k >= n_sections || section_unknown[k])
          unknown.push_back(k);
        else
          dd[k] = predictor ? delta_increment[k] : 0.;
      if (unknown.empty())
        return dd;
      const auto dot = [&](const VectorType &x, const VectorType &y) {
        double sum = 0.;
        for (unsigned int i = 0; i < n_owned; ++i)
          sum += x.local_element(i) * y.local_element(i);
        return Utilities::MPI::sum(sum, comm);
      };
      const unsigned int n_unknown = unknown.size();
      FullMatrix<double> schur(n_unknown, n_unknown);
      Vector<double>     right(n_unknown), solved(n_unknown);
      for (unsigned int i = 0; i < n_unknown; ++i)
        {
          const unsigned int k = unknown[i];
          right(i) =
            (k < n_sections ? section_rhs[k] : part_rhs[k - n_sections]) -
            dot(bordered_row(k), a);
          for (unsigned int l = 0; l < m; ++l)
            {
              const double entry = border(k, l) - dot(bordered_row(k), b[l]);
              const auto   found = std::find(unknown.begin(), unknown.end(), l);
              if (found != unknown.end())
                schur(i, found - unknown.begin()) = entry;
              else
                right(i) -= entry * dd[l];
            }
        }
      schur.gauss_jordan();
      schur.vmult(solved, right);
      for (unsigned int i = 0; i < n_unknown; ++i)
        {
          if (!std::isfinite(solved(i)))
            throw QuasiStaticFailure(
              "the bordered equations of the pretension sections and "
              "rigid parts are singular");
          dd[unknown[i]] = solved(i);
        }
      return dd;
    }



    double
    QuasiStaticSolver::Implementation::energy_increment(
      const VectorType          &du,
      const std::vector<double> &d_delta,
      const std::vector<double> &d_part,
      const Residual            *before,
      const Residual            *after) const
    {
      // The right-hand side the free dofs saw (the predictor: the change
      // of the residual over all dofs), with the prescribed shortening
      // increments' share -k_t dd_t (the load of a predictor whose only
      // driver is a section: without it the first energy is 0).
      double sum = 0.;
      for (unsigned int i = 0; i < partitioner->locally_owned_size(); ++i)
        if (before != nullptr || !constrained[i])
          {
            double right =
              before != nullptr ?
                after->force.local_element(i) - before->force.local_element(i) :
                rhs[partitioner->local_to_global(i)];
            if (!constrained[i])
              for (unsigned int t = 0; t < sections.size(); ++t)
                if (!section_unknown[t])
                  right -= section_column[t].local_element(i) * d_delta[t];
            sum += du.local_element(i) * right;
          }
      sum = Utilities::MPI::sum(sum, comm);
      for (unsigned int s = 0; s < sections.size(); ++s)
        if (section_unknown[s])
          sum += d_delta[s] * section_rhs[s];
      for (unsigned int j = 0; j < d_part.size(); ++j)
        sum += d_part[j] * part_rhs[j];
      return std::abs(sum);
    }



    QuasiStaticSolver::QuasiStaticSolver(
      const DoFHandler<3, 3>                                   &dof_handler,
      const std::shared_ptr<const Utilities::MPI::Partitioner> &partitioner,
      elements::ImplicitElements                               &elements,
      const KinematicConstraints                               &constraints,
      const std::vector<model::ForceContribution *>            &loads,
      const parameters::QuasiStatic                            &settings,
      const MPI_Comm                                            comm,
      const std::vector<PretensionLoad>                        &sections,
      const std::vector<model::RigidBody>                      &bodies,
      const bool                                                bodies_move,
      const std::vector<RigidPartInEquilibrium>                &rigid_parts)
      : impl(std::make_unique<Implementation>(dof_handler,
                                              partitioner,
                                              elements,
                                              constraints,
                                              loads,
                                              settings,
                                              comm,
                                              sections,
                                              bodies,
                                              bodies_move,
                                              rigid_parts))
      , section_force(sections.size(), 0.)
      , shortening(sections.size(), 0.)
    {
      u.reinit(partitioner);
      if (impl->parts)
        part_poses = impl->parts->reference_poses();
    }



    QuasiStaticSolver::~QuasiStaticSolver() = default;



    std::string
    QuasiStaticSolver::linear_solver_name() const
    {
      return impl->use_direct ?
               "direct (" + impl->settings.direct_solver + ")" :
               std::string(impl->symmetric() ? "CG" : "GMRES") +
                 " with ML AMG (6 rigid-body modes)";
    }



    void
    QuasiStaticSolver::set_roundoff_floor(const double roundoff_floor)
    {
      AssertThrow(roundoff_floor >= 0. && std::isfinite(roundoff_floor),
                  ExcMessage("the round-off floor must be finite and >= 0"));
      impl->roundoff_floor = roundoff_floor;
    }



    double
    QuasiStaticSolver::roundoff_floor() const
    {
      return impl->roundoff_floor;
    }



    const std::vector<model::RigidBody> &
    QuasiStaticSolver::bodies() const
    {
      return impl->bodies;
    }



    void
    QuasiStaticSolver::initialize()
    {
      impl->follow_geometry();
      evaluate_state();
      for (model::ForceContribution *load : impl->loads)
        load->accept_step();
    }



    void
    QuasiStaticSolver::evaluate_state()
    {
      u.update_ghost_values();
      Implementation::Residual r;
      std::vector<double>      unused;
      impl->set_section_targets(current_time, shortening, unused);
      impl->evaluate(
        u, shortening, part_poses, current_time, current_time, r);
      if (r.failed)
        throw QuasiStaticFailure(
          "the state at t = " + short_number(current_time, 6) +
          " fails: " + r.failure);
      // Reactions and energies of the state.
      const KinematicConstraints &c = impl->constraints;
      reaction.assign(c.n_groups(), 0.);
      reaction_moment.assign(c.n_groups(), Tensor<1, 3>());
      for (const KinematicConstraints::Entry &entry : c.entries())
        {
          const double f = r.force.local_element(entry.dof);
          reaction[entry.group] += f;
          Point<3> x = entry.X;
          for (unsigned int d = 0; d < 3; ++d)
            x[d] += u.local_element(entry.node_dofs[d]);
          Tensor<1, 3> force;
          // The constrained component of this entry.
          for (unsigned int d = 0; d < 3; ++d)
            if (entry.node_dofs[d] == entry.dof)
              force[d] = f;
          reaction_moment[entry.group] +=
            cross_product_3d(x - c.moment_point(entry.group), force);
        }
      Utilities::MPI::sum(ArrayView<const double>(reaction),
                          impl->comm,
                          ArrayView<double>(reaction));
      for (Tensor<1, 3> &m : reaction_moment)
        for (unsigned int d = 0; d < 3; ++d)
          m[d] = Utilities::MPI::sum(m[d], impl->comm);
      energy          = r.energy;
      energy_by_group = r.energy_by_group;
      section_force   = r.section_force;
    }



    /**
     * One load step of QuasiStaticSolver::run(), from the last converged
     * state to the step's end: the Newton iterations, each a correction
     * (assembly and solve) and a backtracking line search, the
     * convergence test with the last state's penalty update, and the way
     * back to the step's start for a cut-back. It holds run()'s work
     * vectors, allocated once per run.
     */
    class QuasiStaticSolver::LoadStep
    {
    public:
      LoadStep(QuasiStaticSolver &solver, std::ostream &log)
        : solver(solver)
        , I(*solver.impl)
        , settings(I.settings)
        , root(Utilities::MPI::this_mpi_process(I.comm) == 0)
        , log(log)
        , u_start(solver.u)
        , u_trial(solver.u)
        , du(solver.u)
        , increment(solver.u)
        , wall_start(std::chrono::steady_clock::now())
      {}

      /**
       * Start the step to @p t_new, the run's last if @p last_step: the
       * prescribed increments of the constrained dofs and sections, the
       * step's start kept for a cut-back, the penalty of the start's
       * geometry and the residual there.
       */
      void
      begin(const double t_new, const bool last_step);

      /**
       * The Newton iterations of the step begun last: whether they
       * converged, and if not why in @p reason.
       */
      bool
      iterate(std::string &reason);

      /** Back to the step's start (a cut-back). */
      void
      restore_start();

      /** The iterations of the last iterate(), with the one that stopped
       * it; the linear solver's iterations in them. */
      unsigned int iterations = 0, linear_iterations = 0;

    private:
      /**
       * The correction of one iteration (the predictor's first) into du,
       * d_delta and d_part: assembly and solve. Returns false, with the
       * linear solver's message in @p reason, if that failed.
       */
      bool
      solve_correction(const bool    predictor,
                       unsigned int &n_linear,
                       std::string  &reason);

      /**
       * Backtracking line search: halve the correction while an element
       * fails or the residual norm does not decrease (Armijo, factor 1e-4).
       * The predictor's prescribed part is always taken whole (it is the
       * load), and the predictor itself is only checked for failures: its
       * starting residual is the last step's equilibrium. Leaves the
       * accepted candidate in u_trial, delta_trial, poses_trial and
       * r_trial, its step length in @p alpha; false if none was.
       */
      bool
      line_search(const bool predictor, double &alpha);

      /** Make the line search's candidate the iterate. */
      void
      take_trial();

      /**
       * The run's last state (an explicit run may start from it),
       * converged with the penalty held: take the penalty of this state,
       * and whether that changed nothing of note: the residual with it as
       * small as before (within 10 times, or 1e-3 of the tolerance, of the
       * converged @p ratio), so that the state is an equilibrium with its
       * own penalty as closely as Newton converges (the explicit run that
       * starts from it sees no jolt). From the third update on, Newton's
       * tolerance is enough: the penalty's own round-off can hold the
       * residual there (8e-11 of the reactions with the stiff rigid
       * cylinder of benchmarks/ironing.sh's longer slab, which was cut
       * back three times for it).
       */
      bool
      penalty_of_last_state_holds(const double ratio);

      /** Seconds since the run started (the log). */
      double
      wall() const
      {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                             wall_start)
          .count();
      }

      QuasiStaticSolver             &solver;
      Implementation                &I;
      const parameters::QuasiStatic &settings;
      const bool                     root;
      std::ostream                  &log;

      /** The step's end time, whether it is the run's last, whether the
       * contributions follow the geometry and the bodies move in it. */
      double t_new            = 0.;
      bool   last_step        = false;
      bool   follows_geometry = false;
      bool   surfaces_move    = false;
      /** Penalty updates of the last state in this step. */
      unsigned int penalty_updates = 0;

      /** The last converged state (for a cut-back), the line search's
       * candidate, the correction, the prescribed increments. */
      VectorType               u_start, u_trial, du, increment;
      Implementation::Residual r, r_trial;
      /** The same for the sections' shortenings. */
      std::vector<double> delta_start, delta_trial, d_delta, delta_increment,
        prescribed;
      /** And for the rigid parts in equilibrium: poses and increments. */
      std::vector<model::RigidBody> poses_start, poses_trial;
      std::vector<double>           d_part;

      const std::chrono::steady_clock::time_point wall_start;
    };



    void
    QuasiStaticSolver::LoadStep::begin(const double t_new_,
                                       const bool   last_step_)
    {
      t_new                         = t_new_;
      last_step                     = last_step_;
      VectorType                 &u = solver.u;
      const KinematicConstraints &c = I.constraints;
      // The prescribed increments: a displacement group's g(t_new) - u_n,
      // zero for the velocity groups (fixed, symmetry).
      increment = 0.;
      for (const KinematicConstraints::Entry &entry : c.entries())
        if (c.kind(entry.group) == KinematicConstraints::Kind::displacement)
          increment.local_element(entry.dof) =
            c.prescribed_function_value(entry, t_new) -
            u.local_element(entry.dof);

      // (The ghosts too: a ghost dof's inhomogeneity enters this rank's
      // element matrices in assemble().)
      increment.update_ghost_values();
      u_start = u;
      u.update_ghost_values();
      // The sections: targets at t_new, prescribed increments.
      std::vector<double> &shortening = solver.shortening;
      delta_start                     = shortening;
      poses_start                     = solver.part_poses;
      I.set_section_targets(t_new, shortening, prescribed);
      delta_increment.assign(shortening.size(), 0.);
      for (unsigned int k = 0; k < shortening.size(); ++k)
        if (!I.section_unknown[k])
          delta_increment[k] = prescribed[k] - shortening[k];
      // The penalty stiffness of the converged state (again after a
      // cut-back); then of the predictor's state, held during the
      // iterations; in the last step also of the converged state.
      follows_geometry = I.follow_geometry();
      I.evaluate(u, shortening, solver.part_poses, t_new, t_new, r);
      surfaces_move = I.bodies_move_between(solver.current_time, t_new);
    }



    bool
    QuasiStaticSolver::LoadStep::solve_correction(const bool    predictor,
                                                  unsigned int &n_linear,
                                                  std::string  &reason)
    {
      const VectorType                    &u     = solver.u;
      const std::vector<model::RigidBody> &poses = solver.part_poses;
      try
        {
          if (predictor && surfaces_move)
            {
              // Linearised about the converged state, with the surfaces'
              // motion as a load: a node sticking to a surface follows it,
              // as a node on a moving constraint does (the residual at the
              // surfaces' new places would have it slip at once).
              Implementation::Residual r_start;
              I.evaluate(u,
                         solver.shortening,
                         poses,
                         t_new,
                         solver.current_time,
                         r_start);
              I.assemble(u,
                         t_new,
                         solver.current_time,
                         poses,
                         r_start,
                         increment,
                         predictor);
              I.add_body_motion_load(u, solver.current_time, t_new);
            }
          else
            I.assemble(u, t_new, t_new, poses, r, increment, predictor);
          n_linear = I.solve(du,
                             d_delta,
                             d_part,
                             poses,
                             increment,
                             delta_increment,
                             predictor);
        }
      catch (const QuasiStaticFailure &)
        {
          // (A singular rigid part: no cut-back can help.)
          throw;
        }
      catch (const std::exception &e)
        {
          // (deal.II's NoConvergence has an empty what().)
          const std::string what = e.what();
          reason                 = "the linear solver failed" +
                   (what.empty() ? std::string(" to converge") : ": " + what);
          return false;
        }
      return true;
    }



    bool
    QuasiStaticSolver::LoadStep::line_search(const bool predictor,
                                             double    &alpha)
    {
      const VectorType          &u          = solver.u;
      const std::vector<double> &shortening = solver.shortening;
      alpha                                 = 1.;
      for (unsigned int trial = 0; trial < 7; ++trial)
        {
          for (unsigned int i = 0; i < I.partitioner->locally_owned_size(); ++i)
            u_trial.local_element(i) =
              u.local_element(i) +
              (I.constrained[i] ? 1. : alpha) * du.local_element(i);
          // The rigid parts turn by the finite rotation, and their nodes
          // are placed on them exactly.
          poses_trial = solver.part_poses;
          if (I.parts)
            {
              I.parts->advance(poses_trial, d_part, alpha);
              I.parts->place_nodes(poses_trial, u_trial);
            }
          u_trial.update_ghost_values();
          // The predictor takes most of the step's motion: the penalty of
          // its geometry is close to the converged one's, and is held from
          // there on.
          if (predictor && follows_geometry)
            I.follow_geometry();
          delta_trial = shortening;
          for (unsigned int k = 0; k < shortening.size(); ++k)
            delta_trial[k] += (I.section_unknown[k] ? alpha : 1.) * d_delta[k];
          I.evaluate(u_trial, delta_trial, poses_trial, t_new, t_new, r_trial);
          if (!r_trial.failed &&
              (predictor || !settings.line_search || trial == 6 ||
               r_trial.free_norm <= (1. - 1e-4 * alpha) * r.free_norm))
            return true;
          if (!settings.line_search)
            return false;
          alpha *= 0.5;
        }
      return false;
    }



    void
    QuasiStaticSolver::LoadStep::take_trial()
    {
      solver.u.swap(u_trial);
      std::swap(r, r_trial);
      solver.shortening.swap(delta_trial);
      solver.part_poses.swap(poses_trial);
    }



    bool
    QuasiStaticSolver::LoadStep::penalty_of_last_state_holds(const double ratio)
    {
      I.follow_geometry();
      ++penalty_updates;
      I.evaluate(solver.u,
                 solver.shortening,
                 solver.part_poses,
                 t_new,
                 t_new,
                 r);
      const double scale_now = I.residual_scale(r);
      const double ratio_now = r.free_norm / scale_now;
      const bool   holds =
        !r.failed &&
        (I.residual_converged(
           r, std::max(10. * ratio, 1e-3 * settings.residual_tolerance)) ||
         (penalty_updates >= 3 &&
          I.residual_converged(r, settings.residual_tolerance)));
      if (root && !holds)
        log << "    penalty stiffness of this state: residual "
            << std::scientific << std::setprecision(3) << r.free_norm
            << " kN, relative " << ratio_now << std::defaultfloat
            << std::setprecision(6) << std::endl;
      return holds;
    }



    bool
    QuasiStaticSolver::LoadStep::iterate(std::string &reason)
    {
      const parameters::QuasiStatic &s            = settings;
      double                         first_energy = 0.;
      unsigned int                   growth       = 0;
      double previous_norm = std::numeric_limits<double>::max();
      penalty_updates      = 0;
      linear_iterations    = 0;
      for (iterations = 0; iterations < s.max_iterations; ++iterations)
        {
          const bool   predictor = (iterations == 0);
          unsigned int n_linear  = 0;
          if (!solve_correction(predictor, n_linear, reason))
            return false;
          linear_iterations += n_linear;
          double alpha = 1.;
          if (!line_search(predictor, alpha))
            {
              reason = r_trial.failure;
              break;
            }
          // (The predictor's from the residuals before and after it.)
          const double energy_increment =
            predictor ? I.energy_increment(du, d_delta, d_part, &r, &r_trial) :
                        I.energy_increment(du, d_delta, d_part);
          if (predictor)
            first_energy = energy_increment;
          take_trial();

          const double scale = I.residual_scale(r);
          const double ratio = r.free_norm / scale;
          // (Collective: on every rank, not inside the log's if.)
          const double update = du.linfty_norm();
          if (root)
            log << "    iteration " << iterations + 1 << ": residual "
                << std::scientific << std::setprecision(3) << r.free_norm
                << " kN, relative " << ratio << ", update " << update
                << " mm, energy " << energy_increment
                << " J, linear iterations " << n_linear
                << (alpha < 1. ? ", line search " + short_number(alpha) :
                                 std::string())
                << ", " << std::fixed << std::setprecision(2) << wall() << " s"
                << std::defaultfloat << std::setprecision(6) << std::endl;
          bool residual_ok = I.residual_converged(r, s.residual_tolerance);
          // (In a step in which nothing changes, e.g. a held load with
          // friction, even the first iteration's energy is round-off: an
          // increment at the round-off of the strain energy is converged
          // as well.)
          const bool energy_ok =
            r.free_norm <= s.residual_floor ||
            energy_increment <= s.energy_tolerance * first_energy ||
            energy_increment <= 1e-15 * std::abs(r.energy);
          if (!predictor && residual_ok && energy_ok && follows_geometry &&
              last_step)
            residual_ok = penalty_of_last_state_holds(ratio);
          if (!predictor && residual_ok && energy_ok)
            {
              ++iterations;
              return true;
            }
          // Divergence: the residual grew in two iterations in a row, from
          // the third on.
          if (!predictor && r.free_norm > previous_norm)
            ++growth;
          else
            growth = 0;
          if (growth >= 2 && iterations >= 2)
            {
              reason = "the residual grows";
              break;
            }
          previous_norm =
            predictor ? std::numeric_limits<double>::max() : r.free_norm;
        }
      if (reason.empty())
        reason = "no convergence in " + std::to_string(s.max_iterations) +
                 " iterations";
      return false;
    }



    void
    QuasiStaticSolver::LoadStep::restore_start()
    {
      solver.u = u_start;
      solver.u.update_ghost_values();
      solver.shortening = delta_start;
      solver.part_poses = poses_start;
    }



    void
    QuasiStaticSolver::run(const double                 end_time,
                           std::ostream                &log,
                           const std::function<void()> &on_step)
    {
      Implementation                &I = *impl;
      const parameters::QuasiStatic &s = I.settings;
      const bool   root = Utilities::MPI::this_mpi_process(I.comm) == 0;
      LoadStep     load_step(*this, log);
      double       step     = std::min(s.initial_step, s.maximum_step);
      unsigned int cutbacks = 0, cutback_iterations = 0;
      while (current_time < end_time * (1. - 1e-12))
        {
          // Never step over a lock time: the section's target is reached
          // there, and then held.
          double stop = end_time;
          for (const PretensionLoad &section : I.sections)
            if (current_time < section.lock_time * (1. - 1e-12))
              stop = std::min(stop, section.lock_time);
          step = std::min(step, stop - current_time);
          // Snap a last sliver onto the end time (or the lock time).
          if (stop - (current_time + step) < 1e-3 * step)
            step = stop - current_time;
          const double t_new = current_time + step;
          if (root)
            log << "  Step to t = " << short_number(t_new, 6) << " (dt "
                << short_number(step) << ")" << std::endl;

          load_step.begin(t_new, t_new >= end_time * (1. - 1e-12));
          std::string reason;
          if (!load_step.iterate(reason))
            {
              // Back to the last converged state, and halve.
              load_step.restore_start();
              ++cutbacks;
              cutback_iterations +=
                std::min(load_step.iterations + 1, s.max_iterations);
              if (root)
                log << "  Cut back: " << reason << std::endl;
              const bool count_limit = cutbacks > s.max_cutbacks;
              const bool step_limit  = 0.5 * step < s.minimum_step;
              if (count_limit || step_limit)
                {
                  // The history of the last converged state stays current
                  // (never accepted since), and so do the outputs.
                  throw QuasiStaticFailure(
                    "the load step to t = " + short_number(t_new, 6) +
                    " did not converge (" + reason + ") after " +
                    std::to_string(cutbacks - 1) + " cut-backs, at a step of " +
                    short_number(step) + ", which hit " +
                    cutback_limit_advice(reason, count_limit, step_limit, s) +
                    "; the last converged state is t = " +
                    short_number(current_time, 6));
                }
              step *= 0.5;
              continue;
            }

          current_time = t_new;
          records.push_back({t_new,
                             step,
                             load_step.iterations,
                             load_step.linear_iterations,
                             cutbacks,
                             cutback_iterations});
          cutbacks           = 0;
          cutback_iterations = 0;
          // Reactions and energies of the converged state (this evaluation
          // writes the same new history as the last iteration's), then its
          // history becomes the start of the next step.
          evaluate_state();
          I.elements.accept_history();
          for (model::ForceContribution *load : I.loads)
            load->accept_step();
          on_step();
          if (load_step.iterations <= 4)
            step = std::min(1.5 * step, s.maximum_step);
        }
    }
  } // namespace time_integration
} // namespace rubberdyn
