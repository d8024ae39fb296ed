// rubberdyn::io::read_gmsh_mesh(): the shipped meshes read back with the
// tags that parameter_files/meshes/README.md promises, and every kind of bad
// file is refused with one line that names the file and what is wrong,
// never a crash, a hang or a deal.II banner.
//
// Good meshes: cells, and volume per material id; faces, and area per
// boundary id; each volume and area against the closed form of the meshed
// geometry. The boxes are meshed exactly. The cylinder's hull is meshed by
// flat facets, eight around (every 45 degrees), so its closed forms are
// those of the inscribed octagonal prism (radius r, height h): hull
// 8 (2 r sin(pi / 8)) h, each end 2 sqrt(2) r^2, volume 2 sqrt(2) r^2 h.
// Tolerance 1e-12 relative: the nodes are where the closed form has them
// up to Gmsh's printed digits (16 significant, 1e-16 relative), deal.II's
// face areas and cell volumes are exact for these flat faces up to
// rounding, and a sum of a few hundred of them adds rounding errors of
// order 1e-14 relative.
//
// The drop-test cylinder is also compared with the built-in
// geometry::make_standing_cylinder(tria, 25, 24, 1): each Gmsh cell must
// have a built-in cell with the same eight vertices to 1e-12 mm (matched
// by cell centre, one to one), and each boundary face the built-in
// boundary id plus one.
//
// Bad files are written from strings into the working directory: variants
// of two unit hexahedra side by side (msh 2.2, and 4.1), and cuts and
// single-byte corruptions of them at every byte position.
#include <deal.II/grid/tria.h>

#include <rubberdyn/base/exceptions.h>
#include <rubberdyn/geometry/standing_cylinder.h>
#include <rubberdyn/io/gmsh_mesh.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>
#include <vector>

#include "../tests.h"
#include "mesh_tests.h"

using namespace dealii;
using rubberdyn::InputError;
using rubberdyn::io::read_gmsh_mesh;
using testing::check;
using testing::g6;
using testing::mesh_directory;
using testing::out;
using testing::sci;

namespace
{
  const std::string entry = "Mesh/Mesh file";


  /**
   * Print cells and volume per material id, faces and area per boundary
   * id, and check them against @p volumes and @p areas (closed forms),
   * which list every id the mesh must have.
   */
  void
  summarize(const Triangulation<3>               &tria,
            const std::string                    &name,
            const std::map<unsigned int, double> &volumes,
            const std::map<unsigned int, double> &areas)
  {
    std::map<unsigned int, std::pair<unsigned int, double>> materials,
      boundaries;
    for (const auto &cell : tria.active_cell_iterators())
      {
        auto &m = materials[cell->material_id()];
        ++m.first;
        m.second += cell->measure();
        for (const unsigned int f : cell->face_indices())
          if (cell->at_boundary(f))
            {
              auto &b = boundaries[cell->face(f)->boundary_id()];
              ++b.first;
              b.second += cell->face(f)->measure();
            }
      }
    out() << name << ": " << tria.n_active_cells() << " cells, "
          << tria.n_used_vertices() << " vertices" << std::endl;
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
          if (closed_form != expected.end())
            {
              const double error =
                std::abs(value - closed_form->second) / closed_form->second;
              out() << " (closed form " << g6(closed_form->second)
                    << ", relative error < 1e-12)";
              check(error < 1e-12,
                    name + ": " + what + ' ' + std::to_string(id) + ' ' +
                      measure + " relative error " + sci(error));
            }
          out() << std::endl;
        }
      if (!expected.empty())
        check(measured.size() == expected.size(),
              name + ": the " + what + " ids are not the expected ones");
    };
    report("material", materials, volumes, "cells", "volume");
    report("boundary", boundaries, areas, "faces", "area");
  }

  /** Read @p path into a serial triangulation (must succeed). */
  void
  read_good(Triangulation<3> &tria, const std::string &path)
  {
    try
      {
        read_gmsh_mesh(tria, path, entry);
      }
    catch (const std::exception &error)
      {
        check(false, std::string("a good mesh was refused: ") + error.what());
      }
  }

  /**
   * The shipped drop-test mesh against the built-in one: print and check
   * the largest vertex distance of matched cells and the boundary ids.
   */
  void
  compare_with_built_in_cylinder(const Triangulation<3> &gmsh)
  {
    Triangulation<3> built_in;
    rubberdyn::geometry::make_standing_cylinder(built_in, 25., 24., 1);
    check(built_in.n_active_cells() == gmsh.n_active_cells(),
          "the cylinders have the same number of cells");

    std::set<unsigned int> matched;
    double                 largest_distance = 0.;
    unsigned int           n_boundary_faces = 0;
    for (const auto &cell : gmsh.active_cell_iterators())
      {
        // The built-in cell with the nearest centre (vertex average).
        auto   best          = built_in.begin_active();
        double best_distance = std::numeric_limits<double>::max();
        for (const auto &other : built_in.active_cell_iterators())
          {
            const double distance = cell->center().distance(other->center());
            if (distance < best_distance)
              {
                best_distance = distance;
                best          = other;
              }
          }
        matched.insert(best->active_cell_index());

        // Each vertex against the nearest vertex of that cell: the same
        // eight vertices if every distance is small.
        std::set<unsigned int> used;
        for (const unsigned int v : cell->vertex_indices())
          {
            unsigned int nearest  = 0;
            double       distance = std::numeric_limits<double>::max();
            for (const unsigned int w : best->vertex_indices())
              if (cell->vertex(v).distance(best->vertex(w)) < distance)
                {
                  distance = cell->vertex(v).distance(best->vertex(w));
                  nearest  = w;
                }
            used.insert(nearest);
            largest_distance = std::max(largest_distance, distance);
          }
        check(used.size() == 8, "a cylinder cell matches 8 distinct vertices");

        for (const unsigned int f : cell->face_indices())
          if (cell->at_boundary(f))
            {
              ++n_boundary_faces;
              bool found = false;
              for (const unsigned int g : best->face_indices())
                if (cell->face(f)->center().distance(best->face(g)->center()) <
                    1e-9)
                  {
                    found = true;
                    check(best->at_boundary(g) &&
                            cell->face(f)->boundary_id() ==
                              best->face(g)->boundary_id() + 1,
                          "a cylinder face has the built-in boundary id + 1");
                  }
              check(found, "a cylinder boundary face has a built-in match");
            }
      }
    out() << "drop_test_cylinder.msh against make_standing_cylinder(25, 24, "
             "1): "
          << matched.size() << " cells matched one to one, " << n_boundary_faces
          << " boundary faces with the built-in boundary id + 1, "
             "largest vertex distance "
          << sci(largest_distance) << " mm (must be <= 1e-12)" << std::endl;
    check(matched.size() == built_in.n_active_cells(),
          "the cylinder cells match one to one");
    check(largest_distance <= 1e-12, "the cylinder vertices agree to 1e-12 mm");
  }

  /** Whether vertices of cells of material 1 and 2 coincide (by index). */
  unsigned int
  n_shared_vertices(const Triangulation<3> &tria)
  {
    std::set<unsigned int> first, second;
    for (const auto &cell : tria.active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        (cell->material_id() == 1 ? first : second)
          .insert(cell->vertex_index(v));
    std::vector<unsigned int> common;
    std::set_intersection(first.begin(),
                          first.end(),
                          second.begin(),
                          second.end(),
                          std::back_inserter(common));
    return common.size();
  }

  void
  write(const std::string &name, const std::string &text)
  {
    std::ofstream file(name, std::ios::binary);
    file << text;
  }

  /**
   * Read @p name (written from @p text unless @p text is null): return
   * the InputError's message, or "" if it was read. Anything other than
   * an InputError fails the test.
   */
  std::string
  try_to_read(const std::string &name, const std::string *text)
  {
    if (text != nullptr)
      write(name, *text);
    Triangulation<3> tria;
    try
      {
        read_gmsh_mesh(tria, name, entry);
      }
    catch (const InputError &error)
      {
        const std::string message = error.what();
        check(error.entry_path == entry &&
                message.find(entry + ": " + name + ": ") == 0,
              "the message names the entry and the file: " + message);
        check(message.find('\n') == std::string::npos &&
                message.find("-----") == std::string::npos &&
                message.find("An error occurred") == std::string::npos,
              "the message is one line without a banner: " + message);
        return message;
      }
    catch (const std::exception &error)
      {
        check(false, name + ": not an InputError: " + error.what());
      }
    return "";
  }

  /** Refused with a message that contains @p expected; print it. */
  void
  bad(const std::string &name,
      const std::string &text,
      const std::string &expected)
  {
    const std::string message = try_to_read(name, &text);
    out() << message << std::endl;
    check(!message.empty(), name + " was accepted");
    check(message.find(expected) != std::string::npos,
          name + ": expected '" + expected + "' in: " + message);
  }

  // Two unit hexahedra side by side along x, msh 2.2. Node (i, j, k) at
  // (i, j, k) has the tag 1 + i + 3 j + 6 k. Physical surfaces: 1 = x = 0,
  // 2 = x = 2, 3 = the other eight faces; physical volume 1.
  const std::vector<std::string> block_nodes       = {"1 0 0 0",
                                                      "2 1 0 0",
                                                      "3 2 0 0",
                                                      "4 0 1 0",
                                                      "5 1 1 0",
                                                      "6 2 1 0",
                                                      "7 0 0 1",
                                                      "8 1 0 1",
                                                      "9 2 0 1",
                                                      "10 0 1 1",
                                                      "11 1 1 1",
                                                      "12 2 1 1"};
  const std::vector<std::string> block_quadrangles = {"1 3 2 1 1 1 4 10 7",
                                                      "2 3 2 2 2 3 6 12 9",
                                                      "3 3 2 3 3 1 2 5 4",
                                                      "4 3 2 3 3 2 3 6 5",
                                                      "5 3 2 3 3 7 8 11 10",
                                                      "6 3 2 3 3 8 9 12 11",
                                                      "7 3 2 3 3 1 2 8 7",
                                                      "8 3 2 3 3 2 3 9 8",
                                                      "9 3 2 3 3 4 5 11 10",
                                                      "10 3 2 3 3 5 6 12 11"};
  const std::vector<std::string> block_hexahedra =
    {"11 5 2 1 1 1 2 5 4 7 8 11 10", "12 5 2 1 1 2 3 6 5 8 9 12 11"};

  std::string
  join(const std::vector<std::string> &lines)
  {
    std::string text;
    for (const std::string &line : lines)
      text += line + '\n';
    return text;
  }

  /** The block as msh 2.2, with the given parts (counts as listed unless
   * given). */
  std::string
  block(const std::vector<std::string> &nodes,
        const std::vector<std::string> &elements,
        const std::string              &node_count    = "",
        const std::string              &element_count = "")
  {
    return "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n" +
           (node_count.empty() ? std::to_string(nodes.size()) : node_count) +
           '\n' + join(nodes) + "$EndNodes\n$Elements\n" +
           (element_count.empty() ? std::to_string(elements.size()) :
                                    element_count) +
           '\n' + join(elements) + "$EndElements\n";
  }

  std::vector<std::string>
  operator+(std::vector<std::string> a, const std::vector<std::string> &b)
  {
    a.insert(a.end(), b.begin(), b.end());
    return a;
  }

  std::vector<std::string>
  replaced(std::vector<std::string> lines,
           const std::size_t        index,
           const std::string       &line)
  {
    lines.at(index) = line;
    return lines;
  }

  // The same block as msh 4.1 (entities: surface 1 = the end x = 0 with
  // physical surface 1, volume 1 with physical volume 1; the other faces
  // are not tagged).
  std::string
  block_41(const std::string &entities   = "",
           const std::string &node_block = "3 1 0 12",
           const std::string &elements   = "")
  {
    std::string text =
      "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Entities\n" +
      (entities.empty() ? std::string("0 0 1 1\n"
                                      "1 0 0 0 0 1 1 1 1 0\n"
                                      "1 0 0 0 2 1 1 1 1 1 1\n") :
                          entities) +
      "$EndEntities\n$Nodes\n1 12 1 12\n" + node_block + '\n';
    for (unsigned int n = 1; n <= 12; ++n)
      text += std::to_string(n) + '\n';
    for (const std::string &node : block_nodes)
      text += node.substr(node.find(' ') + 1) + '\n';
    text += "$EndNodes\n$Elements\n" +
            (elements.empty() ? std::string("2 3 1 12\n"
                                            "2 1 3 1\n"
                                            "1 1 4 10 7\n"
                                            "3 1 5 2\n"
                                            "11 1 2 5 4 7 8 11 10\n"
                                            "12 2 3 6 5 8 9 12 11\n") :
                                elements) +
            "$EndElements\n";
    return text;
  }

  /**
   * Cut @p text at every byte before its final "$EndElements" is
   * complete: each cut must be refused with an InputError. Print the
   * messages of the cuts at @p shown.
   */
  void
  cut_everywhere(const std::string              &name,
                 const std::string              &text,
                 const std::vector<std::size_t> &shown)
  {
    const std::size_t complete = text.rfind("$EndElements") + 12;
    unsigned int      n_cuts   = 0;
    for (std::size_t cut = 0; cut < complete; ++cut)
      {
        const std::string part    = text.substr(0, cut);
        const std::string message = try_to_read(name, &part);
        check(!message.empty(),
              name + " cut at byte " + std::to_string(cut) + " was accepted");
        ++n_cuts;
        if (std::find(shown.begin(), shown.end(), cut) != shown.end())
          {
            std::string before =
              text.substr(cut >= 8 ? cut - 8 : 0, cut >= 8 ? 8 : cut);
            std::replace(before.begin(), before.end(), '\n', '/');
            out() << "  cut at byte " << cut << " (after '..." << before
                  << "', newlines shown as /): " << message << std::endl;
          }
      }
    out() << name << ": all " << n_cuts
          << " cuts before the end of $EndElements refused" << std::endl;
  }

  /**
   * Replace each byte of @p text in turn by each of a few characters: the
   * result must be read or refused with an InputError, nothing else.
   */
  void
  corrupt_everywhere(const std::string &name, const std::string &text)
  {
    const std::string replacements("x9-. \n$\0", 8);
    unsigned int      n_read = 0, n_refused = 0;
    for (std::size_t i = 0; i < text.size(); ++i)
      for (const char c : replacements)
        {
          if (text[i] == c)
            continue;
          std::string changed = text;
          changed[i]          = c;
          (try_to_read(name, &changed).empty() ? n_read : n_refused)++;
        }
    out() << name << ": " << n_read + n_refused
          << " single-byte corruptions: " << n_read << " read, " << n_refused
          << " refused with an InputError, none crashed" << std::endl;
  }
} // namespace



int
main()
{
  // ------------------------------------------------------------ good meshes
  const double pi = numbers::PI;
  {
    Triangulation<3> tria;
    read_good(tria, mesh_directory + "bar.msh");
    summarize(tria,
              "bar.msh",
              {{1, 100. * 10. * 10.}},
              {{1, 10. * 10.}, {2, 10. * 10.}, {3, 4. * 100. * 10.}});

    // The same bar exported as msh 4.1 (gmsh bar.geo -3 -format msh41).
    Triangulation<3> tria_41;
    read_good(tria_41, std::string(SOURCE_DIR) + "/bar_msh41.msh");
    summarize(tria_41,
              "bar_msh41.msh",
              {{1, 100. * 10. * 10.}},
              {{1, 10. * 10.}, {2, 10. * 10.}, {3, 4. * 100. * 10.}});
    bool same = tria.n_active_cells() == tria_41.n_active_cells();
    for (auto a = tria.begin_active(), b = tria_41.begin_active();
         same && a != tria.end();
         ++a, ++b)
      for (const unsigned int v : a->vertex_indices())
        same &= (a->vertex(v) == b->vertex(v));
    out() << "bar_msh41.msh and bar.msh: "
          << (same ? "the same cells and vertices" : "DIFFERENT") << std::endl;
    check(same, "msh 4.1 and 2.2 give the same mesh");
  }
  {
    Triangulation<3> tria;
    read_good(tria, mesh_directory + "shear_block.msh");
    summarize(tria,
              "shear_block.msh",
              {{1, 20. * 20. * 10.}},
              {{1, 20. * 20.}, {2, 20. * 20.}, {3, 4. * 20. * 10.}});
  }
  {
    Triangulation<3> tria;
    read_good(tria, mesh_directory + "bonded_block.msh");
    summarize(tria,
              "bonded_block.msh",
              {{1, 20. * 20. * 10.}, {2, 20. * 20. * 2.}},
              {{1, 20. * 20.}, {2, 20. * 20.}, {3, 4. * 20. * 12.}});
    const unsigned int shared = n_shared_vertices(tria);
    out() << "  rubber and steel share " << shared
          << " vertices (the 9 x 9 nodes of the bonded face z = 10)"
          << std::endl;
    check(shared == 81, "the bonded block is one conforming mesh");
  }
  {
    Triangulation<3> tria;
    read_good(tria, mesh_directory + "rigid_drop.msh");
    summarize(tria,
              "rigid_drop.msh",
              {{1, 20. * 20. * 10.}, {2, 10. * 10. * 5.}},
              {{1, 20. * 20.},
               {2, 20. * 20.},
               {3, 10. * 10.},
               {4, 4. * 20. * 10. + 10. * 10. + 4. * 10. * 5.}});
    const unsigned int shared = n_shared_vertices(tria);
    out() << "  rubber and rigid block share " << shared << " vertices"
          << std::endl;
    check(shared == 0, "the rigid block is a separate body");
  }
  {
    // The meshes of the mortar contact examples: separate bodies (no
    // shared vertex), areas by face.
    Triangulation<3> bars;
    read_good(bars, mesh_directory + "two_bars.msh");
    summarize(bars,
              "two_bars.msh",
              {{1, 100. * 10. * 10.}, {2, 100. * 10. * 10.}},
              {{1, 100.}, {2, 100.}, {3, 100.}, {4, 100.}, {5, 8. * 100. * 10.}});
    Triangulation<3> block;
    read_good(block, mesh_directory + "block_on_plate.msh");
    summarize(block,
              "block_on_plate.msh",
              {{1, 10. * 10. * 5.}, {2, 20. * 20. * 2.}},
              {{1, 100.},
               {2, 400.},
               {3, 100.},
               {4, 400.},
               {5, 4. * 10. * 5. + 4. * 20. * 2.}});
    Triangulation<3> blocks;
    read_good(blocks, mesh_directory + "two_blocks_on_plate.msh");
    summarize(blocks,
              "two_blocks_on_plate.msh",
              {{1, 500.}, {2, 500.}, {3, 40. * 20. * 2.}},
              {{1, 100.},
               {2, 100.},
               {3, 800.},
               {4, 100.},
               {5, 100.},
               {6, 800.},
               {7, 2. * 4. * 10. * 5. + 2. * (40. + 20.) * 2.}});
    Triangulation<3> tied;
    read_good(tied, mesh_directory + "tied_block.msh");
    summarize(tied,
              "tied_block.msh",
              {{1, 20. * 20. * 10.}, {2, 20. * 20. * 2.}},
              {{1, 400.}, {2, 400.}, {3, 4. * 20. * 12.}, {4, 400.}, {5, 400.}});
    Triangulation<3> stacked;
    read_good(stacked, mesh_directory + "stacked_blocks.msh");
    summarize(stacked,
              "stacked_blocks.msh",
              {{1, 10. * 10. * 5.}, {2, 10. * 10. * 5.}},
              {{1, 100.},
               {2, 100.},
               {3, 100.},
               {4, 100.},
               {5, 2. * 10. * 5.},
               {6, 2. * 10. * 5.},
               {7, 2. * 10. * 5.},
               {8, 2. * 10. * 5.}});
    // The block on the slope: built in the slope's frame (its volumes and
    // faces keep their areas when turned).
    Triangulation<3> slope;
    read_good(slope, mesh_directory + "block_on_slope.msh");
    summarize(slope,
              "block_on_slope.msh",
              {{1, 14. * 10. * 5.}, {2, 10. * 10. * 5.}},
              {{1, 140.},
               {2, 140.},
               {3, 100.},
               {4, 100.},
               {5, 50.},
               {6, 2. * (14. + 10.) * 5. + 3. * 10. * 5.}});
    const unsigned int shared = n_shared_vertices(bars) +
                                n_shared_vertices(block) +
                                n_shared_vertices(blocks) +
                                n_shared_vertices(tied) +
                                n_shared_vertices(stacked) +
                                n_shared_vertices(slope);
    out() << "  shared vertices between their bodies: " << shared
          << std::endl;
    check(shared == 0, "the contact examples' bodies have their own nodes");
  }
  {
    // The bolted joint: 24-gons of circumradius R (area A(R) =
    // 12 R^2 sin(pi/12), perimeter P(R) = 48 R sin(pi/24)); the bolt is
    // the shank (R = 8, z from 0 to 20), head (R = 12, 10 high) and nut
    // (R = 12, 13 high), each plate an annulus 8.5 < R < 30, 10 thick.
    const auto A = [pi](const double R) {
      return 12. * R * R * std::sin(pi / 12.);
    };
    const auto P = [pi](const double R) {
      return 48. * R * std::sin(pi / 24.);
    };
    Triangulation<3> tria;
    read_good(tria, mesh_directory + "bolted_plates.msh");
    summarize(tria,
              "bolted_plates.msh",
              {{1, A(8.) * 20. + A(12.) * 23.},
               {2, (A(30.) - A(8.5)) * 10.},
               {3, (A(30.) - A(8.5)) * 10.}},
              {{1, A(30.) - A(12.)},
               {2, A(30.) - A(12.)},
               {3,
                2. * A(12.) + P(12.) * 23. + P(8.) * 20. +
                  2. * (A(8.5) - A(8.))},
               {4, (P(30.) + P(8.5)) * 20.}});
  }
  {
    const double     r = 12.5, h = 24.;
    Triangulation<3> tria;
    read_good(tria, mesh_directory + "drop_test_cylinder.msh");
    summarize(tria,
              "drop_test_cylinder.msh",
              {{1, 2. * std::sqrt(2.) * r * r * h}},
              {{1, 8. * 2. * r * std::sin(pi / 8.) * h},
               {2, 2. * std::sqrt(2.) * r * r},
               {3, 2. * std::sqrt(2.) * r * r}});
    compare_with_built_in_cylinder(tria);

    // The same cylinder between two plates 40 x 40 x 5 mm, with nodes of
    // their own.
    Triangulation<3> plates;
    read_good(plates, mesh_directory + "drop_test_plates.msh");
    summarize(plates,
              "drop_test_plates.msh",
              {{1, 2. * std::sqrt(2.) * r * r * h},
               {2, 40. * 40. * 5.},
               {3, 40. * 40. * 5.}},
              {{1, 8. * 2. * r * std::sin(pi / 8.) * h},
               {2, 2. * std::sqrt(2.) * r * r},
               {3, 2. * std::sqrt(2.) * r * r},
               {4, 1600.},
               {5, 1600.},
               {6, 1600.},
               {7, 1600.},
               {8, 2. * 4. * 40. * 5.}});
    out() << "  shared vertices between the cylinder and the plates: "
          << n_shared_vertices(plates) << std::endl;
    check(n_shared_vertices(plates) == 0,
          "the cylinder and the plates have their own nodes");
  }
  {
    // Two cubes touching at a corner, with distinct nodes there: the
    // stream reader keeps them apart (16 vertices; the Gmsh API reader
    // GridIn::read_msh(file name) merges them to 15).
    const std::string corner =
      "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n16\n"
      "1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n5 0 0 1\n6 1 0 1\n7 1 1 1\n"
      "8 0 1 1\n9 1 1 1\n10 2 1 1\n11 2 2 1\n12 1 2 1\n13 1 1 2\n14 2 1 2\n"
      "15 2 2 2\n16 1 2 2\n$EndNodes\n$Elements\n2\n"
      "1 5 2 1 1 1 2 3 4 5 6 7 8\n2 5 2 2 2 9 10 11 12 13 14 15 16\n"
      "$EndElements\n";
    write("corner.msh", corner);
    Triangulation<3> tria;
    read_good(tria, "corner.msh");
    summarize(tria, "corner.msh (two cubes touching at a corner)", {}, {});
    check(tria.n_used_vertices() == 16, "touching bodies stay apart");

    // Points and lines (physical points and curves) are ignored; Windows
    // line ends are fine.
    std::string text =
      block(block_nodes,
            block_quadrangles + block_hexahedra +
              std::vector<std::string>{"13 15 2 5 5 1", "14 1 2 6 6 1 11"});
    for (std::size_t i = text.find('\n'); i != std::string::npos;
         i             = text.find('\n', i + 2))
      text.insert(i, "\r");
    write("points_lines_crlf.msh", text);
    Triangulation<3> tria_lines;
    read_good(tria_lines, "points_lines_crlf.msh");
    summarize(tria_lines,
              "points_lines_crlf.msh (a point, a line, CR LF line ends)",
              {{1, 2.}},
              {{1, 1.}, {2, 1.}, {3, 8.}});

    write("block_41.msh", block_41());
    Triangulation<3> tria_41;
    read_good(tria_41, "block_41.msh");
    summarize(tria_41,
              "block_41.msh (msh 4.1, only the end x = 0 tagged)",
              {},
              {});
  }

  // -------------------------------------------------------------- bad files
  out() << std::endl << "Refused files:" << std::endl;
  const auto q = block_quadrangles;
  const auto h = block_hexahedra;
  {
    const std::string message = try_to_read("does_not_exist.msh", nullptr);
    out() << message << std::endl;
    check(message.find("cannot open") != std::string::npos, "missing file");
    std::filesystem::create_directories("a_directory.msh");
    out() << try_to_read("a_directory.msh", nullptr) << std::endl;
  }
  bad("empty.msh", "", "the file is empty");
  bad("not_gmsh.msh", "solid cube\nfacet normal 0 0 1\n", "not a Gmsh mesh");
  bad("binary.msh",
      "$MeshFormat\n2.2 1 8\n" + std::string("\x01\x00\x00\x00", 4) +
        "\n$EndMeshFormat\n$Nodes\n12\n",
      "binary Gmsh file");
  bad("format_1.msh", "$NOD\n1\n1 0 0 0\n$ENDNOD\n", "format 1");
  bad("version_4_0.msh",
      "$MeshFormat\n4 0 8\n$EndMeshFormat\n",
      "version 4 is not supported");
  bad("control_character.msh",
      block(replaced(block_nodes, 4, std::string("5 1 1\0 0", 8)), q + h),
      "control character 0x00");
  bad("tetrahedron.msh",
      block(block_nodes,
            q + h + std::vector<std::string>{"13 4 2 1 1 1 2 4 7"}),
      "element 13 is a tetrahedron (type 4)");
  bad("prism.msh",
      block(block_nodes,
            q + h + std::vector<std::string>{"13 6 2 1 1 1 2 4 7 8 10"}),
      "element 13 is a prism (type 6)");
  {
    std::string hex27 = "13 12 2 1 1";
    for (unsigned int n = 0; n < 27; ++n)
      hex27 += ' ' + std::to_string(1 + n % 12);
    bad("second_order_hexahedron.msh",
        block(block_nodes, q + h + std::vector<std::string>{hex27}),
        "element 13 is a second-order hexahedron (27 nodes) (type 12)");
  }
  bad("triangle.msh",
      block(block_nodes, h + std::vector<std::string>{"13 2 2 3 3 1 2 7"}),
      "element 13 is a triangle (type 2)");
  bad("no_hexahedra.msh", block(block_nodes, q), "the file has no hexahedra");
  bad("node_count_too_large.msh",
      block(block_nodes, q + h, "13"),
      "announces 13 nodes but lists 12");
  bad("node_count_too_small.msh",
      block(block_nodes, q + h, "11"),
      "announces 11 nodes but lists 12");
  bad("element_count_too_large.msh",
      block(block_nodes, q + h, "", "13"),
      "announces 13 elements but lists 12");
  bad("count_not_a_number.msh",
      block(block_nodes, q + h, "twelve"),
      "expected the number of nodes");
  bad("coordinate_not_a_number.msh",
      block(replaced(block_nodes, 3, "4 0 abc 0"), q + h),
      "expected a node coordinate, a finite real number, found 'abc'");
  bad("coordinate_cut.msh",
      block(replaced(block_nodes, 3, "4 0 1"), q + h),
      "expected 4 numbers (node tag and coordinates x y z), found 3");
  bad("node_defined_twice.msh",
      block(replaced(block_nodes, 11, "5 2 1 1"), q + h),
      "node 5 is defined twice");
  bad("undefined_node_in_hexahedron.msh",
      block(block_nodes, q + replaced(h, 1, "12 5 2 1 1 2 3 6 5 8 9 99 11")),
      "element 12 uses node 99, which the $Nodes section does not define");
  bad("undefined_node_in_quadrangle.msh",
      block(block_nodes, replaced(q, 9, "10 3 2 3 3 5 6 12 99") + h),
      "element 10 uses node 99");
  bad("physical_surface_tag_0.msh",
      block(block_nodes, replaced(q, 2, "3 3 2 0 3 1 2 5 4") + h),
      "quadrangle 3 has the physical surface tag 0");
  bad("quadrangle_without_tag.msh",
      block(block_nodes, replaced(q, 2, "3 3 0 1 2 5 4") + h),
      "quadrangle 3 has no physical surface tag");
  bad("cell_without_physical_tag.msh",
      block(block_nodes, q + replaced(h, 1, "12 5 0 2 3 6 5 8 9 12 11")),
      "hexahedron 12 has no physical volume tag");
  bad("cell_with_physical_tag_0.msh",
      block(block_nodes, q + replaced(h, 1, "12 5 2 0 1 2 3 6 5 8 9 12 11")),
      "hexahedron 12 has no physical volume tag (its tag is 0)");
  bad("tag_out_of_range.msh",
      block(block_nodes,
            q + replaced(h, 1, "12 5 2 4294967295 1 2 3 6 5 8 9 12 11")),
      "expected a physical tag, an integer from 0 to 2147483647");
  bad("mirrored_hexahedron.msh",
      block(block_nodes, q + replaced(h, 1, "12 5 2 1 1 8 9 12 11 2 3 6 5")),
      "line 32: hexahedron 12 is mirrored");
  bad("tangled_hexahedron.msh",
      block(block_nodes, q + replaced(h, 1, "12 5 2 1 1 2 3 6 5 8 9 11 12")),
      "line 32: hexahedron 12 is inverted or degenerate");
  bad("hexahedron_twice.msh",
      block(block_nodes,
            q + h + std::vector<std::string>{"13 5 2 2 1 2 3 6 5 8 9 12 11"}),
      "line 33: hexahedron 13 has the same nodes as hexahedron 12 (line 32)");
  bad("interior_quadrangle.msh",
      block(block_nodes,
            q + h + std::vector<std::string>{"13 3 2 4 4 2 5 11 8"}),
      "line 33: quadrangle 13 (physical surface 4) is an interior face");
  bad("quadrangle_not_a_face.msh",
      block(block_nodes,
            q + h + std::vector<std::string>{"13 3 2 4 4 1 2 11 10"}),
      "is not a face of any hexahedron");
  bad("quadrangle_twice.msh",
      block(block_nodes,
            q + h + std::vector<std::string>{"13 3 2 4 4 1 4 10 7"}),
      "covers the same face as quadrangle 1");
  bad("quadrangle_crossed.msh",
      block(block_nodes, replaced(q, 0, "1 3 2 1 1 1 4 7 10") + h),
      "crossed order");
  bad("text_outside_sections.msh",
      block(block_nodes, q + h) + "trailing words\n",
      "expected the start of a section");
  {
    std::string text = block(block_nodes, q + h);
    text.erase(text.find("$EndNodes"), 10);
    bad("section_not_closed.msh",
        text,
        "found '$Elements' inside the section $Nodes");
  }
  bad("no_elements.msh",
      "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n1\n1 0 0 0\n$EndNodes\n",
      "the file has no $Elements section");

  // msh 4.1
  bad(
    "header_4_1_body_2_2.msh",
    [&]() {
      std::string text = block(block_nodes, q + h);
      text.replace(text.find("2.2 0 8"), 7, "4.1 0 8");
      return text;
    }(),
    "this 4.1 file has no $Entities section");
  bad("parametric_41.msh",
      block_41("", "3 1 1 12"),
      "parametric node coordinates are not supported");
  bad("two_physical_groups_41.msh",
      block_41("0 0 1 1\n1 0 0 0 0 1 1 2 1 5 0\n1 0 0 0 2 1 1 1 1 1 1\n"),
      "surface 1 is in 2 physical groups");
  bad("volume_without_physical_group_41.msh",
      block_41("0 0 1 1\n1 0 0 0 0 1 1 1 1 0\n1 0 0 0 2 1 1 0 1 1\n"),
      "hexahedron 11 (volume 1) has no physical volume tag");
  bad("tetrahedra_41.msh",
      block_41("",
               "3 1 0 12",
               "2 3 11 12\n3 1 5 2\n11 1 2 5 4 7 8 11 10\n"
               "12 2 3 6 5 8 9 12 11\n3 1 4 1\n13 1 2 4 7\n"),
      "element 13 is a tetrahedron (type 4)");
  bad("undefined_entity_41.msh",
      block_41("",
               "3 1 0 12",
               "1 2 11 12\n3 7 5 2\n11 1 2 5 4 7 8 11 10\n"
               "12 2 3 6 5 8 9 12 11\n"),
      "volume 7, which the $Entities section does not define");
  bad("element_count_41.msh",
      block_41("",
               "3 1 0 12",
               "1 3 11 12\n3 1 5 2\n11 1 2 5 4 7 8 11 10\n"
               "12 2 3 6 5 8 9 12 11\n"),
      "announces 3 elements but its blocks hold 2");

  // Truncated and corrupted files.
  out() << std::endl << "Truncated files:" << std::endl;
  const std::string good = block(block_nodes, q + h);
  // Shown: cuts inside the header, in the middle of the node count
  // ("1|2"), after a node's x coordinate, in the middle of a node number
  // of the last hexahedron ("1|1"), inside "$EndElements".
  const std::size_t mid_count       = good.find("$Nodes\n12") + 8;
  const std::size_t after_x         = good.find("\n5 1 1 0") + 4;
  const std::size_t mid_node_number = good.find(" 12 11\n$End") + 5;
  cut_everywhere("truncated.msh",
                 good,
                 {10, mid_count, after_x, mid_node_number, good.size() - 5});
  cut_everywhere("truncated_41.msh",
                 block_41(),
                 {block_41().find("0 1 1\n1 1 1") + 3});
  corrupt_everywhere("corrupted.msh", good);
  corrupt_everywhere("corrupted_41.msh", block_41());
}
