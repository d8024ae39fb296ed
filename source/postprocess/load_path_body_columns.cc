#include <deal.II/base/mpi.h>

#include <rubberdyn/contact/rigid_surface_forces.h>
#include <rubberdyn/model/model.h>
#include <rubberdyn/model/rigid_body.h>
#include <rubberdyn/postprocess/load_path_body_columns.h>

namespace rubberdyn
{
  namespace postprocess
  {
    using namespace dealii;

    LoadPathBodyColumns::LoadPathBodyColumns(
      const model::Model                                     &model,
      const std::vector<unsigned int>                        &surface_body,
      const std::vector<const contact::RigidSurfaceForces *> &surfaces,
      const std::vector<HeldPartGroup>                       &held_groups,
      const std::vector<unsigned int>     &equilibrium_parts,
      const std::vector<model::RigidBody> &poses)
      : surface_body(surface_body)
      , surfaces(surfaces)
      , held_groups(held_groups)
      , poses(poses)
    {
      const char *xyz[3] = {"_x", "_y", "_z"};
      for (const model::RigidSurfaceDefinition &surface :
           model.rigid_surfaces)
        for (const std::string quantity : {"_position", "_force"})
          for (unsigned int d = 0; d < 3; ++d)
            columns.push_back(surface.name + quantity + xyz[d]);
      for (const model::Part &part : model.parts)
        if (part.rigid)
          for (unsigned int d = 0; d < 3; ++d)
            columns.push_back(part.name + "_force" + xyz[d]);
      for (const unsigned int p : equilibrium_parts)
        for (const std::string quantity : {"_position", "_rotation"})
          for (unsigned int d = 0; d < 3; ++d)
            columns.push_back(model.parts[p].name + quantity + xyz[d]);
    }



    std::string
    LoadPathBodyColumns::name() const
    {
      return "load path bodies";
    }



    std::vector<std::string>
    LoadPathBodyColumns::history_columns() const
    {
      return columns;
    }



    void
    LoadPathBodyColumns::history_values(const SimulationView &view,
                                        std::vector<double>  &values)
    {
      const model::Model &model = view.model();
      // The force of the solid on each surface (this rank's nodes, summed
      // in one reduction for all of them).
      std::vector<double> sums(3 * model.rigid_surfaces.size());
      for (unsigned int k = 0; k < model.rigid_surfaces.size(); ++k)
        for (unsigned int d = 0; d < 3; ++d)
          sums[3 * k + d] = surfaces[k]->last_result().force_on_plane[0][d];
      Utilities::MPI::sum(ArrayView<const double>(sums),
                          model.comm,
                          ArrayView<double>(sums));
      std::vector<Tensor<1, 3>> surface_force(model.rigid_surfaces.size());
      for (unsigned int k = 0; k < model.rigid_surfaces.size(); ++k)
        for (unsigned int d = 0; d < 3; ++d)
          surface_force[k][d] = sums[3 * k + d];
      // The surfaces: their point where their body is, and that force.
      for (unsigned int k = 0; k < model.rigid_surfaces.size(); ++k)
        {
          const Point<3> position =
            model.rigid_surfaces[k].surface.point +
            view.bodies()[surface_body[k]].displacement;
          for (unsigned int d = 0; d < 3; ++d)
            values.push_back(position[d]);
          for (unsigned int d = 0; d < 3; ++d)
            values.push_back(surface_force[k][d]);
        }
      // A rigid part: the force of the solid on it through its nodes
      // (minus the reaction of its held nodes) and through its surfaces.
      std::vector<Tensor<1, 3>> part_force(model.parts.size());
      for (const HeldPartGroup &held : held_groups)
        part_force[held.part][held.direction] -= view.reactions()[held.group];
      for (unsigned int k = 0; k < model.rigid_surfaces.size(); ++k)
        if (!model.rigid_surfaces[k].rigid_part.empty())
          part_force[model.part_index(model.rigid_surfaces[k].rigid_part)] +=
            surface_force[k];
      for (unsigned int p = 0; p < model.parts.size(); ++p)
        if (model.parts[p].rigid)
          for (unsigned int d = 0; d < 3; ++d)
            values.push_back(part_force[p][d]);
      // The parts in equilibrium: their centre of mass and their rotation
      // vector.
      for (const model::RigidBody &pose : poses)
        {
          const Point<3>     position = pose.current_reference_position();
          const Tensor<1, 3> rotation = model::rotation_vector(pose.rotation);
          for (unsigned int d = 0; d < 3; ++d)
            values.push_back(position[d]);
          for (unsigned int d = 0; d < 3; ++d)
            values.push_back(rotation[d]);
        }
    }
  } // namespace postprocess
} // namespace rubberdyn
