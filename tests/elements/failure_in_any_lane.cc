// An element that inverts is reported with its own cell, whatever its lane:
// a row of 2 L - 1 cells of 1 mm (L = internal::lanes, 8) makes one full
// block (lanes 0 to L-1) and one block of L - 1 elements plus a padding
// lane. For each cell in turn, the nodes of
// its face x = c + 1 are pushed back by 1.5 mm, past its other face:
// that cell inverts, its right neighbour only stretches. The failure must
// name that cell (its id and reference centre), for both formulations,
// every lane of the full block and of the partly filled one; no
// other element may be reported, and the elements of the other block still
// contribute their forces. The kernel masks padding lanes itself (they
// see F = I in the law) instead of relying on their copying lane 0.
#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <rubberdyn/elements/solid_hex_elements.h>
#include <rubberdyn/materials/elastic.h>

#include <string>

#include "../tests.h"

using namespace dealii;
using namespace rubberdyn;
using testing::check;
using testing::out;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  constexpr unsigned int           lanes   = elements::internal::lanes;
  const unsigned int               n_cells = 2 * lanes - 1;
  Triangulation<3>                 tria;
  GridGenerator::subdivided_hyper_rectangle(tria,
                                            {n_cells, 1, 1},
                                            Point<3>(0., 0., 0.),
                                            Point<3>(n_cells, 1., 1.));
  FESystem<3>   fe(FE_Q<3>(1), 3);
  DoFHandler<3> dof_handler(tria);
  dof_handler.distribute_dofs(fe);
  const auto partitioner = std::make_shared<Utilities::MPI::Partitioner>(
    dof_handler.locally_owned_dofs(), MPI_COMM_SELF);
  const materials::Elastic<3> steel(210., 0.3, 7.85e-6);

  bool all_right = true;
  for (const auto formulation :
       {elements::Formulation::fbar, elements::Formulation::displacement})
    {
      elements::SolidHexElements hexes;
      hexes.initialize(dof_handler,
                       partitioner,
                       {{{0}, &steel, formulation}},
                       elements::ElementSettings());
      check(hexes.n_elements() == n_cells, "one element per cell");
      for (const auto &inverted : dof_handler.active_cell_iterators())
        {
          const unsigned int c = inverted->active_cell_index();
          // A uniform 0.1 % stretch along x everywhere (every element has
          // a stress), then the push.
          VectorType u(partitioner), v(partitioner), f(partitioner);
          std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
          for (const auto &cell : dof_handler.active_cell_iterators())
            {
              cell->get_dof_indices(dofs);
              for (unsigned int i = 0; i < dofs.size(); ++i)
                {
                  const auto ci = fe.system_to_component_index(i);
                  if (ci.first == 0)
                    u[dofs[i]] = 1e-3 * cell->vertex(ci.second)[0];
                }
            }
          inverted->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            {
              const auto ci = fe.system_to_component_index(i);
              // Vertices 1, 3, 5, 7: the face x = c + 1.
              if (ci.first == 0 && ci.second % 2 == 1)
                u[dofs[i]] -= 1.5;
            }
          elements::ElementStepResult result;
          hexes.compute_forces(
            u, v, std::vector<double>(n_cells, 1.), f, result);
          const bool right =
            result.failure.failed &&
            result.failure.cell_id == inverted->id().to_string() &&
            result.failure.position.distance(inverted->center()) < 1e-12 &&
            (result.failure.kind ==
               elements::FailureKind::inverted_gauss_point ||
             result.failure.kind == elements::FailureKind::inverted_centre);
          // The block that did not fail still adds its (nonzero) forces.
          const bool other_block_counts = (f.linfty_norm() > 0.);
          out() << (formulation == elements::Formulation::fbar ?
                      "F-bar" :
                      "displacement")
                << ", cell " << c << " (block " << c / lanes << ", lane "
                << c % lanes
                << (c / lanes == 1 ?
                      ", block of " + std::to_string(lanes - 1) :
                      std::string())
                << ") inverted: reported " << result.failure.cell_id << " at "
                << result.failure.position << ": "
                << result.failure.message << "; right cell: "
                << (right ? "yes" : "no") << ", other block's forces added: "
                << (other_block_counts ? "yes" : "no") << std::endl;
          all_right = all_right && right && other_block_counts;
        }
    }
  check(all_right, "every inverted element is reported with its cell");
}
