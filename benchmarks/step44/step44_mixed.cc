// deal.II step-44's default problem with rubberdyn's quasi-static Newton
// solver and its mixed u-p element (Q2-P1-P1, pressure and dilatation
// condensed per cell), or its F-bar element, for benchmarks/step44/compare.sh.
//
//   step44_mixed MESH [mixed|F-bar] [steps=10] [direct|AMG]
//
// MESH: step44_cube.geo meshed (tags there). The problem (step-44, in mm,
// ms, kg, kN, GPa): the unit cube, u_x = 0 on x = 0, u_y = 0 on y = 0,
// u_z = 0 on z = 0, u_x = u_z = 0 on the whole top y = 1; on its patch
// x < 0.5, z < 0.5 a dead load (per reference area, along -y) ramped
// linearly to 0.4 GPa (step-44: p0 = -4 / scale^2 Pa times the Pressure
// ratio p/p0 = 100, traction p N with the reference normal N: 400 MPa)
// in 10 equal load steps. Neo-Hooke mu = 80.194 MPa, nu = 0.4999: Yeoh
// with C10 = mu / 2, C20 = C30 = 0, K = 2 mu (1 + nu) / (3 (1 - 2 nu)),
// U = (K/4)(J^2 - 1 - 2 ln J) (the Simo-Taylor volumetric function, as in
// step-44).
//
// Why a driver and not a .prm: the Model study refuses tractions with the
// mixed element (model::SurfaceLoads integrates Q1 faces), so the load is
// applied as tests/verification/cook_membrane.cc does: the elements'
// residual minus lambda f_ext, f_ext the consistent nodal forces of the
// traction (Gauss 3x3 on the flat faces: exact for Q1 and Q2), lambda set
// to each load step's end before the solver takes that one step (a step
// that fails is halved here, with the load of the shorter step).
//
// Prints: cells, dofs, per load step the Newton and linear iterations and
// the vertical displacement of the top centre (0, 1, 0) (mm), and totals.
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/tria.h>

#include <rubberdyn/elements/dead_loaded_elements.h>
#include <rubberdyn/elements/mixed_up_elements.h>
#include <rubberdyn/elements/solid_hex_elements.h>
#include <rubberdyn/io/gmsh_mesh.h>
#include <rubberdyn/materials/yeoh.h>
#include <rubberdyn/time_integration/kinematic_constraints.h>
#include <rubberdyn/time_integration/quasi_static_solver.h>

#include <cstdlib>
#include <functional>
#include <iomanip>
#include <iostream>
#include <sstream>

using namespace dealii;
using namespace rubberdyn;



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (argc < 2)
    {
      std::cerr << "usage: step44_mixed MESH [mixed|F-bar] [steps=10] "
                   "[direct|AMG]\n";
      return 1;
    }
  const std::string  mesh    = argv[1];
  const bool         mixed   = argc < 3 || std::string(argv[2]) == "mixed";
  const unsigned int n_steps = argc > 3 ? std::atoi(argv[3]) : 10;
  const bool amg = argc > 4 && std::string(argv[4]) == "AMG";

  Triangulation<3> tria;
  io::read_gmsh_mesh(tria, mesh, "Mesh/Mesh file");
  FESystem<3>   fe(FE_Q<3>(mixed ? 2 : 1), 3);
  DoFHandler<3> dof_handler(tria);
  dof_handler.distribute_dofs(fe);
  const auto partitioner =
    std::make_shared<Utilities::MPI::Partitioner>(dof_handler.locally_owned_dofs(),
                                                  MPI_COMM_WORLD);
  std::cout << (mixed ? "mixed u-p (Q2-P1-P1)" : "F-bar (Q1)") << ": "
            << tria.n_global_active_cells() << " cells, "
            << dof_handler.n_dofs() << " dofs" << std::endl;

  const double mu = 0.080194, nu = 0.4999;
  const double K  = 2. * mu * (1. + nu) / (3. * (1. - 2. * nu));
  const materials::Yeoh<3> law(0.5 * mu,
                               0.,
                               0.,
                               std::array<double, 3>{{2. / K, 0., 0.}},
                               1e-6,
                               materials::VolumetricFunction::simo_taylor);

  std::unique_ptr<elements::ImplicitElements> element_layer;
  if (mixed)
    {
      auto e = std::make_unique<elements::MixedUPElements>();
      e->initialize(dof_handler,
                    partitioner,
                    {{{1}, &law, elements::Formulation::mixed_up}});
      element_layer = std::move(e);
    }
  else
    {
      auto e = std::make_unique<elements::SolidHexElements>();
      e->initialize(dof_handler,
                    partitioner,
                    {{{1}, &law, elements::Formulation::fbar}},
                    elements::ElementSettings());
      element_layer = std::move(e);
    }

  // f_ext = int N_i t dA on the patch (id 5), t = (0, -0.4, 0) GPa.
  const double traction = 0.4;
  VectorType   f_ext(partitioner);
  {
    const QGauss<2>                      quadrature(3);
    const MappingQ1<3>                   mapping;
    FEFaceValues<3>                      face_values(mapping,
                                fe,
                                quadrature,
                                update_values | update_JxW_values);
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      for (const unsigned int face : cell->face_indices())
        if (cell->at_boundary(face) && cell->face(face)->boundary_id() == 5)
          {
            face_values.reinit(cell, face);
            cell->get_dof_indices(dofs);
            for (unsigned int i = 0; i < dofs.size(); ++i)
              if (fe.system_to_component_index(i).first == 1)
                for (unsigned int q = 0; q < quadrature.size(); ++q)
                  f_ext[dofs[i]] -= traction * face_values.shape_value(i, q) *
                                    face_values.JxW(q);
          }
  }
  std::cout << "total load " << f_ext.l1_norm() << " kN (0.25 mm^2 x 0.4 GPa = 0.1)"
            << std::endl;
  elements::DeadLoadedElements loaded(*element_layer, f_ext);

  using time_integration::KinematicConstraints;
  KinematicConstraints constraints(dof_handler, partitioner);
  constraints.symmetry_plane("x0", 1, 0);
  constraints.symmetry_plane("bottom", 2, 1);
  constraints.symmetry_plane("z0", 3, 2);
  const auto zero = [](const Point<3> &, double) { return 0.; };
  for (const unsigned int d : {0u, 2u})
    constraints.prescribe("top", {4, 5}, d, KinematicConstraints::Kind::velocity,
                          zero, false);

  parameters::QuasiStatic settings;
  settings.initial_step  = 1.;
  settings.maximum_step  = 1.;
  settings.max_cutbacks  = 0;
  settings.linear_solver = amg ? parameters::QuasiStatic::LinearSolver::amg :
                                 parameters::QuasiStatic::LinearSolver::direct;
  time_integration::QuasiStaticSolver solver(
    dof_handler, partitioner, loaded, constraints, {}, settings, MPI_COMM_WORLD);
  solver.initialize();

  // The top centre's vertical dof (the node at (0, 1, 0)).
  std::map<types::global_dof_index, Point<3>> points;
  DoFTools::map_dofs_to_support_points(MappingQ1<3>(), dof_handler, points);
  types::global_dof_index top_centre = numbers::invalid_dof_index;
  {
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < dofs.size(); ++i)
          if (fe.system_to_component_index(i).first == 1 &&
              points[dofs[i]].distance(Point<3>(0., 1., 0.)) < 1e-9)
            top_centre = dofs[i];
      }
  }

  std::ostringstream                              log;
  unsigned int                                    halved = 0;
  const std::function<void(double, unsigned int)> advance =
    [&](const double t_end, const unsigned int depth) {
      const double t_start = solver.time();
      loaded.load_factor   = t_end;
      try
        {
          solver.run(t_end, log, []() {});
          const auto &step = solver.steps().back();
          std::cout << "t = " << std::setw(6) << std::left << t_end
                    << std::right << " Newton " << std::setw(2)
                    << step.iterations << ", linear " << std::setw(5)
                    << step.linear_iterations << ", top centre u_y "
                    << std::setprecision(6)
                    << solver.displacement()[top_centre] << " mm"
                    << std::endl;
        }
      catch (const time_integration::QuasiStaticFailure &)
        {
          if (depth >= 6)
            throw;
          ++halved;
          advance(0.5 * (t_start + t_end), depth + 1);
          advance(t_end, depth + 1);
        }
    };
  for (unsigned int k = 1; k <= n_steps; ++k)
    advance(double(k) / n_steps, 0);

  unsigned int newton = 0, linear = 0;
  for (const auto &step : solver.steps())
    {
      newton += step.iterations;
      linear += step.linear_iterations;
    }
  std::cout << "Finished: " << solver.steps().size() << " load steps, "
            << newton << " Newton iterations, " << linear
            << " linear iterations, " << halved << " halved steps; top centre u_y "
            << std::setprecision(6) << solver.displacement()[top_centre]
            << " mm" << std::endl;
  if (std::getenv("STEP44_LOG"))
    std::cout << log.str();
}
