#include <deal.II/base/mpi.h>

#include <rubberdyn/elements/solid_hex_elements.h>
#include <rubberdyn/model/model.h>
#include <rubberdyn/model/rigid_body.h>
#include <rubberdyn/postprocess/history_columns.h>
#include <rubberdyn/time_integration/explicit_solver.h>

namespace rubberdyn
{
  namespace postprocess
  {
    namespace
    {
      /** name_x, name_y, name_z. */
      void
      add_vector_columns(const std::string &       name,
                         std::vector<std::string> &columns)
      {
        for (const char *suffix : {"_x", "_y", "_z"})
          columns.push_back(name + suffix);
      }

      void
      add_vector_values(const dealii::Tensor<1, 3> &value,
                        std::vector<double> &       values)
      {
        for (unsigned int d = 0; d < 3; ++d)
          values.push_back(value[d]);
      }
    } // namespace



    EnergyColumns::EnergyColumns(const bool with_friction_work)
      : with_friction_work(with_friction_work)
    {}



    std::string
    EnergyColumns::name() const
    {
      return "energies";
    }



    std::vector<std::string>
    EnergyColumns::history_columns() const
    {
      std::vector<std::string> columns = {"kinetic_energy",
                                          "internal_energy",
                                          "external_work",
                                          "contact_work",
                                          "bulk_viscosity_work",
                                          "added_mass",
                                          "energy_error"};
      if (with_friction_work)
        columns.push_back("friction_work");
      columns.push_back("energy_error_deformable");
      return columns;
    }



    void
    EnergyColumns::history_values(const SimulationView &view,
                                  std::vector<double> &  values)
    {
      const time_integration::ExplicitSolver &solver =
        explicit_solver_of(view, name());
      const auto &e = solver.energies();
      for (const double value :
           {e.kinetic, e.internal, e.external_work, e.contact,
            e.bulk_viscosity_work, solver.added_mass(),
            e.relative_error()})
        values.push_back(value);
      if (with_friction_work)
        values.push_back(e.friction_work);
      values.push_back(e.deformable_relative_error());
    }



    InternalEnergyColumns::InternalEnergyColumns(
      const std::vector<std::string> &part_names)
      : part_names(part_names)
    {}



    std::string
    InternalEnergyColumns::name() const
    {
      return "internal energy";
    }



    std::vector<std::string>
    InternalEnergyColumns::history_columns() const
    {
      std::vector<std::string> columns = {"internal_energy"};
      for (const std::string &part : part_names)
        columns.push_back(part + "_internal_energy");
      return columns;
    }



    void
    InternalEnergyColumns::history_values(const SimulationView &view,
                                          std::vector<double>  &values)
    {
      values.push_back(view.internal_energy());
      const std::vector<double> &by_group = view.internal_energy_by_group();
      for (unsigned int p = 0; p < part_names.size(); ++p)
        values.push_back(p < by_group.size() ? by_group[p] : 0.);
    }



    BoundaryReactionColumns::BoundaryReactionColumns(
      const std::vector<std::string> & names,
      const std::vector<unsigned int> &condition_of_group,
      const std::vector<unsigned int> &direction_of_group)
      : names(names)
      , condition_of_group(condition_of_group)
      , direction_of_group(direction_of_group)
    {}



    std::string
    BoundaryReactionColumns::name() const
    {
      return "boundary reactions";
    }



    std::vector<std::string>
    BoundaryReactionColumns::history_columns() const
    {
      std::vector<std::string> columns;
      for (const std::string &bc : names)
        {
          add_vector_columns(bc + "_force", columns);
          add_vector_columns(bc + "_moment", columns);
        }
      return columns;
    }



    void
    BoundaryReactionColumns::history_values(const SimulationView &view,
                                            std::vector<double> &  values)
    {
      std::vector<dealii::Tensor<1, 3>> force(names.size()),
        moment(names.size());
      const std::vector<double> &reactions = view.reactions();
      const auto                &moments   = view.reaction_moments();
      for (unsigned int g = 0; g < condition_of_group.size(); ++g)
        {
          force[condition_of_group[g]][direction_of_group[g]] += reactions[g];
          moment[condition_of_group[g]] += moments[g];
        }
      for (unsigned int c = 0; c < names.size(); ++c)
        {
          add_vector_values(force[c], values);
          add_vector_values(moment[c], values);
        }
    }



    PretensionSectionColumns::PretensionSectionColumns(
      const std::vector<std::string> &section_names)
      : section_names(section_names)
    {}



    std::string
    PretensionSectionColumns::name() const
    {
      return "pretension sections";
    }



    std::vector<std::string>
    PretensionSectionColumns::history_columns() const
    {
      std::vector<std::string> columns;
      for (const std::string &section : section_names)
        {
          columns.push_back(section + "_force");
          columns.push_back(section + "_shortening");
        }
      return columns;
    }



    void
    PretensionSectionColumns::history_values(const SimulationView &view,
                                             std::vector<double>  &values)
    {
      const std::vector<double>  force      = view.section_forces();
      const std::vector<double> &shortening = view.section_shortenings();
      for (unsigned int s = 0; s < section_names.size(); ++s)
        {
          values.push_back(force[s]);
          values.push_back(shortening[s]);
        }
    }



    CrossSectionColumns::CrossSectionColumns(
      const std::vector<std::string> &section_names)
      : section_names(section_names)
    {}



    std::string
    CrossSectionColumns::name() const
    {
      return "cross sections";
    }



    std::vector<std::string>
    CrossSectionColumns::history_columns() const
    {
      std::vector<std::string> columns;
      for (const std::string &section : section_names)
        {
          add_vector_columns(section + "_force", columns);
          add_vector_columns(section + "_moment", columns);
          add_vector_columns(section + "_centre", columns);
          for (const char *suffix :
               {"_axial_force", "_shear_force", "_torque", "_bending_moment"})
            columns.push_back(section + suffix);
        }
      return columns;
    }



    void
    CrossSectionColumns::history_values(const SimulationView &view,
                                        std::vector<double>  &values)
    {
      const std::vector<model::CrossSection> &sections =
        view.model().cross_sections;
      // (The section resultants are the hexahedra's: a cross section of a
      // mixed u-p part is refused when the model is read.)
      const auto *hexes =
        dynamic_cast<const elements::SolidHexElements *>(&view.elements());
      AssertThrow(hexes != nullptr,
                  dealii::ExcMessage("Cross sections need the F-bar or "
                                     "displacement elements"));
      std::vector<elements::SectionPlane> planes;
      for (const model::CrossSection &section : sections)
        planes.push_back({section.point, section.normal, section.part});
      const std::vector<elements::SectionResultant> local =
        hexes->section_resultants(view.displacement(), planes);
      // One sum over the ranks: force, moment about the origin, centre sum
      // and the number of cut elements of each section.
      std::vector<double> sums;
      for (const elements::SectionResultant &r : local)
        {
          for (unsigned int d = 0; d < 3; ++d)
            sums.push_back(r.force[d]);
          for (unsigned int d = 0; d < 3; ++d)
            sums.push_back(r.moment_about_origin[d]);
          for (unsigned int d = 0; d < 3; ++d)
            sums.push_back(r.centre_sum[d]);
          sums.push_back(r.n_cut);
        }
      dealii::Utilities::MPI::sum(dealii::ArrayView<const double>(sums),
                                  view.model().comm,
                                  dealii::ArrayView<double>(sums));
      for (unsigned int s = 0; s < sections.size(); ++s)
        {
          const double        *sum = &sums[10 * s];
          dealii::Tensor<1, 3> force, moment, centre;
          for (unsigned int d = 0; d < 3; ++d)
            {
              force[d]  = sum[d];
              moment[d] = sum[3 + d];
              centre[d] = sum[9] > 0. ? sum[6 + d] / sum[9] : 0.;
            }
          // About the centre: sum (x - c) x f = sum x x f - c x F.
          moment -= dealii::cross_product_3d(centre, force);
          const dealii::Tensor<1, 3> &n      = sections[s].normal;
          const double                axial  = force * n;
          const double                torque = moment * n;
          add_vector_values(force, values);
          add_vector_values(moment, values);
          add_vector_values(centre, values);
          values.push_back(axial);
          values.push_back((force - axial * n).norm());
          values.push_back(torque);
          values.push_back((moment - torque * n).norm());
        }
    }



    PartColumns::PartColumns(const std::vector<std::string> &part_names)
      : part_names(part_names)
    {}



    std::string
    PartColumns::name() const
    {
      return "part sums";
    }



    std::vector<std::string>
    PartColumns::history_columns() const
    {
      std::vector<std::string> columns;
      for (const std::string &part : part_names)
        {
          columns.push_back(part + "_kinetic_energy");
          columns.push_back(part + "_internal_energy");
          columns.push_back(part + "_bulk_viscosity_work");
          columns.push_back(part + "_gravity_work");
          add_vector_columns(part + "_momentum", columns);
        }
      return columns;
    }



    void
    PartColumns::history_values(const SimulationView &view,
                                std::vector<double> &  values)
    {
      const time_integration::ExplicitSolver &solver =
        explicit_solver_of(view, name());
      const auto &motion   = solver.motion_by_group();
      const auto &internal = solver.internal_energy_by_group();
      const auto &work     = solver.work_by_group();
      for (unsigned int p = 0; p < part_names.size(); ++p)
        {
          values.push_back(motion[p].kinetic_energy);
          values.push_back(internal[p]);
          values.push_back(work[p].bulk_viscosity);
          values.push_back(work[p].gravity);
          add_vector_values(motion[p].momentum, values);
        }
    }



    RigidBodyColumns::RigidBodyColumns(
      const std::vector<model::RigidBody> &bodies)
    {
      for (const model::RigidBody &body : bodies)
        {
          bool driven = false;
          for (unsigned int d = 0; d < 3; ++d)
            driven = driven || !body.moves_freely(d);
          this->bodies.push_back({body.name, body.carries_nodes, driven});
        }
    }



    std::string
    RigidBodyColumns::name() const
    {
      return "rigid bodies";
    }



    std::vector<std::string>
    RigidBodyColumns::history_columns() const
    {
      std::vector<std::string> columns;
      for (const BodyColumns &body : bodies)
        {
          add_vector_columns(body.name + "_position", columns);
          add_vector_columns(body.name + "_velocity", columns);
          add_vector_columns(body.name + "_force", columns);
          if (body.rotating)
            {
              add_vector_columns(body.name + "_rotation", columns);
              add_vector_columns(body.name + "_angular_velocity", columns);
              add_vector_columns(body.name + "_moment", columns);
            }
          else
            {
              columns.push_back(body.name + "_kinetic_energy");
              columns.push_back(body.name + "_gravity_work");
            }
          if (body.driven)
            columns.push_back(body.name + "_drive_work");
        }
      return columns;
    }



    void
    RigidBodyColumns::history_values(const SimulationView &view,
                                     std::vector<double> &  values)
    {
      const auto &energies = explicit_solver_of(view, name()).body_energies();
      for (unsigned int b = 0; b < bodies.size(); ++b)
        {
          const model::RigidBody &body = view.bodies()[b];
          add_vector_values(body.reference_position + body.displacement,
                            values);
          add_vector_values(body.velocity, values);
          add_vector_values(body.contact_force, values);
          if (bodies[b].rotating)
            {
              add_vector_values(model::rotation_vector(body.rotation), values);
              add_vector_values(body.angular_velocity, values);
              add_vector_values(body.contact_moment, values);
            }
          else
            {
              values.push_back(energies[b].kinetic);
              values.push_back(energies[b].gravity_work);
            }
          if (bodies[b].driven)
            values.push_back(energies[b].drive_work);
        }
    }
  } // namespace postprocess
} // namespace rubberdyn
