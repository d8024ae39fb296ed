#include <deal.II/base/geometry_info.h>
#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe.h>

#include <rubberdyn/base/exceptions.h>
#include <rubberdyn/base/parameter_tools.h>
#include <rubberdyn/time_integration/kinematic_constraints.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

namespace rubberdyn
{
  namespace time_integration
  {
    KinematicConstraints::KinematicConstraints(
      const DoFHandler<3, 3> &                                   dof_handler,
      const std::shared_ptr<const Utilities::MPI::Partitioner> &partitioner)
      : dof_handler(dof_handler)
      , partitioner(partitioner)
    {}



    std::vector<unsigned int>
    KinematicConstraints::boundary_dofs(const types::boundary_id boundary_id,
                                        const unsigned int       direction,
                                        std::vector<double> *coordinates) const
    {
      const FiniteElement<3> &fe = dof_handler.get_fe();
      std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
      std::set<unsigned int>               dofs;
      // Ghost cells too: an owned node may lie on a boundary face of a
      // neighbour's cell only.
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned() || cell->is_ghost())
          for (const unsigned int face : cell->face_indices())
            if (cell->at_boundary(face) &&
                cell->face(face)->boundary_id() == boundary_id)
              {
                cell->get_dof_indices(dof_indices);
                for (unsigned int v = 0; v < 4; ++v)
                  {
                    const unsigned int vertex =
                      GeometryInfo<3>::face_to_cell_vertices(face, v);
                    if (coordinates != nullptr)
                      coordinates->push_back(cell->vertex(vertex)[direction]);
                    const types::global_dof_index dof =
                      dof_indices[fe.component_to_system_index(direction,
                                                               vertex)];
                    if (partitioner->in_local_range(dof))
                      dofs.insert(partitioner->global_to_local(dof));
                  }
              }
      return std::vector<unsigned int>(dofs.begin(), dofs.end());
    }



    void
    KinematicConstraints::add_group(const std::string &name,
                                    const std::vector<unsigned int> &dofs,
                                    const std::function<double(double)> &velocity)
    {
      const unsigned int group = velocities.size();
      names.push_back(name);
      velocities.push_back(velocity);
      // A later group overrides an earlier one on a shared dof (the map
      // from dof to entry keeps this linear in the number of dofs).
      for (const unsigned int dof : dofs)
        {
          const auto existing = entry_of_dof.find(dof);
          if (existing != entry_of_dof.end())
            constrained[existing->second].group = group;
          else
            {
              entry_of_dof[dof] = constrained.size();
              constrained.push_back({dof, group});
            }
        }
    }



    void
    KinematicConstraints::prescribe_velocity(
      const std::string &                  name,
      const types::boundary_id             boundary_id,
      const unsigned int                   direction,
      const std::function<double(double)> &velocity)
    {
      AssertThrow(direction < 3, ExcIndexRange(direction, 0, 3));
      std::vector<double>             coordinates;
      const std::vector<unsigned int> dofs =
        boundary_dofs(boundary_id, direction, &coordinates);
      const unsigned int n_vertices = Utilities::MPI::sum(
        static_cast<unsigned int>(coordinates.size()),
        partitioner->get_mpi_communicator());
      if (n_vertices == 0)
        throw InputError(name,
                         "no boundary face has the boundary id " +
                           std::to_string(boundary_id));
      add_group(name, dofs, velocity);
    }



    void
    KinematicConstraints::fix(const std::string &      name,
                              const types::boundary_id boundary_id)
    {
      // One group per direction, so that each reaction component is
      // reported.
      const char *suffix[3] = {"/x", "/y", "/z"};
      for (unsigned int d = 0; d < 3; ++d)
        prescribe_velocity(name + suffix[d], boundary_id, d, [](double) {
          return 0.;
        });
    }



    void
    KinematicConstraints::symmetry_plane(const std::string &      name,
                                         const types::boundary_id boundary_id,
                                         const unsigned int normal_direction)
    {
      AssertThrow(normal_direction < 3, ExcIndexRange(normal_direction, 0, 3));
      std::vector<double> coordinates;
      boundary_dofs(boundary_id, normal_direction, &coordinates);
      const MPI_Comm comm = partitioner->get_mpi_communicator();
      double lowest = std::numeric_limits<double>::max(), highest = -lowest;
      for (const double x : coordinates)
        {
          lowest  = std::min(lowest, x);
          highest = std::max(highest, x);
        }
      lowest  = Utilities::MPI::min(lowest, comm);
      highest = Utilities::MPI::max(highest, comm);
      if (lowest > highest)
        throw InputError(name,
                         "no boundary face has the boundary id " +
                           std::to_string(boundary_id));
      // Flat to rounding of the coordinates (mm).
      if (highest - lowest > 1e-10 * std::max(1., std::abs(lowest)))
        throw InputError(name,
                         "the faces of boundary " +
                           std::to_string(boundary_id) +
                           " are not in one plane normal to axis " +
                           std::to_string(normal_direction) + " (they span " +
                           parameter_tools::format_short(highest - lowest) +
                           " mm along it)");
      prescribe_velocity(name, boundary_id, normal_direction,
                         [](double) { return 0.; });
    }



    std::vector<std::string>
    KinematicConstraints::group_names() const
    {
      return names;
    }
  } // namespace time_integration
} // namespace rubberdyn
