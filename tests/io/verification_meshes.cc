// The verification meshes of the quasi-static solver
// (parameter_files/meshes/{tube,cook_membrane,compression_block}_N.msh,
// doc/verification/reference_solutions.md) read by rubberdyn::io::read_gmsh_mesh(), the reader
// every Model uses: cells, vertices, volume and area per boundary id against
// the closed forms of the meshed geometry, and the features the solver's
// tests rely on.
//
// - Tube (a = 10, b = 20, L = 10 mm, n through the wall, N = 8 n around, one
//   layer): n N cells, (n + 1) N 2 vertices (no seam where the annulus
//   closes), every vertex of the inner faces at r = a and of the outer at
//   r = b. Its hulls are polygons of N flat facets, so the closed forms are
//   those of the polygonal annulus: volume (N / 2) sin(2 pi / N)
//   (b^2 - a^2) L, inner hull 2 N a sin(pi / N) L, outer 2 N b sin(pi / N)
//   L, each end (N / 2) sin(2 pi / N) (b^2 - a^2). Its volume falls short of
//   the circular tube's pi (b^2 - a^2) L by 1 - sin(x) / x, x = 2 pi / N,
//   i.e. x^2 / 6 to leading order (second order in the element size):
//   printed and checked against x^2 / 6 within 1 %.
// - Cook's membrane (corners (0, 0), (48, 44), (48, 60), (0, 44), unit
//   thickness, n x n x 1): n^2 cells, volume 1440 mm^3 (the trapezoid's
//   area by the shoelace formula), clamped edge 44, loaded edge 16, each z
//   face 1440, the free edges sqrt(48^2 + 44^2) + sqrt(48^2 + 16^2) (times
//   the unit thickness); the tip (48, 60) and the middle of the loaded edge
//   (48, 52) are vertices, to 1e-9 mm (Gmsh's transfinite lines place nodes
//   up to 1e-10 mm along the line, tube.geo and cook_membrane.geo).
// - Compression block (10 mm cube, n^3): volume 1000, each symmetry face
//   and the top 100, the free sides 200.
// Tolerance 1e-12 relative for volumes and areas: flat faces, whose
// measures deal.II computes exactly up to rounding (as in
// tests/io/gmsh_mesh.cc); 1e-12 mm for radii (the nodes are printed to 16
// digits).
#include <deal.II/grid/tria.h>

#include <rubberdyn/io/gmsh_mesh.h>

#include <map>
#include <sstream>

#include "../tests.h"
#include "mesh_tests.h"

using namespace dealii;
using rubberdyn::io::read_gmsh_mesh;
using testing::check;
using testing::g6;
using testing::mesh_directory;
using testing::out;
using testing::sci;

namespace
{
  /** Read a shipped mesh (must succeed). */
  void
  read(Triangulation<3> &tria, const std::string &name)
  {
    try
      {
        read_gmsh_mesh(tria, mesh_directory + name, "Mesh/Mesh file");
      }
    catch (const std::exception &error)
      {
        check(false, name + " was refused: " + error.what());
      }
  }

  /**
   * Print and check the cell and vertex counts, the volume (material id 1,
   * the only one) and the area per boundary id against @p volume and
   * @p areas, which list every boundary id the mesh must have.
   */
  void
  summarize(const Triangulation<3>               &tria,
            const std::string                    &name,
            const unsigned int                    n_cells,
            const unsigned int                    n_vertices,
            const double                          volume,
            const std::map<unsigned int, double> &areas)
  {
    double measured_volume = 0.;
    std::map<unsigned int, std::pair<unsigned int, double>> boundaries;
    bool                                                    one_material = true;
    for (const auto &cell : tria.active_cell_iterators())
      {
        one_material = one_material && cell->material_id() == 1;
        measured_volume += cell->measure();
        for (const unsigned int f : cell->face_indices())
          if (cell->at_boundary(f))
            {
              auto &b = boundaries[cell->face(f)->boundary_id()];
              ++b.first;
              b.second += cell->face(f)->measure();
            }
      }
    out() << name << ": " << tria.n_active_cells() << " cells, "
          << tria.n_used_vertices() << " vertices, volume "
          << g6(measured_volume) << " mm^3" << std::endl;
    check(tria.n_active_cells() == n_cells, name + ": number of cells");
    check(tria.n_used_vertices() == n_vertices, name + ": number of vertices");
    check(one_material, name + ": every cell has the material id 1");
    const double volume_error = std::abs(measured_volume - volume) / volume;
    check(volume_error < 1e-12,
          name + ": volume, relative error " + sci(volume_error));
    check(boundaries.size() == areas.size(), name + ": the boundary ids");
    for (const auto &[id, count_and_area] : boundaries)
      {
        const auto expected = areas.find(id);
        check(expected != areas.end(),
              name + ": unexpected boundary id " + std::to_string(id));
        const double error =
          std::abs(count_and_area.second - expected->second) / expected->second;
        out() << "  boundary " << id << ": " << count_and_area.first
              << " faces, area " << g6(count_and_area.second) << " mm^2"
              << std::endl;
        check(error < 1e-12,
              name + ": area of boundary " + std::to_string(id) +
                ", relative error " + sci(error));
      }
    out() << "  volume and areas match the closed forms (relative error < "
             "1e-12)"
          << std::endl;
  }

  /** The largest |r - radius| of the vertices of the faces with @p id. */
  double
  radius_error(const Triangulation<3> &tria,
               const unsigned int      id,
               const double            radius)
  {
    double largest = 0.;
    for (const auto &cell : tria.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->at_boundary(f) && cell->face(f)->boundary_id() == id)
          for (const unsigned int v : cell->face(f)->vertex_indices())
            {
              const Point<3> &p = cell->face(f)->vertex(v);
              largest =
                std::max(largest, std::abs(std::hypot(p[0], p[1]) - radius));
            }
    return largest;
  }

  /** The distance from @p point to the nearest vertex. */
  double
  nearest_vertex(const Triangulation<3> &tria, const Point<3> &point)
  {
    double nearest = std::numeric_limits<double>::max();
    for (const auto &vertex : tria.get_vertices())
      nearest = std::min(nearest, vertex.distance(point));
    return nearest;
  }
} // namespace

int
main()
{
  // The tube.
  const double a = 10., b = 20., length = 10.;
  for (const unsigned int n : {4u, 8u, 16u})
    {
      const unsigned int n_around = 8 * n;
      const std::string  name     = "tube_" + std::to_string(n) + ".msh";
      Triangulation<3>   tria;
      read(tria, name);
      const double x       = 2. * M_PI / n_around;
      const double section = 0.5 * n_around * std::sin(x) * (b * b - a * a);
      summarize(tria,
                name,
                n * n_around,
                (n + 1) * n_around * 2,
                section * length,
                {{1, 2. * n_around * a * std::sin(0.5 * x) * length},
                 {2, 2. * n_around * b * std::sin(0.5 * x) * length},
                 {3, section},
                 {4, section}});
      const double inner = radius_error(tria, 1, a),
                   outer = radius_error(tria, 2, b);
      out() << "  inner vertices at r = a and outer at r = b to 1e-12 mm: "
            << (std::max(inner, outer) < 1e-12 ? "yes" :
                                                 sci(std::max(inner, outer)))
            << std::endl;
      check(inner < 1e-12 && outer < 1e-12, name + ": the hull radii");
      const double deficit = 1. - section / (M_PI * (b * b - a * a));
      out() << "  volume short of pi (b^2 - a^2) L by " << sci(deficit)
            << " (leading order x^2 / 6 = " << sci(x * x / 6.)
            << ", x = 2 pi / " << n_around << ")" << std::endl;
      check(std::abs(deficit / (x * x / 6.) - 1.) < 0.01,
            name + ": the polygon's deficit is x^2 / 6 to leading order");
    }

  // Cook's membrane.
  const double free_edges = std::hypot(48., 44.) + std::hypot(48., 16.);
  for (const unsigned int n : {2u, 4u, 8u, 16u, 32u, 64u})
    {
      const std::string name = "cook_membrane_" + std::to_string(n) + ".msh";
      Triangulation<3>  tria;
      read(tria, name);
      summarize(tria,
                name,
                n * n,
                (n + 1) * (n + 1) * 2,
                1440.,
                {{1, 44.}, {2, 16.}, {3, 1440.}, {4, 1440.}, {5, free_edges}});
      const double tip    = nearest_vertex(tria, Point<3>(48., 60., 0.));
      const double middle = nearest_vertex(tria, Point<3>(48., 52., 0.));
      out() << "  (48, 60, 0) and (48, 52, 0) are vertices to 1e-9 mm: "
            << (std::max(tip, middle) < 1e-9 ? "yes" :
                                               sci(std::max(tip, middle)))
            << std::endl;
      check(tip < 1e-9 && middle < 1e-9, name + ": the tip vertices");
    }

  // The compression block.
  for (const unsigned int n : {4u, 8u})
    {
      const std::string name =
        "compression_block_" + std::to_string(n) + ".msh";
      Triangulation<3> tria;
      read(tria, name);
      summarize(tria,
                name,
                n * n * n,
                (n + 1) * (n + 1) * (n + 1),
                1000.,
                {{1, 100.}, {2, 100.}, {3, 100.}, {4, 100.}, {5, 200.}});
    }
}
