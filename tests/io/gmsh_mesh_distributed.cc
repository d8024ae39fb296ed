// rubberdyn::io::read_gmsh_mesh() into a parallel::distributed
// triangulation: every rank reads the whole file, p4est partitions the
// cells, and the global numbers (cells per material, faces and area per
// boundary id, summed over the locally owned cells) are those of the serial
// read (tests/io/gmsh_mesh.output) on any number of ranks. A bad file is
// refused with the same InputError on every rank.
#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>

#include <rubberdyn/base/exceptions.h>
#include <rubberdyn/io/gmsh_mesh.h>

#include <map>

#include "../tests.h"

using namespace dealii;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                   comm = MPI_COMM_WORLD;
  const bool root = (Utilities::MPI::this_mpi_process(comm) == 0);

  const std::string file =
    std::string(SOURCE_DIR) + "/../../parameter_files/meshes/rigid_drop.msh";
  parallel::distributed::Triangulation<3> tria(comm);
  rubberdyn::io::read_gmsh_mesh(tria, file, "Mesh/Mesh file");

  // Global sums over the locally owned cells: ids 1 to 4 at most.
  std::vector<double> cells(3, 0.), faces(5, 0.), areas(5, 0.);
  for (const auto &cell : tria.active_cell_iterators())
    if (cell->is_locally_owned())
      {
        cells.at(cell->material_id()) += 1.;
        for (const unsigned int f : cell->face_indices())
          if (cell->at_boundary(f))
            {
              faces.at(cell->face(f)->boundary_id()) += 1.;
              areas.at(cell->face(f)->boundary_id()) +=
                cell->face(f)->measure();
            }
      }
  Utilities::MPI::sum(cells, comm, cells);
  Utilities::MPI::sum(faces, comm, faces);
  Utilities::MPI::sum(areas, comm, areas);
  const unsigned int n_owned = tria.n_locally_owned_active_cells();
  testing::check(Utilities::MPI::min(n_owned, comm) > 0,
                 "every rank owns cells");

  if (root)
    {
      auto &out = testing::out();
      out << "rigid_drop.msh: " << tria.n_global_active_cells()
          << " cells in all" << std::endl;
      for (unsigned int m = 1; m < cells.size(); ++m)
        out << "  material " << m << ": " << cells[m] << " cells" << std::endl;
      for (unsigned int b = 0; b < faces.size(); ++b)
        if (faces[b] > 0)
          out << "  boundary " << b << ": " << faces[b] << " faces, area "
              << areas[b] << std::endl;
    }
  testing::check(tria.n_global_active_cells() == 112 && cells[1] == 108 &&
                   cells[2] == 4 && faces[0] == 0,
                 "the distributed mesh is the serial one");

  // A bad file: the same InputError on every rank.
  bool refused = false;
  try
    {
      parallel::distributed::Triangulation<3> other(comm);
      rubberdyn::io::read_gmsh_mesh(other,
                                    "does_not_exist.msh",
                                    "Mesh/Mesh file");
    }
  catch (const rubberdyn::InputError &error)
    {
      refused = true;
      if (root)
        testing::out() << "InputError: " << error.what() << std::endl;
    }
  testing::check(Utilities::MPI::min(refused ? 1u : 0u, comm) == 1,
                 "every rank refuses the missing file");
}
