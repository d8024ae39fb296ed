/**
 * @file
 * Writes the drop test's rubber cylinder as a CalculiX/Abaqus input include,
 * so that CalculiX (benchmarks/calculix/drop_test.inp) runs on the very mesh
 * that rubberdyn's drop test builds.
 *
 * Usage: export_drop_test_mesh [REFINEMENT [OUTPUT [TYPE]]]
 *   REFINEMENT  global refinement of
 * rubberdyn::geometry::make_standing_cylinder (default 2 = 640 cells; 3 = 5120
 * cells) OUTPUT      file name (default drop_test_mesh.inp) TYPE CalculiX
 * element type: C3D8 (default, full integration), C3D8R (reduced integration)
 * or C3D8I (incompatible modes); all three share the node ordering and face
 * labels.
 *
 * The cylinder has diameter 25 mm and height 24 mm (reference study,
 * chapter 4). The file defines
 *   *NODE (NSET=RUBBER_NODES), *ELEMENT,TYPE=TYPE (ELSET=RUBBER),
 *   node sets BOTTOM_NODES (z = 0), TOP_NODES (z = 24) and HULL_NODES,
 *   element-face surfaces BOTTOM, TOP and HULL (the faces with boundary ids
 *   cylinder_boundary::bottom, ::top and ::hull).
 * Units: mm.
 */

#include <deal.II/base/geometry_info.h>
#include <deal.II/grid/tria.h>

#include <rubberdyn/geometry/standing_cylinder.h>

#include <array>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{
  using namespace dealii;

  /**
   * Abaqus C3D8 node k (0-based) is deal.II vertex c3d8_to_dealii[k]:
   * deal.II numbers a hexahedron's vertices lexicographically (x fastest,
   * then y, then z), Abaqus goes counter-clockwise round the bottom face
   * and then round the top face. Both orderings give a positive Jacobian
   * for the same cell, so no face is turned inside out.
   */
  constexpr std::array<unsigned int, 8> c3d8_to_dealii = {
    {0, 1, 3, 2, 4, 5, 7, 6}};

  /**
   * Abaqus face label of each deal.II face: deal.II faces 0..5 are
   * x = 0, x = 1, y = 0, y = 1, z = 0, z = 1 of the reference cell; Abaqus
   * faces S1..S6 of C3D8 are (nodes 1-based) 1234, 5876, 1562, 2673, 3784,
   * 4851.
   */
  constexpr std::array<unsigned int, 6> dealii_face_to_abaqus = {
    {6, 4, 3, 5, 1, 2}};

  /** Abaqus C3D8 face Si (0-based index i-1) as 0-based C3D8 node indices. */
  constexpr std::array<std::array<unsigned int, 4>, 6> abaqus_face_nodes = {
    {{{0, 1, 2, 3}},
     {{4, 7, 6, 5}},
     {{0, 4, 5, 1}},
     {{1, 5, 6, 2}},
     {{2, 6, 7, 3}},
     {{3, 7, 4, 0}}}};

  /**
   * The two tables above must agree: the vertices of deal.II face f are
   * those of Abaqus face dealii_face_to_abaqus[f]. Checked once at start-up
   * so that a typo cannot silently put the contact surface on the wrong
   * side of a cell.
   */
  void
  check_face_tables()
  {
    for (unsigned int f = 0; f < 6; ++f)
      {
        std::set<unsigned int> from_dealii, from_abaqus;
        for (unsigned int v = 0; v < 4; ++v)
          from_dealii.insert(GeometryInfo<3>::face_to_cell_vertices(f, v));
        for (const unsigned int k :
             abaqus_face_nodes[dealii_face_to_abaqus[f] - 1])
          from_abaqus.insert(c3d8_to_dealii[k]);
        if (from_dealii != from_abaqus)
          throw std::logic_error("face tables disagree for deal.II face " +
                                 std::to_string(f));
      }
  }

  /** Writes @p ids as the data lines of a set, 16 per line (Abaqus' limit). */
  void
  write_id_list(std::ostream &out, const std::vector<unsigned int> &ids)
  {
    for (unsigned int i = 0; i < ids.size(); ++i)
      out << ids[i] << ((i % 16 == 15 || i + 1 == ids.size()) ? "\n" : ", ");
  }
} // namespace



int
main(int argc, char **argv)
{
  try
    {
      const unsigned int refinement = (argc > 1 ? std::stoul(argv[1]) : 2u);
      const std::string  output = (argc > 2 ? argv[2] : "drop_test_mesh.inp");
      const std::string  type   = (argc > 3 ? argv[3] : "C3D8");
      if (type != "C3D8" && type != "C3D8R" && type != "C3D8I")
        throw std::invalid_argument("element type must be C3D8, C3D8R or "
                                    "C3D8I, not " +
                                    type);
      const double diameter = 25., height = 24.; // mm
      check_face_tables();

      Triangulation<3> triangulation;
      rubberdyn::geometry::make_standing_cylinder(triangulation,
                                                  diameter,
                                                  height,
                                                  refinement);

      // Abaqus node numbers 1, 2, ... for the vertices of active cells.
      std::map<unsigned int, unsigned int> node_number;
      for (const auto &cell : triangulation.active_cell_iterators())
        for (const unsigned int v : cell->vertex_indices())
          node_number.emplace(cell->vertex_index(v), 0);
      unsigned int next = 1;
      for (auto &entry : node_number)
        entry.second = next++;

      std::ofstream out(output);
      if (!out)
        throw std::runtime_error("cannot write " + output);
      out << "** Drop-test rubber cylinder (diameter " << diameter
          << " mm, height " << height << " mm), written by "
          << "export_drop_test_mesh from\n"
          << "** rubberdyn::geometry::make_standing_cylinder, refinement "
          << refinement << ": " << triangulation.n_active_cells() << ' ' << type
          << " elements, " << node_number.size() << " nodes. Units mm.\n";

      out << "*NODE, NSET=RUBBER_NODES\n" << std::setprecision(12);
      const std::vector<Point<3>> &vertices = triangulation.get_vertices();
      for (const auto &[vertex, number] : node_number)
        out << number << ", " << vertices[vertex][0] << ", "
            << vertices[vertex][1] << ", " << vertices[vertex][2] << '\n';

      out << "*ELEMENT, TYPE=" << type << ", ELSET=RUBBER\n";
      // Boundary faces: boundary id -> (element, Abaqus face label).
      std::map<unsigned int, std::vector<std::pair<unsigned int, unsigned int>>>
                                                     faces_on;
      std::map<unsigned int, std::set<unsigned int>> nodes_on;
      unsigned int                                   element = 0;
      for (const auto &cell : triangulation.active_cell_iterators())
        {
          ++element;
          out << element;
          for (const unsigned int v : c3d8_to_dealii)
            out << ", " << node_number[cell->vertex_index(v)];
          out << '\n';
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary())
              {
                const unsigned int id = cell->face(f)->boundary_id();
                faces_on[id].emplace_back(element, dealii_face_to_abaqus[f]);
                for (const unsigned int v : cell->face(f)->vertex_indices())
                  nodes_on[id].insert(
                    node_number[cell->face(f)->vertex_index(v)]);
              }
        }

      namespace id = rubberdyn::geometry::cylinder_boundary;
      for (const auto &[boundary, name] :
           {std::pair<unsigned int, const char *>(id::bottom, "BOTTOM"),
            std::pair<unsigned int, const char *>(id::top, "TOP"),
            std::pair<unsigned int, const char *>(id::hull, "HULL")})
        {
          if (faces_on[boundary].empty())
            throw std::logic_error(std::string("no faces on ") + name);
          out << "*NSET, NSET=" << name << "_NODES\n";
          write_id_list(out,
                        std::vector<unsigned int>(nodes_on[boundary].begin(),
                                                  nodes_on[boundary].end()));
          out << "*SURFACE, NAME=" << name << ", TYPE=ELEMENT\n";
          for (const auto &[e, label] : faces_on[boundary])
            out << e << ", S" << label << '\n';
        }

      std::cout << "Wrote " << output << ": " << triangulation.n_active_cells()
                << " elements, " << node_number.size() << " nodes, "
                << faces_on[id::bottom].size() << " bottom and "
                << faces_on[id::top].size() << " top faces" << std::endl;
    }
  catch (const std::exception &e)
    {
      std::cerr << "export_drop_test_mesh: " << e.what() << std::endl;
      return EXIT_FAILURE;
    }
  return EXIT_SUCCESS;
}
