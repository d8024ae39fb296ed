// Cost of the explicit element kernel and of whole explicit time steps, in
// ns per element-cycle (wall time x ranks / (cells x evaluations)):
// 1. SolidHexElements::compute_forces on an F-bar Yeoh (chapter-4 rubber)
//    mesh of n x n x n hexahedra, distorted and compressed so that every
//    Gauss point sees a general F;
// 2. ExplicitSolver time steps of the same block squeezed between two
//    rigid plates (penalty contact on both end faces), with the breakdown
//    into element forces, contact, vector updates and communication, and
//    the cost of one ParaView output.
//
//   benchmarks/explicit_element [n=48] [evaluations=100] [F-bar|displacement]
//                               [Yeoh|Elastic|J2|J2-elastic]
//   mpirun -np 2 benchmarks/explicit_element 48 100
//
// The law (default Yeoh, the chapter-4 rubber): `Elastic` and `J2` are
// steel (E = 210 GPa, nu = 0.3; J2 as bolt grade 10.9, yield 0.94 GPa):
// under the benchmark's 20 % compression every J2 point yields (each
// evaluation starts from the virgin history, so every one takes the
// return mapping); `J2-elastic` is the same law with a yield stress of
// 1e3 GPa, so that every point takes the elastic path with history, as
// most metal points do in a step of an impact.
//
// n = 48 gives 110592 cells. Under valgrind --tool=callgrind use a small n
// (e.g. 16, 20 evaluations): instruction counts do not depend on the load
// of the machine, so they compare versions of the kernel reliably.
#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>

#include <rubberdyn/base/partitioner.h>
#include <rubberdyn/contact/rigid_surface_contact.h>
#include <rubberdyn/elements/solid_hex_elements.h>
#include <rubberdyn/materials/elastic.h>
#include <rubberdyn/materials/hardening_curve.h>
#include <rubberdyn/materials/j2_plasticity.h>
#include <rubberdyn/materials/yeoh.h>
#include <rubberdyn/postprocess/field_output.h>
#include <rubberdyn/contact/rigid_surface_forces.h>
#include <rubberdyn/elements/solid_hex_forces.h>
#include <rubberdyn/time_integration/explicit_solver.h>

#include <filesystem>

#include <chrono>
#include <cmath>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>

using namespace dealii;
using namespace rubberdyn;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm     comm = MPI_COMM_WORLD;
  const unsigned int n = argc > 1 ? std::stoi(argv[1]) : 48;
  const unsigned int evaluations = argc > 2 ? std::stoi(argv[2]) : 100;
  const bool fbar = !(argc > 3 && std::string(argv[3]) == "displacement");
  const std::string law_name = argc > 4 ? argv[4] : "Yeoh";

  // A 24 mm cube of n^3 cells with wavy interior nodes (non-parallelepiped
  // elements).
  parallel::distributed::Triangulation<3> triangulation(comm);
  // colorize: boundary ids 4 and 5 are the faces z = 0 and z = 24 mm.
  GridGenerator::subdivided_hyper_rectangle(triangulation, {n, n, n},
                                            Point<3>(0., 0., 0.),
                                            Point<3>(24., 24., 24.), true);
  for (const auto &cell : triangulation.active_cell_iterators())
    cell->set_material_id(0);
  GridTools::transform(
    [](const Point<3> &x) {
      Point<3> y = x;
      for (unsigned int d = 0; d < 3; ++d)
        y[d] += 0.2 * std::sin(0.5 * x[(d + 1) % 3]) *
                std::sin(0.3 * x[(d + 2) % 3]);
      return y;
    },
    triangulation);

  const FESystem<3> fe(FE_Q<3>(1), 3);
  DoFHandler<3>     dof_handler(triangulation);
  dof_handler.distribute_dofs(fe);
  const auto partitioner = rubberdyn::ghosted_partitioner(dof_handler);

  std::unique_ptr<materials::MaterialModel<3>> law;
  if (law_name == "Yeoh")
    law = std::make_unique<materials::Yeoh<3>>(
      0.55e-3, -0.05e-3, 0.015e-3,
      std::array<double, 3>{{1. / 0.331, 0., 0.}}, 1.1e-6);
  else if (law_name == "Elastic")
    law = std::make_unique<materials::Elastic<3>>(210., 0.3, 7.85e-6);
  else if (law_name == "J2" || law_name == "J2-elastic")
    law = std::make_unique<materials::J2Plasticity<3>>(
      210., 0.3, 7.85e-6,
      materials::HardeningCurve(law_name == "J2" ? 0.94 : 1e3, {0.08},
                                {law_name == "J2" ? 1.04 : 1.1e3},
                                "benchmark"));
  else
    throw std::runtime_error("unknown law '" + law_name +
                             "' (Yeoh, Elastic, J2 or J2-elastic)");
  const materials::MaterialModel<3> &rubber = *law;
  elements::SolidHexElements elements;
  elements.initialize(dof_handler, partitioner,
                      {{{0}, &rubber,
                        fbar ? elements::Formulation::fbar :
                               elements::Formulation::displacement}},
                      {0.06, 1.5});

  // 20 % axial compression with the incompressible lateral expansion,
  // plus a shear, and a compressing velocity field (bulk viscosity on).
  VectorType u(partitioner), v(partitioner), f(partitioner);
  std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
  for (const auto &cell : dof_handler.active_cell_iterators())
    if (cell->is_locally_owned() || cell->is_ghost())
      {
        cell->get_dof_indices(dof_indices);
        for (unsigned int i = 0; i < dof_indices.size(); ++i)
          if (partitioner->in_local_range(dof_indices[i]) ||
              partitioner->is_ghost_entry(dof_indices[i]))
            {
              const auto         ci = fe.system_to_component_index(i);
              const Point<3>     X  = cell->vertex(ci.second);
              const unsigned int d  = ci.first;
              const double stretch[3] = {1. / std::sqrt(0.8) - 1.,
                                         1. / std::sqrt(0.8) - 1., -0.2};
              u[dof_indices[i]] = stretch[d] * X[d] + (d == 0 ? 0.05 * X[2] : 0.);
              v[dof_indices[i]] = -0.1 * stretch[d] * X[d];
            }
      }

  const std::vector<double> density_scaling(elements.n_elements(), 1.);
  double                    energy = 0.;
  const auto                start  = std::chrono::steady_clock::now();
  for (unsigned int i = 0; i < evaluations; ++i)
    {
      f = 0.;
      elements::ElementStepResult result;
      elements.compute_forces(u, v, density_scaling, f, result);
      AssertThrow(!result.failure.failed, ExcMessage(result.failure.message));
      energy = result.internal_energy;
    }
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
      .count();
  const double total_energy = Utilities::MPI::sum(energy, comm);
  const double wall         = Utilities::MPI::max(seconds, comm);
  const unsigned int ranks  = Utilities::MPI::n_mpi_processes(comm);
  const double n_cells = triangulation.n_global_active_cells();
  const bool   root    = Utilities::MPI::this_mpi_process(comm) == 0;
  if (root)
    std::cout << (fbar ? "F-bar" : "displacement") << " " << law_name
              << " hexahedra: "
              << n_cells << " cells, " << ranks << " ranks" << std::endl
              << "element kernel alone: " << evaluations << " evaluations, "
              << 1e9 * wall * ranks / (n_cells * evaluations)
              << " ns per element-cycle (internal energy " << total_energy
              << " J)" << std::endl;

  // Whole explicit steps: the undeformed block between two plates, the
  // top one a 50 kg impactor at 2 m/s, for `evaluations` steps.
  const Tensor<1, 3>           up({0., 0., 1.});
  contact::RigidSurfaceContact plates;
  plates.initialize(dof_handler, partitioner, {4, 5}, {rubber.bulk_modulus()},
                    0.1,
                    {{Point<3>(0., 0., 0.), up},
                     {Point<3>(0., 0., 24.), -up}});
  std::vector<model::RigidBody> bodies(2);
  bodies[1].mass        = 50.;
  bodies[1].free[2]     = true;
  bodies[1].velocity[2] = -2.;
  elements::SolidHexForces         element_forces(elements, density_scaling);
  contact::RigidSurfaceForces      plate_forces(plates, {0, 1});
  time_integration::ExplicitSolver solver(dof_handler,
                                          {&element_forces, &plate_forces},
                                          bodies,
                                          nullptr,
                                          partitioner,
                                          {},
                                          comm);
  const std::vector<double> steps     = elements.reference_time_steps();
  const double              min_step = Utilities::MPI::min(
    *std::min_element(steps.begin(), steps.end()), comm);
  const auto step_start = std::chrono::steady_clock::now();
  solver.run(0.9 * min_step * evaluations, []() {});
  const double step_wall = Utilities::MPI::max(
    std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                  step_start)
      .count(),
    comm);
  const auto   timings = solver.timings();
  const double cycles  = n_cells * solver.step() / ranks;
  const auto   ns      = [&](const double seconds) {
    return 1e9 * Utilities::MPI::max(seconds, comm) / cycles;
  };
  const double element_ns = ns(timings.element_forces),
               contact_ns = ns(timings.contact),
               update_ns  = ns(timings.vector_updates),
               comm_ns    = ns(timings.communication);

  // One ParaView output of the whole mesh.
  const std::string directory = "explicit_element_output";
  std::filesystem::create_directories(directory);
  postprocess::FieldOutput output(directory, "solution", comm);
  const auto averages =
    elements.cell_averages(solver.displacement(), triangulation.n_active_cells());
  const auto output_start = std::chrono::steady_clock::now();
  output.write(dof_handler, solver.displacement(), solver.velocity(),
               {{"J", averages.jacobian}}, solver.time());
  const double output_wall = Utilities::MPI::max(
    std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                  output_start)
      .count(),
    comm);
  if (root)
    {
      std::filesystem::remove_all(directory);
      std::cout << "explicit steps: " << solver.step() << " steps, "
                << 1e9 * step_wall * ranks / (n_cells * solver.step())
                << " ns per element-cycle, of which (slowest rank)"
                << std::endl
                << "  element forces  " << element_ns << std::endl
                << "  contact         " << contact_ns << std::endl
                << "  vector updates  " << update_ns << std::endl
                << "  communication   " << comm_ns << std::endl
                << "one ParaView output (pvtu, displacement, velocity, J): "
                << output_wall << " s = " << 1e9 * output_wall * ranks / n_cells
                << " ns per element" << std::endl;
    }
}
