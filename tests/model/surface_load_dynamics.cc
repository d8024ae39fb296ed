// Surface loads in the explicit solver: a free elastic block (2 x 2 x 4
// hexahedra of 1 mm, E = 0.05 GPa, nu = 0.3, rho = 1e-6 kg/mm^3, F-bar,
// default bulk viscosity, no other boundary condition) under loads
// suddenly applied at t = 0, run to 0.5 ms (about 150 steps; 14 periods
// 2 L / c of the first free-free axial mode, c = sqrt(E / rho)).
//
// Momentum. In the central-difference scheme the momentum changes by
//   sum_i m_i (v_i^{n+1/2} - v_i^{n-1/2}) = dt^n sum_i f_i^n,
// dt^n = (dt^{n-1/2} + dt^{n+1/2}) / 2, dt^0 = dt^{1/2} / 2, exactly (up to
// round-off), and the internal forces of every element sum to zero (a
// translation changes neither F nor F-bar), so sum_i f_i^n is the loads'
// resultant F^n. Hence the momentum at t_{N-1/2} is the discrete impulse
//   P^{N-1/2} = sum_{n<N} dt^n F^n,
// which for a constant resultant F is F t_{N-1/2}. Checked to 1e-10
// relative.
//
// Work. SurfaceLoads books (f^{n-1} + f^n) / 2 . (u^n - u^{n-1}). Two exact
// consequences are checked against quantities computed independently
// with deal.II's FEFaceValues / FEValues:
// - a dead uniform traction t: the sum telescopes to t . int_Gamma u^N dA
//   (to 1e-12 relative);
// - a uniform pressure p on the whole closed surface: the nodal forces are
//   -p dV/dx_a exactly (V = int det F dX, the enclosed volume of the
//   bilinear-faced body, and 2 x 2 Gauss integrates int N_a n da exactly),
//   and V is cubic in the nodal positions: along a step's straight path
//   V(s) = V0 + V1 s + V2 s^2 + V3 s^3 with V3 = int det(grad du) dX, and
//   the trapezoidal rule on dV/ds gives V1 + V2 + 3/2 V3. So the booked
//   work is exactly -p (V^N - V^0 + 1/2 sum_n int det(grad du^n) dX)
//   (checked to 1e-10 relative, measured 2e-14; without the cubic terms
//   the difference is 1.4e-5). The resultant on the closed surface is zero
//   at every step, so the momentum stays zero (below 1e-12 of p A times
//   the time).
//
// Energy. EnergyBalance::relative_error() at the end is below 1e-4. This is
// not round-off: with the loads' work by the trapezoidal rule, the
// kinetic energy at t_n from the mean of the two half-step velocities
// differs from the work by O(dt^2) terms of the vibration a sudden load
// excites, and, because the stable step changes by up to 6 % from one
// step to the next when the bulk viscosity switches on or off in the
// critical element, by about F . v (dt^{n+1/2} - dt^{n-1/2}) / 4 for the
// accelerated block. Measured: 3.5e-5 (traction) and 3.4e-5 (pressure and
// linear traction) at the default step scale 0.9; 3.5e-6 and 8.5e-6 at
// 0.45. Case 4 is not checked: an all-round sudden pressure puts much of
// the energy into modes near the stability limit, whose kinetic energy the
// mean of the half-step velocities underestimates by up to
// (omega dt / 2)^2 (measured 5 %; 0.07 % with the pressure ramped over
// 0.2 ms).
//
// Cases:
// 1. a uniform traction t = (0.2, -0.1, 1) 1e-3 GPa on the face z = 4 (a
//    dead load, constant resultant t A, A = 4 mm^2);
// 2. a uniform pressure of 1e-3 GPa on the face z = 0 with a traction
//    t_x = 1e-3 (z / 4) GPa on the face x = 2: the pressure follows the
//    face, so F^n changes with the deformation and the impulse is summed
//    from SurfaceLoads::resultants() at every step;
// 3. case 2 run to 0.25 ms, saved, and continued to 0.5 ms is identical to
//    the last bit to a fresh model that loads the saved state and runs to
//    0.5 ms (displacements, velocities, external work);
// 4. a uniform pressure of 1e-3 GPa on all six faces (the block breathes).
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/lac/vector.h>

#include <rubberdyn/base/partitioner.h>
#include <rubberdyn/elements/solid_hex_elements.h>
#include <rubberdyn/elements/solid_hex_forces.h>
#include <rubberdyn/materials/elastic.h>
#include <rubberdyn/model/surface_loads.h>
#include <rubberdyn/time_integration/explicit_solver.h>

#include <set>
#include <sstream>

#include "../tests.h"

using namespace dealii;
using namespace rubberdyn;
using testing::check;
using testing::sci;

namespace
{
  /** The test's output: written by rank 0, discarded on the others. */
  std::ostream &
  text()
  {
    static std::ofstream discard; // never opened: writes are dropped
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      return testing::out();
    return discard;
  }

  /** The measured errors, on stderr of rank 0 (for the log, not compared). */
  std::ostream &
  measured()
  {
    static std::ofstream discard;
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      return std::cerr;
    return discard;
  }
  using LoadFunction = std::function<double(const Point<3> &, double)>;
  using Type         = model::BoundaryCondition::Type;

  constexpr double end_time = 0.5;
  constexpr double p0       = 1e-3;

  model::BoundaryCondition
  condition(const std::set<types::boundary_id> &ids,
            const Type                          type,
            const std::vector<unsigned int>    &components,
            const std::vector<LoadFunction>    &functions,
            const bool                          depends_on_position)
  {
    model::BoundaryCondition bc;
    bc.name                = "load";
    bc.boundary_ids        = ids;
    bc.type                = type;
    bc.components          = components;
    bc.functions           = functions;
    bc.depends_on_position = depends_on_position;
    return bc;
  }

  /** The free block with its elements, loads and solver. */
  struct FreeBlock
  {
    explicit FreeBlock(const std::vector<model::BoundaryCondition> &conditions)
      : triangulation(MPI_COMM_WORLD)
      , fe(FE_Q<3>(1), 3)
      , dof_handler(triangulation)
      , law(0.05, 0.3, 1e-6)
    {
      // colorize: boundary ids 0..5 on x = 0, x = 2, y = 0, y = 2, z = 0,
      // z = 4; it also numbers the cells by octant: one material here.
      GridGenerator::subdivided_hyper_rectangle(triangulation,
                                                {2, 2, 4},
                                                Point<3>(),
                                                Point<3>(2., 2., 4.),
                                                true);
      for (const auto &cell : triangulation.active_cell_iterators())
        cell->set_material_id(0);
      dof_handler.distribute_dofs(fe);
      partitioner = rubberdyn::ghosted_partitioner(dof_handler);
      elements.initialize(dof_handler,
                          partitioner,
                          {{{0}, &law, elements::Formulation::fbar}},
                          elements::ElementSettings());
      hex_forces = std::make_unique<elements::SolidHexForces>(
        elements,
        std::vector<double>(elements.n_elements(), 1.));
      loads  = std::make_unique<model::SurfaceLoads>(dof_handler,
                                                    partitioner,
                                                    conditions);
      solver = std::make_unique<time_integration::ExplicitSolver>(
        dof_handler,
        std::vector<model::ForceContribution *>{hex_forces.get(), loads.get()},
        bodies,
        nullptr,
        partitioner,
        time_integration::ExplicitSettings(),
        MPI_COMM_WORLD);

      // The direction of every owned dof.
      component.resize(partitioner->locally_owned_size());
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            cell->get_dof_indices(dofs);
            for (unsigned int i = 0; i < dofs.size(); ++i)
              if (partitioner->in_local_range(dofs[i]))
                component[partitioner->global_to_local(dofs[i])] =
                  fe.system_to_component_index(i).first;
          }
    }

    /** sum_i m_i v_i of the last half-step velocities (kg mm/ms). */
    Tensor<1, 3>
    momentum() const
    {
      double p[3] = {0., 0., 0.};
      for (unsigned int i = 0; i < component.size(); ++i)
        p[component[i]] += solver->lumped_mass().local_element(i) *
                           solver->velocity().local_element(i);
      Utilities::MPI::sum(ArrayView<const double>(p, 3),
                          MPI_COMM_WORLD,
                          ArrayView<double>(p, 3));
      return Tensor<1, 3>({p[0], p[1], p[2]});
    }

    /**
     * int_Gamma u dA over the faces of boundary id @p id (mm^3); 2 x 2
     * Gauss is exact for the bilinear u on the flat faces.
     */
    Tensor<1, 3>
    face_integral(const VectorType &u_h, const types::boundary_id id) const
    {
      FEFaceValues<3>             face_values(fe,
                                  QGauss<2>(2),
                                  update_values | update_JxW_values);
      std::vector<Vector<double>> u(4, Vector<double>(3));
      double                      sums[3] = {0., 0., 0.};
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const unsigned int face : cell->face_indices())
            if (cell->at_boundary(face) &&
                cell->face(face)->boundary_id() == id)
              {
                face_values.reinit(cell, face);
                face_values.get_function_values(u_h, u);
                for (unsigned int q = 0; q < 4; ++q)
                  for (unsigned int d = 0; d < 3; ++d)
                    sums[d] += u[q][d] * face_values.JxW(q);
              }
      Utilities::MPI::sum(ArrayView<const double>(sums, 3),
                          MPI_COMM_WORLD,
                          ArrayView<double>(sums, 3));
      return Tensor<1, 3>({sums[0], sums[1], sums[2]});
    }

    /**
     * int det(c I + grad u_h) dX (mm^3): with c = 1 the volume at the
     * displacement @p u_h, with c = 0 the cubic term of the volume in
     * @p u_h. 2 x 2 x 2 Gauss is exact: the determinant of the gradient of
     * a trilinear field is of degree 2 in each coordinate.
     */
    double
    volume(const VectorType &u_h, const double c = 1.) const
    {
      FEValues<3>                            fe_values(fe,
                            QGauss<3>(2),
                            update_gradients | update_JxW_values);
      std::vector<std::vector<Tensor<1, 3>>> grad_u(8,
                                                    std::vector<Tensor<1, 3>>(
                                                      3));
      double                                 local = 0.;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            fe_values.reinit(cell);
            fe_values.get_function_gradients(u_h, grad_u);
            for (unsigned int q = 0; q < 8; ++q)
              {
                Tensor<2, 3> F;
                for (unsigned int i = 0; i < 3; ++i)
                  for (unsigned int j = 0; j < 3; ++j)
                    F[i][j] = (i == j ? c : 0.) + grad_u[q][i][j];
                local += determinant(F) * fe_values.JxW(q);
              }
          }
      return Utilities::MPI::sum(local, MPI_COMM_WORLD);
    }

    parallel::distributed::Triangulation<3>           triangulation;
    FESystem<3>                                       fe;
    DoFHandler<3>                                     dof_handler;
    std::shared_ptr<Utilities::MPI::Partitioner>      partitioner;
    materials::Elastic<3>                             law;
    elements::SolidHexElements                        elements;
    std::unique_ptr<elements::SolidHexForces>         hex_forces;
    std::unique_ptr<model::SurfaceLoads>              loads;
    std::vector<model::RigidBody>                     bodies;
    std::unique_ptr<time_integration::ExplicitSolver> solver;
    std::vector<unsigned int>                         component;
  };

  /**
   * Sums the discrete impulse sum_n dt^n F^n of the loads: called in the
   * monitor, which sees F^n (the last evaluation) and dt^{n+1/2}.
   */
  struct ImpulseMeter
  {
    void
    record(const FreeBlock &block)
    {
      const double step    = block.solver->time_step();
      const double average = started ? 0.5 * (last_step + step) : 0.5 * step;
      for (const auto &r : block.loads->resultants())
        impulse += average * r.force;
      last_step = step;
      started   = true;
    }

    Tensor<1, 3> impulse;
    double       last_step = 0.;
    bool         started   = false;
  };

  /**
   * The displacement and the external work at the time of the energies:
   * the monitor sees both at t_n, whereas after run() the displacement is
   * at t_N and the energies (and the loads' work) at t_{N-1}.
   */
  struct Snapshot
  {
    void
    record(const time_integration::ExplicitSolver &solver)
    {
      if (u.size() == 0)
        u.reinit(solver.displacement(), true);
      u             = solver.displacement();
      external_work = solver.energies().external_work;
    }

    VectorType u;
    double     external_work = 0.;
  };

  /** Largest |a_i - b_i| over the owned entries and ranks. */
  double
  max_difference(const VectorType &a, const VectorType &b)
  {
    double local = 0.;
    for (unsigned int i = 0; i < a.locally_owned_size(); ++i)
      local =
        std::max(local, std::abs(a.local_element(i) - b.local_element(i)));
    return Utilities::MPI::max(local, MPI_COMM_WORLD);
  }

  /** @p v with entries below 1e-12 |v| set to zero, for printing. */
  Tensor<1, 3>
  printable(const Tensor<1, 3> &v)
  {
    Tensor<1, 3> result = v;
    for (unsigned int d = 0; d < 3; ++d)
      if (std::abs(result[d]) < 1e-12 * v.norm())
        result[d] = 0.;
    return result;
  }

  std::vector<model::BoundaryCondition>
  pressure_and_linear_traction()
  {
    return {condition({4},
                      Type::pressure,
                      {0, 1, 2},
                      {[](const Point<3> &, double) { return p0; }},
                      false),
            condition({1},
                      Type::traction,
                      {0},
                      {[](const Point<3> &X, double) {
                        return 1e-3 * X[2] / 4.;
                      }},
                      true)};
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  text() << std::setprecision(4);

  // 1. Uniform traction on z = 4.
  {
    const Tensor<1, 3> t({0.2e-3, -0.1e-3, 1e-3});
    FreeBlock          block({condition({5},
                               Type::traction,
                               {0, 1, 2},
                               {[t](const Point<3> &, double) { return t[0]; },
                                         [t](const Point<3> &, double) { return t[1]; },
                                         [t](const Point<3> &, double) { return t[2]; }},
                               false)});
    Snapshot           snapshot;
    block.solver->run(end_time, [&]() { snapshot.record(*block.solver); });
    const auto        &s        = *block.solver;
    const double       t_half   = s.time() - 0.5 * s.time_step();
    const Tensor<1, 3> impulse  = 4. * t * t_half;
    const Tensor<1, 3> momentum = block.momentum();
    const double       error    = (momentum - impulse).norm() / impulse.norm();
    const double       work     = t * block.face_integral(snapshot.u, 5);
    const double       work_error =
      std::abs(snapshot.external_work - work) / std::abs(work);
    const double energy_error = s.energies().relative_error();
    text() << "uniform traction: " << s.step() << " steps to " << s.time()
           << " ms\n  momentum " << momentum << " kg mm/ms, F t = " << impulse
           << ", within 1e-10: " << (error < 1e-10 ? "yes" : "no")
           << "\n  external work " << snapshot.external_work
           << " J, t . int u dA = " << work
           << " J, within 1e-12: " << (work_error < 1e-12 ? "yes" : "no")
           << "\n  energy error below 1e-4: "
           << (energy_error < 1e-4 ? "yes" : "no") << std::endl;
    measured() << "traction: momentum error " << sci(error) << ", work error "
               << sci(work_error) << ", energy error " << sci(energy_error)
               << std::endl;
    check(error < 1e-10, "momentum " + sci(error));
    check(work_error < 1e-12, "work " + sci(work_error));
    check(energy_error < 1e-4, "energy balance " + sci(energy_error));
  }

  // 2. Follower pressure on z = 0 and a linear traction on x = 2.
  std::string checkpoint;
  VectorType  u_continued, v_continued;
  double      work_continued = 0.;
  {
    FreeBlock    block(pressure_and_linear_traction());
    ImpulseMeter meter;
    const auto   monitor = [&]() { meter.record(block); };
    block.solver->run(0.5 * end_time, monitor);
    {
      std::ostringstream saved;
      block.solver->save(saved);
      checkpoint = saved.str();
    }
    block.solver->run(end_time, monitor);
    const auto        &s        = *block.solver;
    const Tensor<1, 3> momentum = block.momentum();
    const double       error =
      (momentum - meter.impulse).norm() / meter.impulse.norm();
    const double energy_error = s.energies().relative_error();
    text() << "pressure and linear traction: " << s.step() << " steps\n"
           << "  momentum " << printable(momentum)
           << " kg mm/ms, sum dt F = " << printable(meter.impulse)
           << ", within 1e-10: " << (error < 1e-10 ? "yes" : "no")
           << "\n  external work " << s.energies().external_work
           << " J, energy error below 1e-4: "
           << (energy_error < 1e-4 ? "yes" : "no") << std::endl;
    measured() << "pressure: momentum error " << sci(error) << ", energy error "
               << sci(energy_error) << std::endl;
    check(error < 1e-10, "momentum " + sci(error));
    check(energy_error < 1e-4, "energy balance " + sci(energy_error));
    u_continued.reinit(s.displacement(), true);
    v_continued.reinit(s.velocity(), true);
    u_continued    = s.displacement();
    v_continued    = s.velocity();
    work_continued = s.energies().external_work;
  }

  // 3. Restart of case 2 from the state saved at 0.25 ms.
  {
    FreeBlock          block(pressure_and_linear_traction());
    std::istringstream saved(checkpoint);
    block.solver->load(saved);
    block.solver->run(end_time, []() {});
    const auto  &s  = *block.solver;
    const double du = max_difference(s.displacement(), u_continued);
    const double dv = max_difference(s.velocity(), v_continued);
    const bool   identical =
      du == 0. && dv == 0. && s.energies().external_work == work_continued;
    text() << "restart at 0.25 ms: displacements, velocities and external "
              "work identical: "
           << (identical ? "yes" : "no") << std::endl;
    check(identical, "restart differs: " + sci(du) + " " + sci(dv));
  }

  // 4. Pressure on the whole surface.
  {
    FreeBlock    block({condition({0, 1, 2, 3, 4, 5},
                               Type::pressure,
                               {0, 1, 2},
                               {[](const Point<3> &, double) { return p0; }},
                               false)});
    const double volume_0 = block.volume(block.solver->displacement());
    // sum_n int det(grad (u^n - u^{n-1})) dX, from the monitor's u^n.
    Snapshot   snapshot;
    VectorType increment;
    double     cubic_terms = 0.;
    block.solver->run(end_time, [&]() {
      if (snapshot.u.size() > 0)
        {
          increment.reinit(snapshot.u, true);
          increment = block.solver->displacement();
          increment -= snapshot.u;
          increment.update_ghost_values();
          cubic_terms += block.volume(increment, 0.);
        }
      snapshot.record(*block.solver);
    });
    const double change = block.volume(snapshot.u) - volume_0;
    // Per step the trapezoidal rule on -p dV/ds, V cubic in s, gives
    // -p (Delta V + int det(grad Delta u) dX / 2).
    const double work = -p0 * (change + 0.5 * cubic_terms);
    const double work_error =
      std::abs(snapshot.external_work - work) / std::abs(work);
    // Scale of the momentum: p times the largest face area times the time.
    const double momentum_error =
      block.momentum().norm() / (p0 * 8. * block.solver->time());
    text() << "pressure on the closed surface: volume change " << change
           << " mm^3\n  external work " << snapshot.external_work
           << " J, -p (dV + sum int det(grad du) dX / 2) = " << work
           << " J, within 1e-10: " << (work_error < 1e-10 ? "yes" : "no")
           << "\n  momentum below 1e-12 p A t: "
           << (momentum_error < 1e-12 ? "yes" : "no") << std::endl;
    measured() << "closed surface: work error " << sci(work_error)
               << ", without the cubic terms "
               << sci(std::abs(snapshot.external_work + p0 * change) /
                      std::abs(work))
               << ", momentum " << sci(momentum_error) << ", energy error "
               << sci(block.solver->energies().relative_error()) << std::endl;
    check(work_error < 1e-10, "work " + sci(work_error));
    check(momentum_error < 1e-12, "momentum " + sci(momentum_error));
  }
  return 0;
}
