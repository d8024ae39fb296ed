#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/grid/grid_tools.h>

#include <rubberdyn/base/exceptions.h>
#include <rubberdyn/base/parameter_tools.h>
#include <rubberdyn/io/gmsh_mesh.h>
#include <rubberdyn/io/parameter_file.h>
#include <rubberdyn/model/model.h>

#include <filesystem>
#include <string>
#include <vector>

#include "model_study_parsing.h"

// The Model study's `Mesh` section: the Gmsh file, its scale and
// refinement, declared and parsed here.

namespace rubberdyn
{
  namespace studies
  {
    namespace model_study_parsing
    {
      void
      declare_mesh(ParameterHandler &prm)
      {
        prm.enter_subsection("Mesh");
        prm.declare_entry("Mesh file",
                          "",
                          Patterns::FileName(Patterns::FileName::input),
                          "Gmsh mesh (.msh, format 2.2 or 4.1, ASCII) of "
                          "hexahedra; a relative path is relative to the "
                          "folder of the parameter file that sets it (the "
                          "file given, or a file it includes). Physical volume tags "
                          "become material ids (name them in Parts/<name>/"
                          "Material ids), physical surface tags boundary ids "
                          "(for boundary conditions and rigid surfaces). Tag "
                          "0 is reserved.");
        prm.declare_entry("Global refinement",
                          "0",
                          Patterns::Integer(0, 5),
                          "Number of global refinements of the mesh (each "
                          "splits every hexahedron into 8).");
        prm.declare_entry("Scale",
                          "1",
                          Patterns::Double(0.),
                          "Factor on the mesh's coordinates (-, > 0), e.g. "
                          "1000 for a mesh in m (the model is in mm).");
        prm.leave_subsection();
      }



      MeshContents
      parse_mesh(ParameterHandler  &prm,
                 const std::string &parameter_file,
                 model::Model      &m)
      {
        prm.enter_subsection("Mesh");
        std::string        mesh_file  = prm.get("Mesh file");
        const unsigned int refinement = prm.get_integer("Global refinement");
        const double       scale      = prm.get_double("Scale");
        prm.leave_subsection();
        if (mesh_file.empty())
          throw InputError("Mesh/Mesh file",
                           "names no file; a Model needs a Gmsh mesh");
        parameter_tools::require_positive(scale, "Mesh/Scale");
        // Relative to the folder of the parameter file that sets it (the
        // file given or one it includes), so that a study runs from any
        // working directory and a base file shared from another folder
        // finds its mesh.
        if (std::filesystem::path(mesh_file).is_relative() &&
            !parameter_file.empty())
          mesh_file =
            (std::filesystem::path(
               io::file_setting_entry(parameter_file, "Mesh/Mesh file"))
               .parent_path() /
             mesh_file)
              .lexically_normal()
              .string();
        io::read_gmsh_mesh(m.triangulation, mesh_file, "Mesh/Mesh file");
        if (scale != 1.)
          GridTools::scale(scale, m.triangulation);
        m.triangulation.refine_global(refinement);

        // The material and boundary ids present in the mesh, on any rank.
        MeshContents contents;
        contents.file = mesh_file;
        for (const auto &cell : m.triangulation.active_cell_iterators())
          if (cell->is_locally_owned())
            contents.material_ids.insert(cell->material_id());
        const std::vector<types::material_id> local(
          contents.material_ids.begin(),
          contents.material_ids.end());
        for (const auto &ids : Utilities::MPI::all_gather(m.comm, local))
          contents.material_ids.insert(ids.begin(), ids.end());
        contents.boundary_ids = m.boundary_ids_in_mesh();
        return contents;
      }
    } // namespace model_study_parsing
  }   // namespace studies
} // namespace rubberdyn
