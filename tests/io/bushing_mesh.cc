// The bushing assembly's meshes (parameter_files/meshes/bushing.geo, issue
// 10): bushing_1.msh (n = 1, the coarse mesh of the tests) and bushing.msh
// (the default n = 2, the study's mesh), read with read_gmsh_mesh().
//
// Checked for each:
// - every cell a hexahedron, with a positive Jacobian at each of its eight
//   vertices (the minimum scaled Jacobian is printed: 1 for a brick, 0.71
//   for the 45 degree corners of the O-grids);
// - the eleven material ids, each part's cells and volume against the
//   closed form of the meshed geometry; the 38 boundary ids, each one's
//   faces and area against its closed form. Round hulls are polygons of
//   N = 24 n flat facets with their corners on the circles, N = 24 at
//   every n for bolt and nut (bolt_quarter = 6; area of a disc of radius
//   R: A(R) = (N / 2) R^2 sin(2 pi / N), perimeter P(R) =
//   2 N R sin(pi / N)), which is what the closed forms use. Tolerance 1e-10
//   relative: the nodes lie where the closed forms have them up to Gmsh's
//   rounding (the rotations put a few nodes 1e-14 mm off their planes) and
//   16 printed digits, deal.II's volumes and areas of these flat-faced
//   cells are exact up to rounding, and the sums of up to 54 000 terms add
//   rounding errors of order 1e-13 relative. A wrong radius, thickness,
//   element layer or tag moves a measure by far more (a tenth of a mm on
//   any radius: 1e-3 relative at least);
// - that only the three designed pairs share vertices (bolt / nut, inner
//   sleeve / rubber, metal sleeve / plate): every other pair of touching
//   parts has nodes of its own for contact or tied pairs;
// - at least two element layers through each thin part (washer, brace and
//   plate: distinct heights of its vertices; the three sleeves: distinct
//   radii), printed;
// - the pretension section: a layer of shank elements is centred on
//   z = 30 (the default section_z), so that the section plane cuts the
//   whole shank's cross-section (the core's 6 x 6 cells and ring A's
//   24 x 2) halfway through its elements and no bolt vertex lies on it
//   (a plane on element faces cuts no element: doc/quasi_static.md,
//   "Bolt pretension").
#include <deal.II/base/geometry_info.h>
#include <deal.II/grid/tria.h>

#include <rubberdyn/io/gmsh_mesh.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <vector>

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
  /** The default dimensions of bushing.geo (mm). */
  namespace dimension
  {
    constexpr double bolt = 8., hole = 8.5, head = 12., head_height = 10.;
    constexpr double end_length = 6., nut = 15., nut_height = 14.;
    constexpr double washer = 36., washer_t = 4.;
    constexpr double inner = 14., L = 60., rubber = 25., lip = 32.5;
    constexpr double lip_h = 6., plastic = 27.5, metal = 29.5;
    constexpr double plate_t = 5., plate_w = 90., plate_length = 345.;
    constexpr double brace_t = 8., brace_x = 135., brace_y = 170.;
    constexpr double clamp = 20., brace_square = 25.;
    constexpr double support_l = 40., support_h = 20.;
    constexpr double weight_l = 60., weight_w = 60., weight_h = 40.;
    constexpr double edge_r = 10., edge_facets = 8.;
    constexpr double section_z = 30.;
  } // namespace dimension

  /**
   * The number of distinct values in @p values, values closer than
   * 1e-6 mm counted as one.
   */
  unsigned int
  n_distinct(std::vector<double> values)
  {
    std::sort(values.begin(), values.end());
    unsigned int count = 0;
    for (std::size_t i = 0; i < values.size(); ++i)
      if (i == 0 || values[i] - values[i - 1] > 1e-6)
        ++count;
    return count;
  }

  /**
   * The scaled Jacobian of @p cell at each of its vertices: the
   * determinant of the three edges leaving the vertex (each taken along
   * the reference cell's coordinate direction), divided by their lengths;
   * returns the smallest.
   */
  template <typename Cell>
  double
  min_scaled_jacobian(const Cell &cell)
  {
    double smallest = 1.;
    for (const unsigned int v : cell->vertex_indices())
      {
        Tensor<1, 3> edge[3];
        double       length = 1.;
        for (unsigned int d = 0; d < 3; ++d)
          {
            // Vertex v is lexicographic (bit d: the coordinate d is 1);
            // its neighbour along d flips that bit.
            const unsigned int w    = v ^ (1u << d);
            const double       sign = (v & (1u << d)) ? -1. : 1.;
            edge[d] = sign * (cell->vertex(w) - cell->vertex(v));
            length *= edge[d].norm();
          }
        const double det = edge[0] * cross_product_3d(edge[1], edge[2]);
        smallest         = std::min(smallest, det / length);
      }
    return smallest;
  }

  void
  check_bushing(const std::string &file, const unsigned int n)
  {
    using namespace dimension;
    const double pi = numbers::PI;
    const double N  = 24. * n;
    const auto   A  = [&](const double R) {
      return N / 2. * R * R * std::sin(2. * pi / N);
    };
    const auto P = [&](const double R) {
      return 2. * N * R * std::sin(pi / N);
    };
    // Bolt and nut: 4 bolt_quarter = 24 facets around at every n.
    const double Nb  = 24.;
    const auto   Ab  = [&](const double R) {
      return Nb / 2. * R * R * std::sin(2. * pi / Nb);
    };
    const auto Pb = [&](const double R) {
      return 2. * Nb * R * std::sin(pi / Nb);
    };
    // The drop weight's and the support's blocks: a profile l x h in the
    // xz-plane, two of its corners rounded with the radius edge_r by
    // edge_facets facets each (a quarter of a polygon of 4 edge_facets),
    // extruded over the width w. The rounded face: l - 2 edge_r flat plus
    // the two arcs; the other faces: the far face, the two sides beyond
    // the radius and the profile's two ends.
    const double arc    = edge_facets * 2. * edge_r *
                       std::sin(pi / (4. * edge_facets));
    const double corner = edge_facets / 2. * edge_r * edge_r *
                          std::sin(pi / (2. * edge_facets));
    const auto profile  = [&](const double l, const double h) {
      return l * h - 2. * edge_r * edge_r + 2. * corner;
    };
    const auto rounded_face = [&](const double l, const double w) {
      return (l - 2. * edge_r + 2. * arc) * w;
    };
    const auto other_faces = [&](const double l, const double w,
                                 const double h) {
      return l * w + 2. * (h - edge_r) * w + 2. * profile(l, h);
    };
    const double z_end  = -washer_t - nut_height - end_length;
    const double z_head = L + brace_t;

    const std::map<unsigned int, double> volumes = {
      {1,
       Ab(bolt) * (z_head + head_height - z_end) +
         (Ab(head) - Ab(bolt)) * head_height},
      {2, (Ab(nut) - Ab(bolt)) * nut_height},
      {3, (A(washer) - A(hole)) * washer_t},
      {4, (A(inner) - A(hole)) * L},
      {5, (A(rubber) - A(inner)) * L + (A(lip) - A(rubber)) * 2. * lip_h},
      {6, (A(plastic) - A(rubber)) * (L - 2. * lip_h)},
      {7, (A(metal) - A(plastic)) * (L - 2. * lip_h)},
      {8, (plate_w * plate_length - A(metal)) * plate_t},
      {9, (brace_x * brace_y - A(hole)) * brace_t},
      {10, profile(support_l, support_h) * plate_w},
      {11, profile(weight_l, weight_h) * weight_w}};
    const double brace_face                    = brace_x * brace_y - A(hole);
    const double clamp_back                    = clamp * 2. * brace_square;
    const std::map<unsigned int, double> areas = {
      {1, Pb(bolt) * (z_head + washer_t)},
      {2, Ab(head) - Ab(bolt)},
      {3, Ab(bolt)},
      {4, Ab(head) + Pb(head) * head_height + Pb(bolt) * end_length},
      {5, Ab(nut) - Ab(bolt)},
      {6, Pb(nut) * nut_height + Ab(nut) - Ab(bolt)},
      {7, A(washer) - A(hole)},
      {8, A(washer) - A(hole)},
      {9, (P(washer) + P(hole)) * washer_t},
      {10, A(inner) - A(hole)},
      {11, A(inner) - A(hole)},
      {12, P(hole) * L},
      {13, A(lip) - A(inner)},
      {14, A(lip) - A(inner)},
      {15, P(rubber) * (L - 2. * lip_h)},
      {16, 2. * (A(lip) - A(rubber))},
      {17, P(lip) * 2. * lip_h},
      {18, P(rubber) * (L - 2. * lip_h)},
      {19, P(plastic) * (L - 2. * lip_h)},
      {20, 2. * (A(plastic) - A(rubber))},
      {21, P(plastic) * (L - 2. * lip_h)},
      {22, P(metal) * (L - 2. * lip_h - plate_t)},
      {23, 2. * (A(metal) - A(plastic))},
      {24, plate_w * (plate_length - clamp) - A(metal)},
      {25, plate_w * plate_length - A(metal)},
      {26, 2. * (plate_w + plate_length) * plate_t},
      {27, brace_face},
      {28, brace_face - clamp_back - 2. * clamp * clamp},
      {29, clamp_back},
      {30, clamp * clamp},
      {31, clamp * clamp},
      {32, P(hole) * brace_t},
      {33, 2. * (brace_x + brace_y) * brace_t},
      {34, rounded_face(support_l, plate_w)},
      {35, other_faces(support_l, plate_w, support_h)},
      {36, rounded_face(weight_l, weight_w)},
      {37, other_faces(weight_l, weight_w, weight_h)},
      {38, clamp * plate_w}};

    Triangulation<3> tria;
    try
      {
        read_gmsh_mesh(tria, mesh_directory + file, "Mesh/Mesh file");
      }
    catch (const std::exception &error)
      {
        check(false, file + " was refused: " + error.what());
      }
    out() << file << " (n = " << n << "): " << tria.n_active_cells()
          << " cells, " << tria.n_used_vertices() << " vertices" << std::endl;

    // Cells, volumes, Jacobians; the vertices of each part.
    std::map<unsigned int, std::pair<unsigned int, double>> materials,
      boundaries;
    std::map<unsigned int, std::set<unsigned int>> part_vertices;
    double                                         min_jacobian    = 1.;
    unsigned int                                   n_non_hexahedra = 0;
    unsigned int                                   n_straddling    = 0;
    for (const auto &cell : tria.active_cell_iterators())
      {
        if (cell->reference_cell() != ReferenceCells::Hexahedron)
          ++n_non_hexahedra;
        auto &m = materials[cell->material_id()];
        ++m.first;
        m.second += cell->measure();
        min_jacobian = std::min(min_jacobian, min_scaled_jacobian(cell));
        for (const unsigned int v : cell->vertex_indices())
          part_vertices[cell->material_id()].insert(cell->vertex_index(v));
        for (const unsigned int f : cell->face_indices())
          if (cell->at_boundary(f))
            {
              auto &b = boundaries[cell->face(f)->boundary_id()];
              ++b.first;
              b.second += cell->face(f)->measure();
            }
        if (cell->material_id() == 1)
          {
            double low = 1e300, high = -1e300;
            for (const unsigned int v : cell->vertex_indices())
              {
                low  = std::min(low, cell->vertex(v)[2]);
                high = std::max(high, cell->vertex(v)[2]);
              }
            if (low < section_z - 1e-9 && high > section_z + 1e-9)
              ++n_straddling;
          }
      }
    check(n_non_hexahedra == 0, file + ": every cell is a hexahedron");
    out() << "  minimum scaled Jacobian at the vertices: "
          << std::setprecision(2) << std::fixed << min_jacobian
          << std::defaultfloat << std::endl;
    check(min_jacobian > 0., file + ": a cell is inverted at a vertex");

    const auto report = [&](const char                           *what,
                            const auto                           &measured,
                            const std::map<unsigned int, double> &expected,
                            const char                           *items,
                            const char                           *measure) {
      for (const auto &[id, count_and_measure] : measured)
        {
          const double value = count_and_measure.second;
          out() << "  " << what << ' ' << id << ": " << count_and_measure.first
                << ' ' << items << ", " << measure << ' ' << g6(value);
          const auto closed_form = expected.find(id);
          check(closed_form != expected.end(),
                file + ": unexpected " + what + " id " + std::to_string(id));
          const double error =
            std::abs(value - closed_form->second) / closed_form->second;
          out() << " (closed form " << g6(closed_form->second)
                << ", relative error < 1e-10)" << std::endl;
          check(error < 1e-10,
                file + ": " + what + ' ' + std::to_string(id) + ' ' + measure +
                  " relative error " + sci(error));
        }
      check(measured.size() == expected.size(),
            file + ": not every " + what + " id is present");
    };
    report("material", materials, volumes, "cells", "volume");
    report("boundary", boundaries, areas, "faces", "area");

    // Shared vertices: only the designed pairs.
    const std::set<std::pair<unsigned int, unsigned int>> designed = {{1, 2},
                                                                      {4, 5},
                                                                      {7, 8}};
    for (auto a = part_vertices.begin(); a != part_vertices.end(); ++a)
      for (auto b = std::next(a); b != part_vertices.end(); ++b)
        {
          std::vector<unsigned int> common;
          std::set_intersection(a->second.begin(),
                                a->second.end(),
                                b->second.begin(),
                                b->second.end(),
                                std::back_inserter(common));
          const bool shared = !common.empty();
          if (shared)
            out() << "  materials " << a->first << " and " << b->first
                  << " share " << common.size() << " vertices" << std::endl;
          check(shared == (designed.count({a->first, b->first}) == 1),
                file + ": materials " + std::to_string(a->first) + " and " +
                  std::to_string(b->first) +
                  (shared ? " share vertices" : " share no vertex"));
        }

    // Element layers through the thin parts.
    const auto vertices = tria.get_vertices();
    const auto layers =
      [&](const unsigned int material, const bool radial, const char *name) {
        std::vector<double> values;
        for (const unsigned int v : part_vertices[material])
          values.push_back(radial ? std::hypot(vertices[v][0], vertices[v][1]) :
                                    vertices[v][2]);
        const unsigned int n_layers = n_distinct(values) - 1;
        out() << "  " << name << ": " << n_layers << " element layers through "
              << (radial ? "the wall" : "the thickness") << std::endl;
        check(n_layers >= 2,
              file + ": " + name + " has fewer than two element layers");
      };
    layers(3, false, "washer");
    layers(4, true, "inner sleeve");
    layers(6, true, "plastic outer sleeve");
    layers(7, true, "metal outer sleeve");
    layers(8, false, "plate");
    layers(9, false, "brace");

    // The pretension section: no bolt vertex on z = section_z, and the
    // plane cuts the whole shank's cross-section (the core's 6 x 6 cells
    // and ring A's 24 x 2, at every n).
    unsigned int n_section = 0;
    for (const unsigned int v : part_vertices[1])
      if (std::abs(vertices[v][2] - section_z) < 1e-9)
        ++n_section;
    const unsigned int expected_straddling = 6 * 6 + 24 * 2;
    out() << "  section z = " << section_z << ": " << n_section
          << " bolt vertices on it, " << n_straddling
          << " bolt cells across" << std::endl;
    check(n_section == 0 && n_straddling == expected_straddling,
          file + ": the section plane does not cut the shank's element "
                 "layer halfway");
  }
} // namespace



int
main()
{
  check_bushing("bushing_1.msh", 1);
  check_bushing("bushing.msh", 2);
}
