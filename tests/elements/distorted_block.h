// The mesh of the element tests: a block of nx x ny x 1 cubes of 5 mm,
// every node moved by the smooth map y_d = x_d + 0.1 sin(0.7 x_{d+1} + d)
// x_{d+2} (indices mod 3), so that no two cells are alike and none is a
// parallelepiped (on which an element's errors could cancel), while none
// comes near inverting.
#ifndef rubberdyn_tests_elements_distorted_block_h
#define rubberdyn_tests_elements_distorted_block_h

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>

#include <cmath>

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
} // namespace fixtures

#endif
