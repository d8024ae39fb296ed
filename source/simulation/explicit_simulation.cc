#include <deal.II/base/parameter_handler.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/base/quadrature_lib.h>

#include <rubberdyn/base/exceptions.h>
#include <rubberdyn/base/parameter_tools.h>
#include <rubberdyn/contact/initial_penetrations.h>
#include <rubberdyn/contact/mortar_contact_pair.h>
#include <rubberdyn/contact/rigid_surface_forces.h>
#include <rubberdyn/elements/solid_hex_forces.h>
#include <rubberdyn/simulation/explicit_simulation.h>
#include <rubberdyn/simulation/simulation_setup.h>
#include <rubberdyn/model/rigid_part_mass.h>
#include <rubberdyn/postprocess/mass_scaling_columns.h>
#include <rubberdyn/simulation/selective_mass_scaling_setup.h>
#include <rubberdyn/model/surface_loads.h>
#include <rubberdyn/postprocess/contact_pair_columns.h>
#include <rubberdyn/postprocess/history_columns.h>
#include <rubberdyn/postprocess/history_expressions.h>
#include <rubberdyn/postprocess/history_nodes.h>
#include <rubberdyn/postprocess/interaction_columns.h>
#include <rubberdyn/postprocess/time_history.h>
#include <rubberdyn/time_integration/explicit_solver.h>
#include <rubberdyn/time_integration/kinematic_constraints.h>

#include <array>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <limits>
#include <map>
#include <ostream>
#include <sstream>

namespace rubberdyn
{
  namespace simulation
  {
    using namespace model;

    using time_integration::KinematicConstraints;

    std::string
    ExplicitSimulation::model_parameters_text(const ParameterHandler &prm)
    {
      std::ostringstream all;
      prm.print_parameters(all, ParameterHandler::ShortPRM);
      std::istringstream lines(all.str());
      std::string        line, text;
      unsigned int       output_depth = 0;
      while (std::getline(lines, line))
        {
          const auto        first = line.find_first_not_of(' ');
          const std::string entry =
            first == std::string::npos ? "" : line.substr(first);
          if (output_depth > 0)
            {
              if (entry.rfind("subsection", 0) == 0)
                ++output_depth;
              else if (entry == "end")
                --output_depth;
              continue;
            }
          if (entry == "subsection Output")
            {
              output_depth = 1;
              continue;
            }
          if (entry.rfind("set End time", 0) == 0 || entry.empty() ||
              entry[0] == '#')
            continue;
          text += entry + '\n';
        }
      return text;
    }



    namespace
    {
      /**
       * The owned nodes of part @p p (its cells' vertices whose dofs this
       * rank owns), with their reference positions.
       */
      time_integration::RigidPartNodes
      owned_nodes_of_part(const Model &model, const unsigned int p)
      {
        time_integration::RigidPartNodes nodes;
        std::set<unsigned int>           seen;
        const unsigned int n_dofs = model.fe.n_dofs_per_cell();
        std::vector<types::global_dof_index> dofs(n_dofs);
        for (const auto &cell : model.dof_handler.active_cell_iterators())
          if ((cell->is_locally_owned() || cell->is_ghost()) &&
              model.part_of_material_id(cell->material_id()) == p)
            {
              cell->get_dof_indices(dofs);
              for (const unsigned int vertex : cell->vertex_indices())
                {
                  std::array<unsigned int, 3> local;
                  bool                        owned = true;
                  for (unsigned int d = 0; d < 3; ++d)
                    {
                      const types::global_dof_index dof =
                        dofs[model.fe.component_to_system_index(d, vertex)];
                      owned = owned && model.partitioner->in_local_range(dof);
                      if (owned)
                        local[d] = model.partitioner->global_to_local(dof);
                    }
                  if (owned && seen.insert(local[0]).second)
                    {
                      nodes.dofs.push_back(local);
                      nodes.X.push_back(cell->vertex(vertex));
                    }
                }
            }
        return nodes;
      }

      /**
       * Mass, centre and inertia of rigid part @p p on @p body: the mass
       * its nodes carry in the solver (@p nodal_mass: its cells' lumped
       * mass, @p part_mass, and what deformable neighbours add to shared
       * nodes); the centre of that nodal mass (so that gravity has no
       * moment about it); the inertia of its cells by Gauss quadrature (a
       * lumped inertia of a coarse mesh is far off: +50 % for two
       * elements across) plus the neighbours' share as point masses.
       */
      void
      set_rigid_part_inertia(const Model &                           model,
                             const unsigned int                      p,
                             const time_integration::RigidPartNodes &nodes,
                             const VectorType &                      nodal_mass,
                             const VectorType &                      part_mass,
                             RigidBody &                             body)
      {
        double sums[4] = {0., 0., 0., 0.};
        for (unsigned int n = 0; n < nodes.dofs.size(); ++n)
          {
            const double m = nodal_mass.local_element(nodes.dofs[n][0]);
            sums[0] += m;
            for (unsigned int d = 0; d < 3; ++d)
              sums[1 + d] += m * nodes.X[n][d];
          }
        Utilities::MPI::sum(ArrayView<const double>(sums, 4),
                            model.comm,
                            ArrayView<double>(sums, 4));
        body.mass = sums[0];
        for (unsigned int d = 0; d < 3; ++d)
          body.reference_position[d] = sums[1 + d] / sums[0];
        const Point<3> &c = body.reference_position;
        const auto point_inertia = [](const Tensor<1, 3> &r, const double m) {
          Tensor<2, 3> J;
          for (unsigned int i = 0; i < 3; ++i)
            for (unsigned int j = 0; j < 3; ++j)
              J[i][j] = m * ((i == j ? r.norm_square() : 0.) - r[i] * r[j]);
          return J;
        };
        Tensor<2, 3> inertia;
        for (unsigned int n = 0; n < nodes.dofs.size(); ++n)
          {
            const unsigned int i = nodes.dofs[n][0];
            inertia += point_inertia(nodes.X[n] - c,
                                     nodal_mass.local_element(i) -
                                       part_mass.local_element(i));
          }
        FEValues<3> fe_values(model.fe, QGauss<3>(2),
                              update_quadrature_points | update_JxW_values);
        const double density = model.parts[p].law->density();
        for (const auto &cell : model.dof_handler.active_cell_iterators())
          if (cell->is_locally_owned() &&
              model.part_of_material_id(cell->material_id()) == p)
            {
              fe_values.reinit(cell);
              for (const unsigned int q : fe_values.quadrature_point_indices())
                inertia += point_inertia(fe_values.quadrature_point(q) - c,
                                         density * fe_values.JxW(q));
            }
        double values[9];
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = 0; j < 3; ++j)
            values[3 * i + j] = inertia[i][j];
        Utilities::MPI::sum(ArrayView<const double>(values, 9),
                            model.comm,
                            ArrayView<double>(values, 9));
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = 0; j < 3; ++j)
            body.inertia[i][j] = values[3 * i + j];
      }

    } // namespace



    ExplicitSimulation::ExplicitSimulation(
      Model &                             model,
      const parameters::TimeIntegration &time_integration,
      const parameters::Output &          output,
      const std::string &                 title,
      const std::string &                 model_parameters)
      : model(model)
      , time_integration(time_integration)
      , output(output)
      , title(title)
      , model_parameters(model_parameters)
    {
      // Slave nodes that start inside their master surface: reported,
      // moved out or refused before anything is built from the mesh (a
      // hand-off's load path has done it already).
      contact::resolve_initial_penetrations(model);

      build_elements();
      const std::vector<double> density_scaling = mass_scaling_factors();
      element_forces =
        std::make_unique<elements::SolidHexForces>(*elements, density_scaling);
      // Selective mass scaling: mass on the deformation modes of the
      // elements below their part's target step; their stable steps grow.
      SelectiveMassScalingSetup mass_scaling =
        setup::selective_mass_scaling(model, time_integration, *elements);
      mass_scaling_parts = mass_scaling.parts;
      if (mass_scaling.scaling)
        elements->set_time_step_factors(mass_scaling.time_step_factors);
      check_number_of_steps();
      set_added_mass(density_scaling);

      // The contributions in the order the solver sums their forces:
      // elements, the rigid parts' mass, rigid surfaces, contact pairs,
      // surface loads.
      std::vector<model::ForceContribution *> contributions = {
        element_forces.get()};
      const std::vector<VectorType> mass_of_part = setup::part_masses(model);
      add_rigid_part_mass(mass_of_part, contributions);
      build_bodies();
      setup::add_rigid_surfaces(
        model, body_of_surface(), contacts, contact_forces, contributions);
      setup::add_contact_pairs(model, contact_pairs, contributions);

      // Boundary conditions: one constraint group per component.
      constraints =
        std::make_unique<KinematicConstraints>(model.dof_handler,
                                               model.partitioner);
      setup::add_kinematic_constraints(model, *constraints, condition_of_group,
                                       direction_of_group);

      // Pressures and tractions: one contribution for all of them.
      surface_loads = setup::surface_loads(model, condition_of_load);
      if (surface_loads)
        contributions.push_back(surface_loads.get());

      build_solver(contributions, mass_of_part);
      set_initial_velocities();
      attach_rigid_parts(mass_of_part);
      if (mass_scaling.scaling)
        explicit_solver->set_selective_mass_scaling(
          std::move(mass_scaling.scaling));
    }



    void
    ExplicitSimulation::build_elements()
    {
      // Elements: one group per part (its law and formulation).
      const std::vector<elements::ElementGroup> groups =
        setup::element_groups(model, time_integration);
      const elements::ElementSettings element_settings =
        setup::element_settings(time_integration);
      elements = std::make_unique<elements::SolidHexElements>();
      elements->initialize(model.dof_handler, model.partitioner, groups,
                           element_settings);
      // Pretension sections (locked: their shortenings come with the
      // preload, start_from()).
      if (!model.pretension_sections.empty())
        setup::cut_pretension_sections(model, *elements);
      // Cross sections: each must cut an element of its part.
      setup::check_cross_sections(model, *elements);
    }



    std::vector<double>
    ExplicitSimulation::mass_scaling_factors() const
    {
      // Mass scaling: elements whose stable step is below the target get
      // added density.
      std::vector<double> density_scaling(elements->n_elements(), 1.);
      if (time_integration.mass_scaling_time_step > 0.)
        {
          const std::vector<double> steps = elements->reference_time_steps();
          for (unsigned int e = 0; e < steps.size(); ++e)
            {
              const double step = time_integration.time_step_scale * steps[e];
              if (step < time_integration.mass_scaling_time_step)
                density_scaling[e] =
                  std::pow(time_integration.mass_scaling_time_step / step, 2);
            }
        }
      {
        // The largest factor must be a number: the target step is at most
        // the End time (TimeIntegration::parse_parameters()), but a target
        // near a huge End time over a small element still overflows the
        // square (1e300 ms over 3e-3 ms gives inf).
        double largest = 1.;
        for (const double factor : density_scaling)
          largest = std::max(largest, factor);
        parameter_tools::require_usable(
          Utilities::MPI::max(largest, model.comm),
          "Time integration/Mass scaling time step",
          "the density factor (target step / stable step)^2 of the smallest "
          "element",
          "");
      }
      return density_scaling;
    }



    void
    ExplicitSimulation::check_number_of_steps() const
    {
      // Refuse a run that could never end (End time = 1e308) before
      // anything runs, in `--check` too. The step changes as the model
      // deforms (contact and compression shrink it), so the count is an
      // estimate; the limit is four orders above any real run.
      const double first_step =
        time_integration.time_step_scale * smallest_element_time_step();
      // The solver's first step is at most first_step (contact can only
      // shorten it): a Minimum time step above it stops every run at its
      // first step, after writing the state.
      if (time_integration.minimum_time_step > first_step)
        throw InputError(
          "Time integration/Minimum time step",
          "is " +
            parameter_tools::format_short(
              time_integration.minimum_time_step) +
            " ms, above the first stable time step of " +
            parameter_tools::format_short(first_step) +
            " ms: the run would stop at its first step");
      const double n_steps = time_integration.end_time / first_step;
      if (n_steps > parameters::TimeIntegration::max_time_steps)
        throw InputError(
          "Time integration/End time",
          "is " + parameter_tools::format_short(time_integration.end_time) +
            " ms: at the first stable time step of " +
            parameter_tools::format_short(first_step) +
            " ms the run would take " +
            parameter_tools::format_short(n_steps) +
            " steps, more than the limit of " +
            parameter_tools::format_short(
              parameters::TimeIntegration::max_time_steps) +
            "; shorten the End time");
    }



    void
    ExplicitSimulation::set_added_mass(const std::vector<double> &density_scaling)
    {
      // The mass with the scaled densities less the physical mass.
      added_mass_by_part = elements->mass_by_group(density_scaling);
      const std::vector<double> physical = elements->mass_by_group(
        std::vector<double>(density_scaling.size(), 1.));
      for (unsigned int i = 0; i < added_mass_by_part.size(); ++i)
        added_mass_by_part[i] -= physical[i];
      Utilities::MPI::sum(ArrayView<const double>(added_mass_by_part),
                          model.comm,
                          ArrayView<double>(added_mass_by_part));
    }



    void
    ExplicitSimulation::add_rigid_part_mass(
      const std::vector<VectorType>           &mass_of_part,
      std::vector<model::ForceContribution *> &contributions)
    {
      // The rigid parts' cells give only their lumped mass.
      VectorType rigid_mass(model.partitioner);
      bool       any_rigid = false;
      for (unsigned int p = 0; p < model.parts.size(); ++p)
        if (model.parts[p].rigid)
          {
            rigid_mass += mass_of_part[p];
            any_rigid = true;
          }
      if (any_rigid)
        {
          rigid_part_mass = std::make_unique<RigidPartMass>(rigid_mass);
          contributions.push_back(rigid_part_mass.get());
        }
    }



    void
    ExplicitSimulation::build_bodies()
    {
      // The bodies: those of the rigid surfaces that have their own, in
      // their order, then those of the rigid parts.
      for (const RigidSurfaceDefinition &definition : model.rigid_surfaces)
        if (definition.rigid_part.empty())
          bodies.push_back(definition.body);
      body_of_part.assign(model.parts.size(), numbers::invalid_unsigned_int);
      for (unsigned int p = 0; p < model.parts.size(); ++p)
        if (model.parts[p].rigid)
          {
            const Part &part = model.parts[p];
            body_of_part[p]  = bodies.size();
            RigidBody body;
            body.name = part.name;
            for (unsigned int d = 0; d < 3; ++d)
              {
                body.free[d]          = part.rigid_free_translation[d];
                body.free_rotation[d] = part.rigid_free_rotation[d];
                body.velocity[d] =
                  body.free[d] ? part.initial_velocity[d] : 0.;
                body.angular_velocity[d] =
                  body.free_rotation[d] ? part.initial_angular_velocity[d] :
                                          0.;
              }
            // Mass, centre and inertia once the nodal masses are known.
            body.mass = 1.;
            bodies.push_back(body);
          }
    }



    std::vector<unsigned int>
    ExplicitSimulation::body_of_surface() const
    {
      // One contact per rigid surface, each surface carried by its body.
      std::vector<unsigned int> body_of_surface;
      for (unsigned int s = 0, own = 0; s < model.rigid_surfaces.size(); ++s)
        {
          const RigidSurfaceDefinition &definition = model.rigid_surfaces[s];
          body_of_surface.push_back(
            definition.rigid_part.empty() ?
              own++ :
              body_of_part[model.part_index(definition.rigid_part)]);
        }
      return body_of_surface;
    }



    void
    ExplicitSimulation::build_solver(
      const std::vector<model::ForceContribution *> &contributions,
      const std::vector<VectorType>                 &mass_of_part)
    {
      time_integration::ExplicitSettings settings;
      settings.time_step_scale   = time_integration.time_step_scale;
      settings.minimum_time_step = time_integration.minimum_time_step;
      settings.assembled_step_estimate =
        time_integration.assembled_step_estimate;
      settings.assembled_step.refresh_interval =
        time_integration.stable_step_refresh_interval;
      settings.gravity           = model.gravity;
      settings.n_groups          = std::max<unsigned int>(1, model.parts.size());
      explicit_solver = std::make_unique<time_integration::ExplicitSolver>(
        model.dof_handler, contributions, bodies, constraints.get(),
        model.partitioner, settings, model.comm);
      if (model.parts.size() > 1)
        explicit_solver->set_group_masses(mass_of_part);
    }



    void
    ExplicitSimulation::set_initial_velocities()
    {
      // Initial velocities of the parts (a node shared by two parts takes
      // the velocity of the later one).
      VectorType initial_velocity(model.partitioner);
      {
        const unsigned int n_dofs = model.fe.n_dofs_per_cell();
        std::vector<types::global_dof_index> dofs(n_dofs);
        for (const auto &cell : model.dof_handler.active_cell_iterators())
          if (cell->is_locally_owned() || cell->is_ghost())
            {
              const Part &part =
                model.parts[model.part_of_material_id(cell->material_id())];
              cell->get_dof_indices(dofs);
              for (unsigned int i = 0; i < n_dofs; ++i)
                if (model.partitioner->in_local_range(dofs[i]))
                  initial_velocity(dofs[i]) =
                    part.initial_velocity
                      [model.fe.system_to_component_index(i).first];
            }
      }
      explicit_solver->set_initial_velocity(initial_velocity);
    }



    void
    ExplicitSimulation::attach_rigid_parts(
      const std::vector<VectorType> &mass_of_part)
    {
      // Rigid parts: their nodes follow their bodies. A boundary condition
      // on them would fight the body: refused, naming both.
      std::vector<time_integration::RigidPartNodes> rigid_nodes;
      for (unsigned int p = 0; p < model.parts.size(); ++p)
        if (model.parts[p].rigid)
          {
            time_integration::RigidPartNodes nodes =
              owned_nodes_of_part(model, p);
            nodes.body  = body_of_part[p];
            nodes.group = p;
            set_rigid_part_inertia(model, p, nodes,
                                   explicit_solver->lumped_mass(),
                                   mass_of_part[p], bodies[body_of_part[p]]);
            rigid_nodes.push_back(std::move(nodes));
          }
      if (!rigid_nodes.empty())
        {
          std::string message;
          std::vector<int> part_of_dof(model.partitioner->locally_owned_size(),
                                       -1);
          for (const auto &nodes : rigid_nodes)
            for (const auto &node : nodes.dofs)
              for (const unsigned int i : node)
                part_of_dof[i] = nodes.group;
          for (const KinematicConstraints::Entry &entry :
               constraints->entries())
            if (part_of_dof[entry.dof] >= 0 && message.empty())
              message =
                "Boundary conditions/" +
                model.boundary_conditions[condition_of_group[entry.group]]
                  .name +
                "/Boundary ids: a node of the rigid part '" +
                model.parts[part_of_dof[entry.dof]].name +
                "' is in this condition; a rigid part moves as its Rigid "
                "motion says (fixed, or free directions), not by boundary "
                "conditions";
          const std::vector<std::string> messages =
            Utilities::MPI::all_gather(model.comm, message);
          for (const std::string &m : messages)
            if (!m.empty())
              {
                const auto colon = m.find(": ");
                throw InputError(m.substr(0, colon), m.substr(colon + 2));
              }
          explicit_solver->set_rigid_parts(rigid_nodes);
        }
    }



    ExplicitSimulation::~ExplicitSimulation() = default;



    void
    ExplicitSimulation::start_from(const PreloadState &state)
    {
      AssertThrow(state.history.size() == elements->history().size() &&
                    state.shortenings.size() == elements->n_sections() &&
                    state.contact_states.size() ==
                      contacts.size() + contact_pairs.size(),
                  ExcMessage("The preload does not fit the elements"));
      elements->history() = state.history;
      elements->set_section_shortenings(state.shortenings);
      // The contacts' tangential forces and reference points: the first
      // explicit step continues the load path's friction state.
      for (unsigned int c = 0; c < contacts.size(); ++c)
        {
          AssertThrow(state.contact_states[c].size() ==
                        contacts[c]->state().size(),
                      ExcMessage("The preload does not fit the contacts"));
          contacts[c]->state() = state.contact_states[c];
        }
      // The mortar pairs' friction states, accepted at the explicit run's
      // start (t = 0).
      for (unsigned int p = 0; p < contact_pairs.size(); ++p)
        contact_pairs[p]->set_friction_state(
          state.contact_states[contacts.size() + p], 0.);
      // The rigid parts the load path moved, at rest. The load path turns
      // them about the same centre of mass c as this run's C (up to
      // round-off): x = c + d + R (X - c) = C + d' + R (X - C) for
      // d' = d + (1 - R) (c - C).
      for (const RigidPartPose &pose : state.rigid_part_poses)
        {
          AssertThrow(pose.part < body_of_part.size() &&
                        body_of_part[pose.part] != numbers::invalid_unsigned_int,
                      ExcMessage("The preload's rigid parts do not fit"));
          RigidBody         &body   = bodies[body_of_part[pose.part]];
          const Tensor<1, 3> offset = pose.centre - body.reference_position;
          // The load path balanced the part about its centre of mass, and
          // its held translations hold that point: a restart whose
          // densities move the centre would start it out of equilibrium.
          if (offset.norm() > 1e-9 * (1. + pose.centre.norm()))
            {
              std::ostringstream where;
              where << pose.centre << " mm in the preload, " << body.reference_position
                    << " mm now";
              throw InputError(
                "Output/Restart from checkpoint",
                "the centre of mass of the rigid part '" +
                  model.parts[pose.part].name +
                  "', about which the preload found its equilibrium, has "
                  "moved (" + where.str() +
                  "): a density changed; run the preload again");
            }
          body.displacement =
            pose.displacement + offset - pose.rotation * offset;
          body.rotation = pose.rotation;
        }
      explicit_solver->set_initial_displacement(state.displacement);
    }



    PreloadState
    ExplicitSimulation::read_preload(const std::string &directory,
                                     const std::string &parameters) const
    {
      std::vector<std::size_t> contact_state_sizes;
      for (const auto &contact : contacts)
        contact_state_sizes.push_back(contact->state().size());
      for (const auto &pair : contact_pairs)
        contact_state_sizes.push_back(pair->friction_state().size());
      return simulation::read_preload(directory,
                                 parameters,
                                 model.partitioner,
                                 elements->history().size(),
                                 elements->n_sections(),
                                 contact_state_sizes,
                                 model.comm);
    }



    const time_integration::ExplicitSolver &
    ExplicitSimulation::solver() const
    {
      return *explicit_solver;
    }



    void
    ExplicitSimulation::add_standard_postprocessors()
    {
      add_postprocessor(std::make_unique<postprocess::EnergyColumns>(true));
      if (explicit_solver->selective_mass_scaling() != nullptr)
        {
          std::vector<std::string> names;
          for (const Part &part : model.parts)
            names.push_back(part.name);
          add_postprocessor(std::make_unique<postprocess::MassScalingColumns>(
            *explicit_solver->selective_mass_scaling(),
            names,
            mass_scaling_parts));
        }
      std::vector<std::string> names;
      for (const BoundaryCondition &bc : model.boundary_conditions)
        names.push_back(bc.name);
      add_postprocessor(std::make_unique<postprocess::ReactionAndLoadColumns>(
        std::make_unique<postprocess::BoundaryReactionColumns>(
          names, condition_of_group, direction_of_group),
        surface_loads.get(),
        condition_of_load));
      names.clear();
      for (const Part &part : model.parts)
        names.push_back(part.name);
      add_postprocessor(std::make_unique<postprocess::PartColumns>(names));
      // The bodies in their order: rigid surfaces with their own body, then
      // the rigid parts (with their rotation).
      add_postprocessor(std::make_unique<postprocess::RigidBodyColumns>(bodies));
      std::vector<const contact::RigidSurfaceForces *> surfaces;
      for (const auto &surface : contact_forces)
        surfaces.push_back(surface.get());
      add_postprocessor(std::make_unique<postprocess::InteractionEnergyColumns>(
        model, condition_of_group, surface_loads.get(), condition_of_load,
        surfaces));
      if (auto columns = setup::contact_pair_columns(model, contact_pairs))
        add_postprocessor(std::move(columns));
      if (!model.pretension_sections.empty())
        {
          names.clear();
          for (const PretensionSection &section : model.pretension_sections)
            names.push_back(section.name);
          add_postprocessor(
            std::make_unique<postprocess::PretensionSectionColumns>(names));
        }
      if (!model.cross_sections.empty())
        {
          names.clear();
          for (const CrossSection &section : model.cross_sections)
            names.push_back(section.name);
          add_postprocessor(
            std::make_unique<postprocess::CrossSectionColumns>(names));
        }
      if (!output.history_nodes.empty())
        add_postprocessor(std::make_unique<postprocess::HistoryNodeColumns>(
          std::make_unique<postprocess::HistoryNodes>(model,
                                                      output.history_nodes)));
    }



    void
    ExplicitSimulation::add_postprocessor(
      std::unique_ptr<postprocess::Postprocessor> plugin)
    {
      postprocessors.push_back(std::move(plugin));
    }



    void
    ExplicitSimulation::log_model(std::ostream &log) const
    {
      if (Utilities::MPI::this_mpi_process(model.comm) != 0)
        return;
      log << title << ": " << model.triangulation.n_global_active_cells()
          << " cells, " << model.dof_handler.n_dofs() << " dofs, "
          << Utilities::MPI::n_mpi_processes(model.comm) << " ranks\n";
      for (const Part &part : model.parts)
        {
          log << "  " << part.name << ": ";
          part.law->print_constants(log);
        }
      log << "  Lumped mass " << explicit_solver->physical_mass()
          << " kg, added mass " << explicit_solver->added_mass() << " kg (";
      for (unsigned int p = 0; p < model.parts.size(); ++p)
        log << (p > 0 ? ", " : "") << model.parts[p].name << " "
            << (p < added_mass_by_part.size() ? added_mass_by_part[p] : 0.)
            << " kg";
      log << ")" << std::endl;
      setup::log_selective_mass_scaling(model, mass_scaling_parts, log);
      setup::log_initial_penetrations(model, log);
    }
  } // namespace simulation
} // namespace rubberdyn
