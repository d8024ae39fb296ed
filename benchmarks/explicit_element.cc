// Cost of the explicit element kernel: SolidHexElements::compute_forces on
// an F-bar Yeoh (chapter-4 rubber) mesh of n x n x n hexahedra, distorted
// and compressed so that every Gauss point sees a general F, in ns per
// element-cycle (wall time x ranks / (cells x evaluations)).
//
//   benchmarks/explicit_element [n=48] [evaluations=100] [F-bar|displacement]
//   mpirun -np 2 benchmarks/explicit_element 48 100
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

#include <rubberdyn/elements/solid_hex_elements.h>
#include <rubberdyn/materials/yeoh.h>

#include <chrono>
#include <cmath>
#include <iostream>
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

  // A 24 mm cube of n^3 cells with wavy interior nodes (non-parallelepiped
  // elements).
  parallel::distributed::Triangulation<3> triangulation(comm);
  GridGenerator::subdivided_hyper_cube(triangulation, n, 0., 24.);
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
  IndexSet relevant;
  DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
  const auto partitioner = std::make_shared<Utilities::MPI::Partitioner>(
    dof_handler.locally_owned_dofs(), relevant, comm);

  const materials::Yeoh<3> rubber(0.55e-3, -0.05e-3, 0.015e-3,
                                  std::array<double, 3>{{1. / 0.331, 0., 0.}},
                                  1.1e-6);
  elements::SolidHexElements elements;
  elements.initialize(dof_handler, partitioner, {{0, &rubber}},
                      {fbar ? elements::Formulation::fbar :
                              elements::Formulation::displacement,
                       0.06, 1.5});

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
  if (Utilities::MPI::this_mpi_process(comm) == 0)
    std::cout << (fbar ? "F-bar" : "displacement") << " Yeoh hexahedra: "
              << triangulation.n_global_active_cells() << " cells, " << ranks
              << " ranks, " << evaluations << " evaluations, "
              << 1e9 * wall * ranks /
                   (double(triangulation.n_global_active_cells()) * evaluations)
              << " ns per element-cycle (internal energy " << total_energy
              << " J)" << std::endl;
}
