// The mesh of the element tests: a block of nx x ny x 1 cubes of 5 mm,
// every node moved by the smooth map y_d = x_d + 0.1 sin(0.7 x_{d+1} + d)
// x_{d+2} (indices mod 3), so that no two cells are alike and none is a
// parallelepiped (on which an element's errors could cancel), while none
// comes near inverting.
#ifndef rubberdyn_tests_elements_distorted_block_h
#define rubberdyn_tests_elements_distorted_block_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/partitioner.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>

#include <cmath>
#include <memory>

namespace fixtures
{
  /** Fill @p tria with the distorted block of @p nx x @p ny x 1 cells. */
  inline void
  make_distorted_block(dealii::Triangulation<3> &tria,
                       const unsigned int        nx,
                       const unsigned int        ny)
  {
    using dealii::Point;
    dealii::GridGenerator::subdivided_hyper_rectangle(tria,
                                                      {nx, ny, 1},
                                                      Point<3>(0., 0., 0.),
                                                      Point<3>(5. * nx,
                                                               5. * ny,
                                                               5.));
    dealii::GridTools::transform(
      [](const Point<3> &x) {
        Point<3> y = x;
        for (unsigned int d = 0; d < 3; ++d)
          y[d] += 0.1 * std::sin(0.7 * x[(d + 1) % 3] + d) * x[(d + 2) % 3];
        return y;
      },
      tria);
  }

  /**
   * The distorted block with its vector-valued FE_Q(@p degree)^3 dofs on
   * one rank: what the element tests evaluate elements on.
   */
  struct DistortedBlock
  {
    DistortedBlock(const unsigned int nx,
                   const unsigned int ny,
                   const unsigned int degree = 1)
      : fe(dealii::FE_Q<3>(degree), 3)
    {
      make_distorted_block(tria, nx, ny);
      dof_handler.reinit(tria);
      dof_handler.distribute_dofs(fe);
      partitioner = std::make_shared<dealii::Utilities::MPI::Partitioner>(
        dof_handler.locally_owned_dofs(), MPI_COMM_SELF);
    }

    dealii::Triangulation<3>                                   tria;
    dealii::FESystem<3>                                        fe;
    dealii::DoFHandler<3>                                      dof_handler;
    std::shared_ptr<const dealii::Utilities::MPI::Partitioner> partitioner;
  };
} // namespace fixtures

#endif
