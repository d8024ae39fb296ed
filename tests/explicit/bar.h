// Shared set-up of the bar tests of the explicit engine: a slender
// prismatic bar of trilinear hexahedra, distributed over MPI_COMM_WORLD
// exactly as the drop-test study distributes its cylinder
// (source/studies/drop_test.cc), and a step load that tracks the wave
// front by the mean axial velocity of cross-sections.
#ifndef rubberdyn_tests_explicit_bar_h
#define rubberdyn_tests_explicit_bar_h

#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>

#include <rubberdyn/base/partitioner.h>
#include <rubberdyn/base/vector.h>
#include <rubberdyn/contact/rigid_surface_contact.h>
#include <rubberdyn/contact/rigid_surface_forces.h>
#include <rubberdyn/elements/solid_hex_elements.h>
#include <rubberdyn/elements/solid_hex_forces.h>
#include <rubberdyn/materials/material_model.h>
#include <rubberdyn/time_integration/explicit_solver.h>
#include <rubberdyn/time_integration/kinematic_constraints.h>

#include <cmath>
#include <functional>
#include <memory>
#include <set>
#include <vector>

namespace bar
{
  using namespace dealii;

  /**
   * Boundary ids of the bar (GridGenerator::subdivided_hyper_rectangle
   * with colorize = true).
   */
  namespace boundary
  {
    constexpr types::boundary_id x_min = 0, x_max = 1, y_min = 2, y_max = 3,
                                 z_min = 4, z_max = 5;
  } // namespace boundary

  /**
   * A bar of square cross-section @p width x @p width (mm), @p n_across
   * elements in each lateral direction, along z from 0 to @p length (mm)
   * with @p n_along elements: the bar's axis is z.
   */
  class Bar
  {
  public:
    Bar(const double       width,
        const unsigned int n_across,
        const double       length,
        const unsigned int n_along,
        const MPI_Comm     comm)
      : width(width)
      , length(length)
      , comm(comm)
      , triangulation(comm)
      , fe(FE_Q<3>(1), 3)
      , dof_handler(triangulation)
    {
      GridGenerator::subdivided_hyper_rectangle(triangulation,
                                                {n_across, n_across, n_along},
                                                Point<3>(0., 0., 0.),
                                                Point<3>(width, width, length),
                                                /*colorize=*/true);
      // colorize also numbers the cells by octant: one material here.
      for (const auto &cell : triangulation.active_cell_iterators())
        cell->set_material_id(0);
      dof_handler.distribute_dofs(fe);
      partitioner = rubberdyn::ghosted_partitioner(dof_handler);
    }

    /** Cross-section area (mm^2). */
    double
    area() const
    {
      return width * width;
    }

    /**
     * Local indices of the locally owned axial (z) degrees of freedom of
     * the nodes in the cross-section z = @p z (which must be a node layer).
     */
    std::vector<unsigned int>
    axial_dofs_at(const double z) const
    {
      std::set<unsigned int>               dofs;
      std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            cell->get_dof_indices(dof_indices);
            for (const unsigned int v : cell->vertex_indices())
              if (std::abs(cell->vertex(v)[2] - z) < 1e-9 * length)
                {
                  const types::global_dof_index i =
                    dof_indices[fe.component_to_system_index(2, v)];
                  if (partitioner->in_local_range(i))
                    dofs.insert(partitioner->global_to_local(i));
                }
          }
      return {dofs.begin(), dofs.end()};
    }

    /**
     * Local indices of the locally owned degrees of freedom of direction
     * @p component (0, 1, 2) of all nodes.
     */
    std::vector<unsigned int>
    owned_dofs_of_component(const unsigned int component) const
    {
      std::set<unsigned int>               dofs;
      std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            cell->get_dof_indices(dof_indices);
            for (const unsigned int v : cell->vertex_indices())
              {
                const types::global_dof_index i =
                  dof_indices[fe.component_to_system_index(component, v)];
                if (partitioner->in_local_range(i))
                  dofs.insert(partitioner->global_to_local(i));
              }
          }
      return {dofs.begin(), dofs.end()};
    }

    const double                                 width, length;
    const MPI_Comm                               comm;
    parallel::distributed::Triangulation<3>      triangulation;
    const FESystem<3>                            fe;
    DoFHandler<3>                                dof_handler;
    std::shared_ptr<Utilities::MPI::Partitioner> partitioner;
  };


  /**
   * The explicit model of a bar: F-bar hexahedra (default element settings)
   * of one law, penalty contact of the boundaries @p contact_ids with the
   * rigid @p surfaces (none by default), one rigid body per surface (held:
   * the caller may give them mass, freedom and velocity before the first
   * run), the kinematic constraints that @p add_constraints adds (none by
   * default), and the solver without mass scaling and with @p settings
   * (default settings unless given).
   */
  struct ExplicitBar
  {
    ExplicitBar(
      const Bar &                                          bar,
      const rubberdyn::materials::MaterialModel<3> &       law,
      const std::set<types::boundary_id> &                 contact_ids = {},
      const std::vector<rubberdyn::contact::RigidSurface> &surfaces    = {},
      const double                                         penalty_scale = 1.,
      const rubberdyn::time_integration::ExplicitSettings &settings      = {},
      const std::function<void(
        rubberdyn::time_integration::KinematicConstraints &)> &add_constraints =
        {})
      : bodies(surfaces.size())
      , constraints(bar.dof_handler, bar.partitioner)
    {
      elements.initialize(bar.dof_handler,
                          bar.partitioner,
                          {{{0}, &law, rubberdyn::elements::Formulation::fbar}},
                          rubberdyn::elements::ElementSettings());
      contact.initialize(bar.dof_handler,
                         bar.partitioner,
                         contact_ids,
                         {law.bulk_modulus()},
                         penalty_scale,
                         surfaces);
      if (add_constraints)
        add_constraints(constraints);
      element_forces = std::make_unique<rubberdyn::elements::SolidHexForces>(
        elements, std::vector<double>(elements.n_elements(), 1.));
      std::vector<unsigned int> body_of_surface;
      for (unsigned int s = 0; s < surfaces.size(); ++s)
        body_of_surface.push_back(s);
      contact_forces =
        std::make_unique<rubberdyn::contact::RigidSurfaceForces>(
          contact, body_of_surface);
      solver = std::make_unique<rubberdyn::time_integration::ExplicitSolver>(
        bar.dof_handler,
        std::vector<rubberdyn::model::ForceContribution *>{
          element_forces.get(), contact_forces.get()},
        bodies,
        &constraints,
        bar.partitioner,
        settings,
        bar.comm);
    }

    rubberdyn::elements::SolidHexElements                        elements;
    rubberdyn::contact::RigidSurfaceContact                      contact;
    std::vector<rubberdyn::model::RigidBody>                     bodies;
    rubberdyn::time_integration::KinematicConstraints            constraints;
    std::unique_ptr<rubberdyn::elements::SolidHexForces>         element_forces;
    std::unique_ptr<rubberdyn::contact::RigidSurfaceForces>      contact_forces;
    std::unique_ptr<rubberdyn::time_integration::ExplicitSolver> solver;
  };



  /** Arrival of a wave front at stations along the bar. */
  struct FrontArrivals
  {
    /** Station positions along the bar (mm). */
    std::vector<double> z;
    /** Arrival times (ms); negative if the front did not arrive. */
    std::vector<double> t;
    /** Least-squares slope of z over t (mm/ms). */
    double speed = 0.;
  };


  /**
   * Tracks the arrival of a velocity-step front of amplitude @p v0 (mm/ms)
   * at cross-sections z = stations (node layers) of a bar initially at
   * rest: the front arrives at a station when the mean axial velocity of
   * the nodes of that cross-section first reaches v0 / 2, interpolated
   * linearly between steps; the velocity the solver holds after a step
   * belongs to the half step t_n + dt / 2. Call record() from the solver's
   * monitor, on every rank.
   */
  class FrontTracker
  {
  public:
    FrontTracker(const Bar                 &bar,
                 const std::vector<double> &stations,
                 const double               v0)
      : comm(bar.comm)
      , v0(v0)
      , previous_v(stations.size(), 0.)
    {
      for (const double z : stations)
        {
          dofs.push_back(bar.axial_dofs_at(z));
          n_nodes.push_back(
            Utilities::MPI::sum<unsigned int>(dofs.back().size(), bar.comm));
          arrivals.z.push_back(z);
          arrivals.t.push_back(-1.);
        }
    }

    /** Take the solver's state after a step into account. */
    void
    record(const rubberdyn::time_integration::ExplicitSolver &solver)
    {
      const unsigned int  n = arrivals.z.size();
      const double        t = solver.time() + 0.5 * solver.time_step();
      std::vector<double> sums(n, 0.);
      for (unsigned int s = 0; s < n; ++s)
        for (const unsigned int i : dofs[s])
          sums[s] += solver.velocity().local_element(i);
      Utilities::MPI::sum(ArrayView<const double>(sums),
                          comm,
                          ArrayView<double>(sums));
      for (unsigned int s = 0; s < n; ++s)
        {
          const double v = sums[s] / n_nodes[s];
          if (arrivals.t[s] < 0. && v >= 0.5 * v0)
            arrivals.t[s] = previous_t + (t - previous_t) *
                                           (0.5 * v0 - previous_v[s]) /
                                           (v - previous_v[s]);
          previous_v[s] = v;
        }
      previous_t = t;
    }

    /** The arrivals so far and the least-squares fit z = z_0 + speed t. */
    FrontArrivals
    result() const
    {
      FrontArrivals      result = arrivals;
      const unsigned int n      = result.z.size();
      double             mean_t = 0., mean_z = 0.;
      for (unsigned int s = 0; s < n; ++s)
        {
          mean_t += result.t[s] / n;
          mean_z += result.z[s] / n;
        }
      double stt = 0., stz = 0.;
      for (unsigned int s = 0; s < n; ++s)
        {
          stt += (result.t[s] - mean_t) * (result.t[s] - mean_t);
          stz += (result.t[s] - mean_t) * (result.z[s] - mean_z);
        }
      result.speed = stz / stt;
      return result;
    }

  private:
    const MPI_Comm                         comm;
    const double                           v0;
    std::vector<std::vector<unsigned int>> dofs;
    std::vector<unsigned int>              n_nodes;
    FrontArrivals                          arrivals;
    std::vector<double>                    previous_v;
    double                                 previous_t = 0.;
  };


  /**
   * Push the end z = 0 of the bar, initially at rest, with a rigid plane
   * of huge mass (1e6 kg, millions of times the bar's, free along z)
   * moving at @p v0 (mm/ms): a step in velocity applied through penalty
   * contact with scale @p penalty_scale. With @p confined, four held
   * frictionless rigid planes on the lateral faces keep them from moving
   * outwards (a bar in a closely fitting rigid sleeve: uniaxial strain in
   * compression).
   *
   * The arrivals of the front at @p stations are those of FrontTracker.
   * The run ends at @p end_time (ms), before the reflection from the free
   * end returns to any station. The solver runs with @p settings.
   */
  inline FrontArrivals
  step_load_front(const Bar                                    &bar,
                  const rubberdyn::materials::MaterialModel<3> &material,
                  const double                                  v0,
                  const double                                  penalty_scale,
                  const bool                                    confined,
                  const std::vector<double>                    &stations,
                  const double                                  end_time,
                  const rubberdyn::time_integration::ExplicitSettings
                    &settings = {})
  {
    const Tensor<1, 3> ex({1., 0., 0.}), ey({0., 1., 0.}), ez({0., 0., 1.});
    std::set<types::boundary_id>                  ids    = {boundary::z_min};
    std::vector<rubberdyn::contact::RigidSurface> planes = {
      {Point<3>(0., 0., 0.), ez}};
    if (confined)
      {
        ids.insert(
          {boundary::x_min, boundary::x_max, boundary::y_min, boundary::y_max});
        const double a = bar.width;
        planes.push_back({Point<3>(0., 0., 0.), ex});
        planes.push_back({Point<3>(a, 0., 0.), -ex});
        planes.push_back({Point<3>(0., 0., 0.), ey});
        planes.push_back({Point<3>(0., a, 0.), -ey});
      }
    ExplicitBar model(bar, material, ids, planes, penalty_scale, settings);
    // The pusher; the confining planes stay held.
    model.bodies[0].mass        = 1e6;
    model.bodies[0].free[2]     = true;
    model.bodies[0].velocity[2] = v0;
    auto &solver                = *model.solver;

    FrontTracker tracker(bar, stations, v0);
    solver.run(end_time, [&]() { tracker.record(solver); });
    return tracker.result();
  }
} // namespace bar

#endif
