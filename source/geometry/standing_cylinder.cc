#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria.h>

#include <rubberdyn/geometry/standing_cylinder.h>

namespace rubberdyn
{
  namespace geometry
  {
    void
    make_standing_cylinder(dealii::Triangulation<3, 3> &triangulation,
                           const double                 diameter,
                           const double                 height,
                           const unsigned int           refinement)
    {
      using namespace dealii;
      // deal.II's cylinder lies along x, centred at the origin, with
      // boundary ids 0 (hull), 1 (x = -h/2) and 2 (x = +h/2); turn it so
      // that its axis is z and it stands on z = 0 (the ids then mean hull,
      // bottom, top).
      Triangulation<3> coarse;
      GridGenerator::subdivided_cylinder(coarse, 2, diameter / 2., height / 2.);
      GridTools::transform(
        [&](const Point<3> &x) {
          return Point<3>(x[1], x[2], x[0] + height / 2.);
        },
        coarse);
      triangulation.copy_triangulation(coarse);
      triangulation.set_manifold(0, CylindricalManifold<3>(2));
      triangulation.refine_global(refinement);
    }
  } // namespace geometry
} // namespace rubberdyn
