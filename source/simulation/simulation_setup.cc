#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>

#include <rubberdyn/base/durable_files.h>
#include <rubberdyn/base/exceptions.h>
#include <rubberdyn/contact/mortar_contact_pair.h>
#include <rubberdyn/contact/rigid_surface_contact.h>
#include <rubberdyn/contact/rigid_surface_forces.h>
#include <rubberdyn/model/model.h>
#include <rubberdyn/postprocess/contact_pair_columns.h>
#include <rubberdyn/simulation/simulation_setup.h>
#include <rubberdyn/model/surface_loads.h>
#include <rubberdyn/time_integration/kinematic_constraints.h>

#include <cmath>
#include <iomanip>
#include <ostream>
#include <set>
#include <sstream>
#include <stdexcept>

namespace rubberdyn
{
  namespace simulation
  {
    using namespace model;

    namespace setup
    {
      std::vector<elements::ElementGroup>
      element_groups(const Model                       &model,
                     const parameters::TimeIntegration &time_integration)
      {
        unsigned int n_fbar_parts = 0;
        for (const Part &part : model.parts)
          if (!part.rigid && part.formulation == elements::Formulation::fbar)
            ++n_fbar_parts;
        const std::string model_entry = "Time integration/F-bar stabilization";
        std::vector<elements::ElementGroup> groups;
        // A rigid part's group has no cells: no element forces, no step.
        for (const Part &part : model.parts)
          {
            const bool fbar =
              !part.rigid && part.formulation == elements::Formulation::fbar;
            const double beta =
              fbar ? part.fbar_stabilization.value_or(
                       time_integration.fbar_stabilization) :
                     0.;
            // The entry a hull collapse's message names: the part's own,
            // if it has one; else, with several deformable F-bar parts,
            // both the part's and the model's (the model-wide one alone
            // would leave the user to find the part).
            const std::string part_entry =
              "Parts/" + part.name + "/F-bar stabilization";
            std::string entry = model_entry;
            if (part.fbar_stabilization)
              entry = part_entry;
            else if (n_fbar_parts > 1)
              entry = part_entry + " (this part) or " + model_entry +
                      " (every part without its own)";
            // 0.03 is where the stabilisation starts to hold the hull
            // instability in the drop test (doc/theory.md 8.1).
            std::ostringstream advice;
            if (beta < 0.03)
              advice << "set " << entry << " to 0.03 or more";
            else
              advice << "raise " << entry << " above "
                     << std::setprecision(3) << beta;
            groups.push_back(
              {part.rigid ? std::set<types::material_id>() : part.material_ids,
               part.law.get(),
               part.formulation,
               beta,
               advice.str()});
          }
        return groups;
      }



      elements::ElementSettings
      element_settings(const parameters::TimeIntegration &time_integration)
      {
        elements::ElementSettings settings;
        settings.bulk_viscosity_linear = time_integration.bulk_viscosity_linear;
        settings.bulk_viscosity_quadratic =
          time_integration.bulk_viscosity_quadratic;
        return settings;
      }



      void
      add_kinematic_constraints(
        const Model                            &model,
        time_integration::KinematicConstraints &constraints,
        std::vector<unsigned int>              &condition_of_group,
        std::vector<unsigned int>              &direction_of_group)
      {
        using time_integration::KinematicConstraints;
        for (unsigned int c = 0; c < model.boundary_conditions.size(); ++c)
          {
            const BoundaryCondition &bc   = model.boundary_conditions[c];
            const std::string        path = "Boundary conditions/" + bc.name;
            const auto zero = [](const Point<3> &, double) { return 0.; };
            const auto add  = [&](const unsigned int               direction,
                                 const KinematicConstraints::Kind kind,
                                 const KinematicConstraints::Function &function,
                                 const bool depends_on_position) {
              constraints.prescribe(path,
                                    bc.boundary_ids,
                                    direction,
                                    kind,
                                    function,
                                    depends_on_position,
                                    bc.moment_point);
              condition_of_group.push_back(c);
              direction_of_group.push_back(direction);
            };
            switch (bc.type)
              {
                case BoundaryCondition::Type::fixed:
                  for (const unsigned int d : bc.components)
                    add(d, KinematicConstraints::Kind::velocity, zero, false);
                  break;
                case BoundaryCondition::Type::displacement:
                case BoundaryCondition::Type::velocity:
                  for (unsigned int k = 0; k < bc.components.size(); ++k)
                    add(bc.components[k],
                        bc.type == BoundaryCondition::Type::velocity ?
                          KinematicConstraints::Kind::velocity :
                          KinematicConstraints::Kind::displacement,
                        bc.functions[k],
                        bc.depends_on_position);
                  break;
                case BoundaryCondition::Type::symmetry:
                  add(constraints.plane_normal_direction(path, bc.boundary_ids),
                      KinematicConstraints::Kind::velocity,
                      zero,
                      false);
                  break;
                case BoundaryCondition::Type::pressure:
                case BoundaryCondition::Type::traction:
                  break;
              }
          }
      }



      std::unique_ptr<SurfaceLoads>
      surface_loads(const Model               &model,
                    std::vector<unsigned int> &condition_of_load)
      {
        std::vector<BoundaryCondition> loads;
        for (unsigned int c = 0; c < model.boundary_conditions.size(); ++c)
          {
            const BoundaryCondition &bc = model.boundary_conditions[c];
            if (bc.type == BoundaryCondition::Type::pressure ||
                bc.type == BoundaryCondition::Type::traction)
              {
                loads.push_back(bc);
                condition_of_load.push_back(c);
              }
          }
        if (loads.empty())
          return nullptr;
        return std::make_unique<SurfaceLoads>(model.dof_handler,
                                              model.partitioner,
                                              loads);
      }



      /**
       * The error of a section (pretension or cross section, at @p prefix)
       * whose plane cuts no element of its part.
       */
      template <typename Section>
      [[noreturn]] void
      throw_plane_misses_part(const Model       &model,
                              const std::string &prefix,
                              const Section     &section)
      {
        std::ostringstream where;
        where << "the plane through (" << section.point << ") with normal ("
              << section.normal << ") cuts no element of the part '"
              << model.parts[section.part].name
              << "': it misses the part, or lies on element faces (move it "
                 "inside a layer of elements)";
        throw InputError(prefix + section.name + "/Point", where.str());
      }



      std::vector<unsigned int>
      cut_pretension_sections(const Model                &model,
                              elements::SolidHexElements &hexes)
      {
        const std::vector<PretensionSection> &sections =
          model.pretension_sections;
        std::vector<elements::SectionPlane> planes;
        for (const PretensionSection &section : sections)
          planes.push_back({section.point, section.normal, section.part});
        std::vector<unsigned int> n_cut;
        std::string               error;
        try
          {
            n_cut = hexes.cut_sections(planes);
          }
        catch (const std::invalid_argument &e)
          {
            error = e.what();
            n_cut.assign(sections.size(), 0);
          }
        // (An element cut twice on one rank ends every rank.)
        durable_files::throw_if_any(model.comm,
                                    "Pretension sections/Names",
                                    error);
        Utilities::MPI::sum(ArrayView<const unsigned int>(n_cut),
                            model.comm,
                            ArrayView<unsigned int>(n_cut));
        for (unsigned int s = 0; s < sections.size(); ++s)
          if (n_cut[s] == 0)
            throw_plane_misses_part(model,
                                    "Pretension sections/",
                                    sections[s]);
        return n_cut;
      }



      void
      check_cross_sections(const Model                      &model,
                           const elements::SolidHexElements &hexes)
      {
        if (model.cross_sections.empty())
          return;
        std::vector<elements::SectionPlane> planes;
        for (const CrossSection &section : model.cross_sections)
          planes.push_back({section.point, section.normal, section.part});
        // (Where the planes cut depends on the reference positions only.)
        const VectorType zero(model.partitioner);
        const std::vector<elements::SectionResultant> resultants =
          hexes.section_resultants(zero, planes);
        for (unsigned int s = 0; s < planes.size(); ++s)
          if (Utilities::MPI::sum(resultants[s].n_cut, model.comm) == 0)
            throw_plane_misses_part(model,
                                    "Cross sections/",
                                    model.cross_sections[s]);
      }



      void
      add_rigid_surfaces(
        const Model                                             &model,
        const std::vector<unsigned int>                         &body_of_surface,
        std::vector<std::unique_ptr<contact::RigidSurfaceContact>> &contacts,
        std::vector<std::unique_ptr<contact::RigidSurfaceForces>>  &forces,
        std::vector<model::ForceContribution *> &contributions)
      {
        AssertDimension(body_of_surface.size(), model.rigid_surfaces.size());
        // The penalty stiffness s K A^2 / V takes the bulk modulus of the
        // element under each face.
        std::vector<double> bulk_modulus_by_material;
        for (const Part &part : model.parts)
          for (const types::material_id id : part.material_ids)
            {
              if (bulk_modulus_by_material.size() <= id)
                bulk_modulus_by_material.resize(id + 1, 0.);
              bulk_modulus_by_material[id] = part.law->bulk_modulus();
            }
        for (unsigned int s = 0; s < model.rigid_surfaces.size(); ++s)
          {
            const RigidSurfaceDefinition &definition = model.rigid_surfaces[s];
            contacts.push_back(std::make_unique<contact::RigidSurfaceContact>());
            contacts.back()->initialize(model.dof_handler,
                                        model.partitioner,
                                        definition.boundary_ids,
                                        bulk_modulus_by_material,
                                        definition.penalty_scale,
                                        {definition.surface});
            forces.push_back(std::make_unique<contact::RigidSurfaceForces>(
              *contacts.back(), std::vector<unsigned int>{body_of_surface[s]}));
            contributions.push_back(forces.back().get());
          }
      }



      void
      add_contact_pairs(
        const Model                                             &model,
        std::vector<std::unique_ptr<contact::MortarContactPair>> &pairs,
        std::vector<model::ForceContribution *> &contributions)
      {
        for (const ContactPairDefinition &pair : model.contact_pairs)
          {
            pairs.push_back(
              std::make_unique<contact::MortarContactPair>(model, pair));
            contributions.push_back(pairs.back().get());
          }
      }



      void
      log_initial_penetrations(Model &model, std::ostream &log)
      {
        if (!model.initial_penetrations || model.initial_penetrations_logged)
          return;
        model.initial_penetrations_logged = true;
        if (Utilities::MPI::this_mpi_process(model.comm) != 0)
          return;
        using parameters::InitialPenetration;
        for (const InitialPenetrationReport &report :
             *model.initial_penetrations)
          {
            const std::string choice = " (" + report.entry + " = " +
                                       parameters::to_string(report.action) +
                                       ")";
            if (report.action == InitialPenetration::move_slave_nodes_out)
              log << "  " << report.interaction << ": " << report.found
                  << "; moved out onto it" << choice << ": " << report.n_moved
                  << " nodes' reference coordinates changed, by up to "
                  << report.max_move << " mm" << std::endl;
            else
              log << "  WARNING: " << report.interaction << ": " << report.found
                  << "; kept" << choice
                  << ": the penalty pushes them out from the first step"
                  << std::endl;
          }
      }



      std::string
      initial_penetrations_json(const Model &model)
      {
        // Nine digits, as the summary's other numbers.
        const auto number = [](const double value) {
          std::ostringstream s;
          s << std::setprecision(9) << value;
          return s.str();
        };
        std::string text = "[";
        if (model.initial_penetrations)
          for (const InitialPenetrationReport &report :
               *model.initial_penetrations)
            text += std::string(text.size() > 1 ? ", " : "") +
                    "{\"interaction\": \"" + report.interaction +
                    "\", \"nodes\": " + std::to_string(report.n_nodes) +
                    ", \"max_penetration\": " + number(report.max_penetration) +
                    ", \"at\": [" + number(report.where[0]) + ", " +
                    number(report.where[1]) + ", " + number(report.where[2]) +
                    "], \"action\": \"" + parameters::to_string(report.action) +
                    "\", \"moved_nodes\": " + std::to_string(report.n_moved) +
                    ", \"max_move\": " + number(report.max_move) + "}";
        return text + "]";
      }



      std::vector<VectorType>
      part_masses(const Model &model)
      {
        std::vector<VectorType> masses(model.parts.size());
        for (VectorType &m : masses)
          m.reinit(model.partitioner);
        FEValues<3> fe_values(model.fe, QGauss<3>(2),
                              update_values | update_JxW_values);
        const unsigned int n_dofs = model.fe.n_dofs_per_cell();
        std::vector<types::global_dof_index> dofs(n_dofs);
        for (const auto &cell : model.dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              const unsigned int p =
                model.part_of_material_id(cell->material_id());
              const double density = model.parts[p].law->density();
              fe_values.reinit(cell);
              cell->get_dof_indices(dofs);
              for (unsigned int i = 0; i < n_dofs; ++i)
                {
                  const unsigned int component =
                    model.fe.system_to_component_index(i).first;
                  double m = 0.;
                  for (const unsigned int q :
                       fe_values.quadrature_point_indices())
                    m += density *
                         fe_values.shape_value_component(i, q, component) *
                         fe_values.JxW(q);
                  masses[p](dofs[i]) += m;
                }
            }
        for (VectorType &m : masses)
          m.compress(VectorOperation::add);
        return masses;
      }



      Point<3>
      rigid_part_centre_of_mass(const Model                   &model,
                                const unsigned int             p,
                                const std::vector<VectorType> &masses)
      {
        // Each owned support point of the part's cells once: the nodal
        // mass (of its x dof) times its position.
        const FiniteElement<3> &fe       = model.fe;
        const unsigned int      n_points = fe.n_dofs_per_cell() / 3;
        std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
        std::set<types::global_dof_index>    seen;
        double                               sums[4] = {0., 0., 0., 0.};
        const MappingQ1<3>                   mapping;
        for (const auto &cell : model.dof_handler.active_cell_iterators())
          if ((cell->is_locally_owned() || cell->is_ghost()) &&
              model.part_of_material_id(cell->material_id()) == p)
            {
              cell->get_dof_indices(dofs);
              for (unsigned int k = 0; k < n_points; ++k)
                {
                  const types::global_dof_index dof =
                    dofs[fe.component_to_system_index(0, k)];
                  if (!model.partitioner->in_local_range(dof) ||
                      !seen.insert(dof).second)
                    continue;
                  double m = 0.;
                  for (const VectorType &mass : masses)
                    m += mass(dof);
                  const Point<3> X = mapping.transform_unit_to_real_cell(
                    cell, fe.base_element(0).unit_support_point(k));
                  sums[0] += m;
                  for (unsigned int d = 0; d < 3; ++d)
                    sums[1 + d] += m * X[d];
                }
            }
        Utilities::MPI::sum(ArrayView<const double>(sums, 4),
                            model.comm,
                            ArrayView<double>(sums, 4));
        AssertThrow(sums[0] > 0.,
                    ExcMessage("The rigid part '" + model.parts[p].name +
                               "' has no mass"));
        Point<3> centre;
        for (unsigned int d = 0; d < 3; ++d)
          centre[d] = sums[1 + d] / sums[0];
        return centre;
      }
    std::unique_ptr<postprocess::Postprocessor>
    contact_pair_columns(
      const Model                                                    &model,
      const std::vector<std::unique_ptr<contact::MortarContactPair>> &pairs)
    {
      if (pairs.empty())
        return nullptr;
      std::vector<std::string>                         names;
      std::vector<const contact::MortarContactPair *> views;
      for (unsigned int p = 0; p < pairs.size(); ++p)
        {
          names.push_back(model.contact_pairs[p].name);
          views.push_back(pairs[p].get());
        }
      return std::make_unique<postprocess::ContactPairColumns>(views,
                                                               names,
                                                               model.comm);
    }



    } // namespace setup
  }   // namespace simulation
} // namespace rubberdyn
