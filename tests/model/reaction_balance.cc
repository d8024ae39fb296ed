// The reactions of the boundary conditions balance the inertia of the body
// exactly, force and moment, at every step of the central-difference scheme
// (issue 7, "Verification": reaction moments).
//
// The model: the rubber block of parameter_files/meshes/shear_block.msh
// (20 x 20 x 10 mm, 8 x 8 x 4 cells; surfaces 1 = bottom z = 0, 2 = top
// z = 10), Yeoh rubber, no gravity, no contact. Condition `base` holds the
// bottom fixed (moment point q_b = (10, 10, 0)); condition `top` prescribes
// the top's x and z displacements (y free), a shear, a compression and a
// tilt about y:
//   u_x = a s(t),  u_z = (-b + c (X - 10)) s(t),  s = (1 - cos(pi t / T)) / 2
// for t < T, s = 1 after, with a = 1.5 mm, b = 0.5 mm, c = 0.03, T = 1 ms
// (moment point q_t = (10, 10, 10)), run to 1.2 ms. Built as a
// model::Model here and run by simulation::ExplicitSimulation, with a
// postprocessor plugin that records every step.
//
// The identities. The solver (time_integration/explicit_solver.h) takes,
// for every dof i,
//   v_i^{n+1/2} = v_i^{n-1/2} + Dt^n / m_i (-f_int,i^n + r_i^n),
// with Dt^n = (Dt^{n-1/2} + Dt^{n+1/2}) / 2 (Dt^0 = Dt^{1/2} / 2 and
// v^{-1/2} = v^0 on the first step), m_i the lumped mass (with mass
// scaling), f_int the elements' internal forces at u^n and r_i^n the
// reaction of the constraint that holds dof i (zero on free dofs; on a
// constrained dof the solver defines r_i by this very equation, from the
// velocity it imposes). Summed over all dofs of one direction:
//   (1) sum_bc R^n = sum_i m_i (v_i^{n+1/2} - v_i^{n-1/2}) / Dt^n,
// because the internal forces of an element sum to zero (sum_a grad N_a =
// 0: a rigid translation stores no energy). Crossed with x_i^n - p, x^n =
// X + u^n the current node positions, and summed over the nodes:
//   (2) sum_bc M_p^n = sum_nodes (x^n - p) x m (v^{n+1/2} - v^{n-1/2}) / Dt^n,
// because the internal forces of an objective stored energy W(x) have no
// resultant moment at the positions where they are evaluated: W(Q x) =
// W(x) for every rotation Q = exp(theta w x) gives 0 = dW/dtheta = w .
// sum_a x_a x f_int,a for every axis w. This holds for each element's
// quadrature-summed energy (F -> Q F at each Gauss point; F-bar's
// (J_0 / J)^{1/3} and its stabilisation energy, a function of J_q / J_0,
// are invariant), and also for the bulk viscosity force, a pressure, i.e.
// a symmetric stress, with sum_a x_a (x) grad_x N_a = I.
// Each condition's moment is reported about its own moment point q, so
// it is shifted to the common point p = (-5, 3, 20) by M_p = M_q + (q - p)
// x F. Both identities are exact up to round-off.
//
// Tolerance: 1e-8 of the largest reaction force (and moment) of the run,
// checked at every step. Round-off in the sums is about 1e-16 times the
// sum of the magnitudes of the element forces at a node (a few times the
// reactions), and in m (v^{n+1/2} - v^{n-1/2}) about 1e-16 m |v| / Dt,
// which is 1e-12 of the reactions here; 1e-8 leaves a wide margin and is
// still far below what a wrong term gives (see the three controls at the
// end: leaving out one condition, forgetting the shift of the moment point,
// or taking the moments with the reference positions X instead of x^n).
//
// First step: the top's prescribed displacement has a zero time derivative
// at t = 0, and the solver's forward difference of it over 1e-9 ms is
// exactly 0 (cos(pi 1e-9 / T) rounds to 1), so v^0 = 0 everywhere, as the
// plugin assumes.
//
// Run twice: F-bar with its volumetric stabilisation, and the displacement
// formulation; on 1 and 2 ranks (reaction_balance.mpirun=2.output).
#include <deal.II/base/mpi.h>
#include <deal.II/base/tensor.h>

#include <rubberdyn/io/gmsh_mesh.h>
#include <rubberdyn/simulation/explicit_simulation.h>
#include <rubberdyn/model/model.h>
#include <rubberdyn/postprocess/postprocessor.h>
#include <rubberdyn/time_integration/explicit_solver.h>

#include <array>
#include <cmath>
#include <memory>
#include <sstream>
#include <vector>

#include "../tests.h"
#include "model_fixtures.h"

using namespace dealii;
using namespace rubberdyn;
using testing::check;
using testing::out;
using testing::sci;

namespace
{
  const Point<3> p(-5., 3., 20.);

  /** What one condition adds to the balance. */
  struct Condition
  {
    /** Its moment point. */
    Point<3> q;
    /** The solver's constraint groups that belong to it. */
    std::vector<unsigned int> groups;
  };

  /**
   * Records at every step the reactions (already summed over ranks by the
   * solver) and this rank's share of the inertia terms of (1) and (2);
   * finish() sums the shares over the ranks once.
   */
  class ReactionBalance : public postprocess::Postprocessor
  {
  public:
    ReactionBalance(const model::Model             &model,
                    const std::vector<Condition>   &conditions,
                    const std::vector<unsigned int> direction_of_group)
      : conditions(conditions)
      , direction_of_group(direction_of_group)
    {
      // The locally owned nodes: the global indices of their x, y, z dofs
      // and their reference positions. A node's dofs are owned together.
      const FiniteElement<3>              &fe = model.fe;
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      std::vector<bool> seen(model.partitioner->locally_owned_size(), false);
      for (const auto &cell : model.dof_handler.active_cell_iterators())
        if (cell->is_locally_owned() || cell->is_ghost())
          {
            cell->get_dof_indices(dofs);
            for (const unsigned int v : cell->vertex_indices())
              {
                Node node;
                for (unsigned int d = 0; d < 3; ++d)
                  node.dofs[d] = dofs[fe.component_to_system_index(d, v)];
                if (!model.partitioner->in_local_range(node.dofs[0]))
                  continue;
                const unsigned int local =
                  model.partitioner->global_to_local(node.dofs[0]);
                if (seen[local])
                  continue;
                seen[local] = true;
                node.X      = cell->vertex(v);
                nodes.push_back(node);
              }
          }
      v_old.reinit(model.partitioner);
    }

    std::string
    name() const override
    {
      return "reaction balance";
    }

    void
    after_step(const postprocess::SimulationView &view) override
    {
      const time_integration::ExplicitSolver &s = *view.explicit_solver();
      const VectorType &u = s.displacement(), &v = s.velocity(),
                       &m = s.lumped_mass();
      const double dt_new = s.time_step();
      const double dt_n   = started ? 0.5 * (dt_old + dt_new) : 0.5 * dt_new;

      // This rank's inertia terms: force, moment with x^n, moment with X.
      std::vector<double> share(9, 0.);
      for (const Node &node : nodes)
        {
          Tensor<1, 3> inertia, x, X;
          for (unsigned int d = 0; d < 3; ++d)
            {
              const auto i = node.dofs[d];
              inertia[d]   = m(i) * (v(i) - v_old(i)) / dt_n;
              x[d]         = node.X[d] + u(i) - p[d];
              X[d]         = node.X[d] - p[d];
            }
          const Tensor<1, 3> moment           = cross_product_3d(x, inertia);
          const Tensor<1, 3> reference_moment = cross_product_3d(X, inertia);
          for (unsigned int d = 0; d < 3; ++d)
            {
              share[d] += inertia[d];
              share[3 + d] += moment[d];
              share[6 + d] += reference_moment[d];
            }
        }
      inertia_shares.push_back(share);

      // The reactions of each condition, and its moment shifted to p.
      Step step;
      for (const Condition &condition : conditions)
        {
          Tensor<1, 3> force, moment_q;
          for (const unsigned int g : condition.groups)
            {
              force[direction_of_group[g]] += s.reactions()[g];
              moment_q += s.reaction_moments()[g];
            }
          step.force.push_back(force);
          step.moment_q.push_back(moment_q);
          step.moment_p.push_back(moment_q +
                                  cross_product_3d(condition.q - p, force));
        }
      steps.push_back(step);

      v_old   = v;
      dt_old  = dt_new;
      started = true;
    }

    void
    finish(const postprocess::SimulationView &view) override
    {
      std::vector<double> all;
      for (const std::vector<double> &share : inertia_shares)
        all.insert(all.end(), share.begin(), share.end());
      Utilities::MPI::sum(all, view.model().comm, all);
      for (unsigned int n = 0; n < steps.size(); ++n)
        for (unsigned int d = 0; d < 3; ++d)
          {
            steps[n].inertia_force[d]            = all[9 * n + d];
            steps[n].inertia_moment[d]           = all[9 * n + 3 + d];
            steps[n].inertia_moment_reference[d] = all[9 * n + 6 + d];
          }
    }

    /** One step's reactions (per condition) and inertia terms. */
    struct Step
    {
      std::vector<Tensor<1, 3>> force, moment_q, moment_p;
      Tensor<1, 3> inertia_force, inertia_moment, inertia_moment_reference;
    };
    std::vector<Step> steps;

  private:
    struct Node
    {
      types::global_dof_index dofs[3];
      Point<3>                X;
    };
    std::vector<Condition>           conditions;
    std::vector<unsigned int>        direction_of_group;
    std::vector<Node>                nodes;
    VectorType                       v_old;
    double                           dt_old  = 0.;
    bool                             started = false;
    std::vector<std::vector<double>> inertia_shares;
  };



  void
  run_case(const std::string          &title,
           const elements::Formulation formulation,
           const double                fbar_stabilization,
           const MPI_Comm              comm)
  {
    model::Model model(comm);
    io::read_gmsh_mesh(model.triangulation,
                       fixtures::mesh_directory() + "shear_block.msh",
                       "Mesh/Mesh file");

    // The rubber of parameter_files/shear_block.prm.
    model::Part rubber;
    rubber.name         = "rubber";
    rubber.material_ids = {1};
    rubber.formulation  = formulation;
    rubber.law          = fixtures::rubber_law();
    model.parts.push_back(std::move(rubber));

    const double T = 1., a = 1.5, b = 0.5, c = 0.03;
    const auto   s = [T](const double t) {
      return t < T ? 0.5 * (1. - std::cos(numbers::PI * t / T)) : 1.;
    };
    model::BoundaryCondition base;
    base.name         = "base";
    base.boundary_ids = {1};
    base.type         = model::BoundaryCondition::Type::fixed;
    base.moment_point = Point<3>(10., 10., 0.);
    model::BoundaryCondition top;
    top.name                = "top";
    top.boundary_ids        = {2};
    top.type                = model::BoundaryCondition::Type::displacement;
    top.components          = {0, 2};
    top.depends_on_position = true;
    top.moment_point        = Point<3>(10., 10., 10.);
    top.functions.push_back(
      [=](const Point<3> &, const double t) { return a * s(t); });
    top.functions.push_back([=](const Point<3> &X, const double t) {
      return (-b + c * (X[0] - 10.)) * s(t);
    });
    model.boundary_conditions.push_back(base);
    model.boundary_conditions.push_back(top);
    model.setup();

    parameters::TimeIntegration time_integration;
    time_integration.end_time           = 1.2;
    time_integration.fbar_stabilization = fbar_stabilization;
    parameters::Output output;
    output.directory               = "output_" + title;
    output.field_output_interval   = 0.;
    output.history_output_interval = 0.1;
    simulation::ExplicitSimulation simulation(model,
                                         time_integration,
                                         output,
                                         "Reaction balance",
                                         title);
    simulation.add_standard_postprocessors();

    // The constraint groups in the order ExplicitSimulation adds them: one
    // per listed component, condition by condition (if that order changed,
    // the balance would fail, not pass wrongly).
    const std::vector<Condition> conditions = {{base.moment_point, {0, 1, 2}},
                                               {top.moment_point, {3, 4}}};
    auto                         plugin     = std::make_unique<ReactionBalance>(
      model,
      conditions,
      std::vector<unsigned int>{0, 1, 2, 0, 2});
    ReactionBalance &balance = *plugin;
    simulation.add_postprocessor(std::move(plugin));
    std::ostringstream log;
    simulation.run(log);

    // Residuals of (1) and (2) at every step, relative to the largest
    // reaction force and moment (about p) of the run; the controls with
    // the top's reactions left out, with the moments about their own
    // points added unshifted, and with the inertia moments about X.
    double largest_force = 0., largest_moment = 0.;
    double force_residual = 0., moment_residual = 0.;
    double without_top = 0., unshifted = 0., reference = 0.;
    for (const ReactionBalance::Step &step : balance.steps)
      {
        Tensor<1, 3> force, moment, moment_unshifted;
        for (unsigned int k = 0; k < conditions.size(); ++k)
          {
            force += step.force[k];
            moment += step.moment_p[k];
            moment_unshifted += step.moment_q[k];
          }
        largest_force  = std::max(largest_force, force.norm());
        largest_moment = std::max(largest_moment, moment.norm());
        for (unsigned int k = 0; k < conditions.size(); ++k)
          {
            largest_force  = std::max(largest_force, step.force[k].norm());
            largest_moment = std::max(largest_moment, step.moment_p[k].norm());
          }
        force_residual =
          std::max(force_residual, (force - step.inertia_force).norm());
        moment_residual =
          std::max(moment_residual, (moment - step.inertia_moment).norm());
        without_top =
          std::max(without_top, (step.force[0] - step.inertia_force).norm());
        unshifted =
          std::max(unshifted, (moment_unshifted - step.inertia_moment).norm());
        reference =
          std::max(reference, (moment - step.inertia_moment_reference).norm());
      }
    force_residual /= largest_force;
    moment_residual /= largest_moment;
    without_top /= largest_force;
    unshifted /= largest_moment;
    reference /= largest_moment;

    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        out() << title << ": largest reaction " << std::setprecision(2)
              << largest_force << " kN, largest moment about p "
              << largest_moment << " kN mm" << std::endl;
        std::cout << title << ": " << balance.steps.size()
                  << " steps checked, to t = " << simulation.solver().time()
                  << " ms" << std::endl;
        out() << "  largest residual of sum R = sum m dv / dt:             "
              << sci(force_residual) << " (limit 1e-8)" << std::endl;
        out() << "  largest residual of sum M_p = sum (x - p) x m dv / dt: "
              << sci(moment_residual) << " (limit 1e-8)" << std::endl;
        out() << "  controls (each must be far above 1e-8):" << std::endl;
        out() << "    reaction of 'top' left out:           " << without_top
              << std::endl;
        out() << "    moments not shifted to p:             " << unshifted
              << std::endl;
        out() << "    inertia moments with X instead of x:  " << reference
              << std::endl;
      }
    check(force_residual < 1e-8, title + ": force balance within 1e-8");
    check(moment_residual < 1e-8, title + ": moment balance within 1e-8");
    check(largest_force > 0.01 && largest_moment > 0.1,
          title + ": the reactions are not trivial");
    check(without_top > 1e-3 && unshifted > 1e-3 && reference > 1e-6,
          title + ": the controls would fail the 1e-8 check");
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  run_case("fbar", elements::Formulation::fbar, 0.3, MPI_COMM_WORLD);
  run_case("displacement",
           elements::Formulation::displacement,
           0.,
           MPI_COMM_WORLD);
}
