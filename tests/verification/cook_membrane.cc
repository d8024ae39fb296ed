// Cook's membrane (doc/verification/reference_solutions.md section 2), plane strain, nearly
// incompressible neo-Hooke (G = 80.1938 MPa, K = 400 942 MPa), total shear
// load 100 N on the 16 mm x 1 mm edge x = 48 (boundary id 2): the vertical
// displacement of the tip C = (48, 60) by the quasi-static Newton solver
// (time_integration::QuasiStaticSolver), for the F-bar element
// (SolidHexElements) and the mixed u-p element (MixedUPElements), on the
// structured meshes cook_membrane_n, n x n x 1 cells.
//
// The load: the quasi-static Model study applies tractions through
// model::SurfaceLoads, which integrates bilinear faces of Q1 nodes and is
// refused with the mixed element's Q2 dofs, so this
// driver builds the solver's pieces itself (mesh, dofs, elements,
// KinematicConstraints) and wraps the elements in an ImplicitElements whose
// residual is f_int(u) - lambda f_ext, f_ext the consistent nodal forces of
// the uniform dead traction t_y = 0.00625 GPa per reference area, f_i =
// int N_i t dA over the faces of id 2 (Gauss 3x3: exact on these flat faces
// for Q1 and Q2). The load factor lambda is set to the end of each load
// step before the solver takes that one step (10 steps of 0.1; a step that
// does not converge is halved by the driver, with the load of the shorter
// step, since the solver's own cut-back would keep the end load): every
// reported state is an exact equilibrium of f_int = lambda f_ext, the load
// path of a traction of function t (the F-bar values equal those of the
// Model study with its traction, tests/model/cook_membrane_quasi_static.sh,
// to the 5 digits printed there). Boundary conditions: the clamped edge
// (id 1) fixed, u_z = 0 on both faces z = 0 and z = 1 (ids 3 and 4; every
// node lies on one).
//
// References: the converged 6.908 mm (6.9083; Elguedj, Bazilevs, Calo and
// Hughes, CMAME 197 (2008) 2732, 128 x 128) and the F-bar values of
// OpenGeoSys (CooksMembraneFbar.py, 6.86 to 6.89 at 20 to 30 elements a
// side), doc/verification/reference_solutions.md.
// Criteria (issue 9): for both elements the tip displacement grows
// monotonically with n, and the finest level computed is within 1 % of
// 6.908; every load step converged in at most 8 Newton iterations. The
// test runs F-bar to n = 32 and the mixed element to n = 8 (n = 16 takes
// 13 s, n = 32 69 s, n = 64 11 minutes); with COOK_FBAR_MAX_N=64
// COOK_MIXED_MAX_N=64 in the environment (benchmarks/cook_membrane.sh) it
// runs both to n = 64 and also
// asserts n = 32 within 1 % of 6.908 and of its own n = 64 value. The
// measured tables are in doc/quasi_static.md.
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

#include <chrono>
#include <cstdlib>
#include <functional>
#include <sstream>

#include "../tests.h"

using namespace dealii;
using namespace rubberdyn;
using testing::check;
using testing::out;

namespace
{

  struct Run
  {
    double       tip;
    unsigned int most_iterations;
    unsigned int cutbacks;
    double       seconds;
  };

  Run
  cook(const unsigned int n, const bool mixed)
  {
    const auto       start = std::chrono::steady_clock::now();
    Triangulation<3> tria;
    io::read_gmsh_mesh(tria,
                       std::string(SOURCE_DIR) +
                         "/../../parameter_files/meshes/cook_membrane_" +
                         std::to_string(n) + ".msh",
                       "Mesh/Mesh file");
    FESystem<3>   fe(FE_Q<3>(mixed ? 2 : 1), 3);
    DoFHandler<3> dof_handler(tria);
    dof_handler.distribute_dofs(fe);
    const auto partitioner = std::make_shared<Utilities::MPI::Partitioner>(
      dof_handler.locally_owned_dofs(),
      MPI_COMM_WORLD);

    // Neo-Hooke: Yeoh with C10 = G/2, U = (K/2)(J - 1)^2, K = 400.942 GPa.
    const double             G = 0.0801938, K = 400.942;
    const materials::Yeoh<3> law(0.5 * G,
                                 0.,
                                 0.,
                                 std::array<double, 3>{{2. / K, 0., 0.}},
                                 1e-6);

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

    // f_ext = int N_i t dA on the loaded edge, t = (0, 0.00625, 0) GPa.
    VectorType f_ext(partitioner);
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
          if (cell->at_boundary(face) && cell->face(face)->boundary_id() == 2)
            {
              face_values.reinit(cell, face);
              cell->get_dof_indices(dofs);
              for (unsigned int i = 0; i < dofs.size(); ++i)
                if (fe.system_to_component_index(i).first == 1)
                  for (unsigned int q = 0; q < quadrature.size(); ++q)
                    f_ext[dofs[i]] += 0.00625 * face_values.shape_value(i, q) *
                                      face_values.JxW(q);
            }
    }
    check(std::abs(f_ext.l1_norm() - 0.1) < 1e-12, "total load 0.1 kN");
    elements::DeadLoadedElements loaded(*element_layer, f_ext);

    time_integration::KinematicConstraints constraints(dof_handler,
                                                       partitioner);
    constraints.fix("clamped", 1);
    constraints.symmetry_plane("z0", 3, 2);
    constraints.symmetry_plane("z1", 4, 2);

    // One solver step per run() (its own cut-backs off: they would keep
    // the end load); the driver halves a step that fails, with the load
    // of the shorter step, as the solver's cut-back would.
    parameters::QuasiStatic settings;
    settings.initial_step  = 1.;
    settings.maximum_step  = 1.;
    settings.max_cutbacks  = 0;
    settings.linear_solver = parameters::QuasiStatic::LinearSolver::direct;
    time_integration::QuasiStaticSolver solver(dof_handler,
                                               partitioner,
                                               loaded,
                                               constraints,
                                               {},
                                               settings,
                                               MPI_COMM_WORLD);
    solver.initialize();
    std::ostringstream                              log;
    unsigned int                                    cutbacks = 0;
    const std::function<void(double, unsigned int)> advance =
      [&](const double t_end, const unsigned int depth) {
        const double t_start = solver.time();
        loaded.load_factor   = t_end;
        try
          {
            solver.run(t_end, log, []() {});
          }
        catch (const time_integration::QuasiStaticFailure &)
          {
            check(depth < 6, "at most 6 halvings of a load step");
            ++cutbacks;
            advance(0.5 * (t_start + t_end), depth + 1);
            advance(t_end, depth + 1);
          }
      };
    for (unsigned int k = 1; k <= 10; ++k)
      advance(0.1 * k, 0);

    // The tip's vertical displacement (the node at (48, 60, 0)).
    std::map<types::global_dof_index, Point<3>> points;
    DoFTools::map_dofs_to_support_points(MappingQ1<3>(), dof_handler, points);
    const std::vector<unsigned int> component = [&]() {
      std::vector<unsigned int>            c(dof_handler.n_dofs());
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            c[dofs[i]] = fe.system_to_component_index(i).first;
        }
      return c;
    }();
    double tip = std::numeric_limits<double>::quiet_NaN();
    for (const auto &[dof, X] : points)
      if (component[dof] == 1 && X.distance(Point<3>(48., 60., 0.)) < 1e-9)
        tip = solver.displacement()[dof];
    unsigned int most = 0;
    for (const auto &step : solver.steps())
      most = std::max(most, step.iterations);
    return {tip,
            most,
            cutbacks,
            std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                          start)
              .count()};
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const char                      *max_env = std::getenv("COOK_MIXED_MAX_N");
  const unsigned int mixed_max_n           = max_env ? std::atoi(max_env) : 8;
  const char        *fbar_env              = std::getenv("COOK_FBAR_MAX_N");
  const unsigned int fbar_max_n = fbar_env ? std::atoi(fbar_env) : 32;
  const double       reference  = 6.908;

  bool all_ok = true;
  for (const bool mixed : {false, true})
    {
      const unsigned int max_n = mixed ? mixed_max_n : fbar_max_n;
      out() << (mixed ? "mixed u-p" : "F-bar") << ": tip u_y (mm)" << std::endl;
      std::vector<double> tips;
      bool                monotone = true;
      unsigned int        most     = 0;
      for (unsigned int n = 2; n <= max_n; n *= 2)
        {
          const Run r = cook(n, mixed);
          if (!tips.empty() && !(r.tip > tips.back()))
            monotone = false;
          tips.push_back(r.tip);
          most = std::max(most, r.most_iterations);
          out() << "  n = " << n << ": " << std::fixed << std::setprecision(3)
                << r.tip << ", " << std::setprecision(2)
                << 100. * (r.tip / reference - 1.) << " % from 6.908"
                << std::defaultfloat << std::endl;
          std::cerr << (mixed ? "mixed u-p" : "F-bar") << " n = " << n
                    << ": tip " << std::setprecision(7) << r.tip << ", "
                    << r.most_iterations << " iterations at most, "
                    << r.cutbacks << " halved steps, " << std::setprecision(3)
                    << r.seconds << " s" << std::endl;
        }
      // The finest level within 1 % of 6.908; with n = 64 computed, n = 32
      // within 1 % of it too.
      const double finest         = tips.back();
      const bool   near_reference = std::abs(finest / reference - 1.) < 0.01;
      out() << "  monotone: " << (monotone ? "yes" : "no")
            << "; n = " << (1u << tips.size())
            << " within 1 % of 6.908: " << (near_reference ? "yes" : "no");
      bool near_own = true;
      if (max_n >= 64)
        {
          near_own = std::abs(tips[tips.size() - 2] / finest - 1.) < 0.01 &&
                     std::abs(tips[tips.size() - 2] / reference - 1.) < 0.01;
          out() << "; n = 32 within 1 % of 6.908 and of n = 64: "
                << (near_own ? "yes" : "no");
        }
      out() << "; at most 8 Newton iterations a step: "
            << (most <= 8 ? "yes" : "no") << std::endl;
      all_ok = all_ok && monotone && near_reference && near_own && most <= 8;
    }
  check(all_ok, "Cook's membrane converges to 6.908 within 1 %");
}
