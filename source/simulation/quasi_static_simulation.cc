#include <deal.II/base/mpi.h>

#include <rubberdyn/base/exceptions.h>
#include <rubberdyn/base/parameter_tools.h>
#include <rubberdyn/contact/initial_penetrations.h>
#include <rubberdyn/contact/mortar_contact_pair.h>
#include <rubberdyn/contact/rigid_surface_contact.h>
#include <rubberdyn/contact/rigid_surface_forces.h>
#include <rubberdyn/elements/mixed_up_elements.h>
#include <rubberdyn/elements/solid_hex_elements.h>
#include <rubberdyn/model/gravity_load.h>
#include <rubberdyn/model/model.h>
#include <rubberdyn/simulation/quasi_static_simulation.h>
#include <rubberdyn/simulation/quasi_static_view.h>
#include <rubberdyn/simulation/simulation_setup.h>
#include <rubberdyn/model/surface_loads.h>
#include <rubberdyn/postprocess/field_output.h>
#include <rubberdyn/postprocess/field_output_writer.h>
#include <rubberdyn/postprocess/contact_pair_columns.h>
#include <rubberdyn/postprocess/history_columns.h>
#include <rubberdyn/postprocess/history_nodes.h>
#include <rubberdyn/postprocess/interaction_columns.h>
#include <rubberdyn/postprocess/load_path_body_columns.h>
#include <rubberdyn/postprocess/run_summary.h>
#include <rubberdyn/postprocess/time_history_plot.h>
#include <rubberdyn/postprocess/time_history.h>
#include <rubberdyn/time_integration/kinematic_constraints.h>
#include <rubberdyn/time_integration/quasi_static_solver.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <limits>
#include <ostream>
#include <sstream>

namespace rubberdyn
{
  namespace simulation
  {
    using namespace model;

    namespace
    {
      /**
       * The Newton and linear iterations of the converged load steps, the
       * cut-backs and the iterations the failed attempts took, summed over
       * the steps of @p s.
       */
      std::array<unsigned int, 4>
      iteration_totals(const time_integration::QuasiStaticSolver &s)
      {
        std::array<unsigned int, 4> totals = {{0, 0, 0, 0}};
        for (const auto &step : s.steps())
          {
            totals[0] += step.iterations;
            totals[1] += step.linear_iterations;
            totals[2] += step.cutbacks;
            totals[3] += step.cutback_iterations;
          }
        return totals;
      }
    } // namespace

    namespace
    {
      /** K + 4 G / 3 of @p part's law (GPa): its stiffest response. */
      double
      dilatational_modulus(const Part &part)
      {
        return part.law->bulk_modulus() + 4. / 3. * part.law->shear_modulus();
      }
    } // namespace



    void
    QuasiStaticSimulation::check_supported(
      const Model                       &model,
      const parameters::TimeIntegration &time_integration,
      const parameters::Output          &output)
    {
      const std::string scheme = "Time integration/Scheme";
      const auto        refuse = [&](const std::string &what,
                              const std::string &entry) {
        throw InputError(scheme,
                         "'" + time_integration.scheme + "' cannot run " +
                           what + " (" + entry +
                           ") yet; use 'explicit', or remove it");
      };
      for (const Part &part : model.parts)
        {
          if (part.formulation == elements::Formulation::mixed_up &&
              part.law->n_state_variables() > 0)
            throw InputError("Parts/" + part.name + "/Element formulation",
                             "'mixed u-p' takes hyperelastic laws only; the "
                             "law of part '" +
                               part.name + "' (" + part.law->name() +
                               ") keeps a history; use 'F-bar'");
          // (In 'quasi-static then explicit' they are the explicit run's.)
          if (time_integration.scheme == "quasi-static" &&
              (part.initial_velocity.norm() != 0. ||
               part.initial_angular_velocity.norm() != 0.))
            refuse("an initial velocity of the part '" + part.name + "'",
                   "Parts/" + part.name + "/Initial velocity");
        }
      for (const BoundaryCondition &bc : model.boundary_conditions)
        {
          // A velocity has no meaning on a load path of pseudo-time.
          if (bc.type == BoundaryCondition::Type::velocity)
            refuse("the velocity condition '" + bc.name + "'",
                   "Boundary conditions/" + bc.name + "/Type");
          // SurfaceLoads integrates bilinear faces of Q1 nodes; the mixed
          // u-p element's Q2 face nodes would get an inconsistent load.
          const bool load = bc.type == BoundaryCondition::Type::traction ||
                            bc.type == BoundaryCondition::Type::pressure;
          for (const Part &part : model.parts)
            if (load && part.formulation == elements::Formulation::mixed_up)
              throw InputError("Boundary conditions/" + bc.name + "/Type",
                               "the mixed u-p element (part '" + part.name +
                                 "') does not take tractions and pressures "
                                 "yet; use 'F-bar' for this model");
        }
      // The contact of a surface on a moving rigid part would need the
      // contact's tangent with respect to the part's motion.
      for (const RigidSurfaceDefinition &surface : model.rigid_surfaces)
        if (!surface.rigid_part.empty())
          {
            const Part &part =
              model.parts[model.part_index(surface.rigid_part)];
            if (part.quasi_static_equilibrium)
              throw InputError(
                "Parts/" + part.name + "/Quasi-static motion",
                "'equilibrium' cannot move the rigid part '" + part.name +
                  "' on the load path: it carries the rigid surface '" +
                  surface.name + "' (Rigid surfaces/" + surface.name +
                  "/Rigid part), whose contact does not take the part's "
                  "motion into its tangent yet; use 'held'");
          }
      if (time_integration.mass_scaling_time_step > 0.)
        refuse("mass scaling", "Time integration/Mass scaling time step");
      // 'quasi-static then explicit': the explicit run scales, the load
      // path has no inertia to scale.
      if (time_integration.scheme == "quasi-static")
        {
          if (time_integration.selective_mass_scaling_time_step > 0.)
            refuse("selective mass scaling",
                   "Time integration/Selective mass scaling time step");
          for (const Part &part : model.parts)
            if (part.selective_mass_scaling_time_step.value_or(0.) > 0.)
              refuse("selective mass scaling",
                     "Parts/" + part.name +
                       "/Selective mass scaling time step");
        }
      if (output.checkpoint_interval > 0.)
        refuse("checkpoints", "Output/Checkpoint interval");
      if (output.restart && time_integration.scheme == "quasi-static")
        refuse("a restart", "Output/Restart from checkpoint");
    }



    QuasiStaticSimulation::QuasiStaticSimulation(
      Model                             &model,
      const parameters::TimeIntegration &time_integration,
      const parameters::Output          &output,
      const std::string                 &title)
      : model(model)
      , time_integration(time_integration)
      , output(output)
      , title(title)
    {
      check_supported(model, time_integration, output);
      // Slave nodes that start inside their master surface: reported,
      // moved out or refused before anything is built from the mesh.
      contact::resolve_initial_penetrations(model);
      // The mixed u-p element on the model's Q2 dofs, or the explicit
      // engine's hexahedra (F-bar, displacement) on its Q1 dofs.
      if (model.uses_mixed_up())
        {
          auto mixed = std::make_unique<elements::MixedUPElements>();
          mixed->initialize(model.dof_handler,
                            model.partitioner,
                            setup::element_groups(model, time_integration));
          elements = std::move(mixed);
        }
      else
        {
          auto hexes = std::make_unique<elements::SolidHexElements>();
          hexes->initialize(model.dof_handler,
                            model.partitioner,
                            setup::element_groups(model, time_integration),
                            setup::element_settings(time_integration));
          cut_pretension_sections(*hexes);
          elements = std::move(hexes);
        }
      constraints = std::make_unique<time_integration::KinematicConstraints>(
        model.dof_handler,
        model.partitioner);
      setup::add_kinematic_constraints(model,
                                       *constraints,
                                       condition_of_group,
                                       direction_of_group);
      // Pressures and tractions: one contribution for all of them, as in
      // the explicit run.
      surface_loads = setup::surface_loads(model, condition_of_load);
      std::vector<ForceContribution *> contributions;
      if (surface_loads)
        contributions.push_back(surface_loads.get());
      // The nodal masses, for gravity and the centres of the rigid parts in
      // equilibrium (once, if either needs them).
      std::vector<VectorType> masses;
      const auto              nodal_masses = [&]() -> const auto & {
        if (masses.empty())
          masses = setup::part_masses(model);
        return masses;
      };
      // Gravity grows over the load path to its full weight at the end,
      // which the explicit run of a hand-off applies from its start.
      if (model.gravity.norm() != 0.)
        {
          gravity_load = std::make_unique<GravityLoad>(
            model, nodal_masses(), time_integration.quasi_static_end_time);
          contributions.push_back(gravity_load.get());
        }
      // Rigid parts: their nodes are constrained (one group per
      // direction, after the conditions' groups). They stand still, or
      // move with the part's pose, whose free directions are then
      // unknowns of the solver.
      std::vector<time_integration::RigidPartInEquilibrium> rigid_parts;
      for (unsigned int p = 0; p < model.parts.size(); ++p)
        if (model.parts[p].rigid)
          {
            const Part &part = model.parts[p];
            for (unsigned int d = 0; d < 3; ++d)
              {
                // (Named after the entry that makes the part rigid: a
                // condition on its nodes is refused naming it.)
                held_part_groups.push_back({p, d, constraints->n_groups()});
                constraints->hold_cells("Parts/" + part.name + "/Model",
                                        part.material_ids,
                                        d);
              }
            if (!part.quasi_static_equilibrium)
              continue;
            time_integration::RigidPartInEquilibrium unknowns;
            bool                                     any = false;
            for (unsigned int d = 0; d < 3; ++d)
              {
                unknowns.free[d]     = part.rigid_free_translation[d];
                unknowns.free[3 + d] = part.rigid_free_rotation[d];
                any = any || unknowns.free[d] || unknowns.free[3 + d];
              }
            // (A part in equilibrium with no free direction is held.)
            if (!any)
              continue;
            require_held_by_solid(p);
            unknowns.name         = part.name;
            unknowns.material_ids = part.material_ids;
            unknowns.centre =
              setup::rigid_part_centre_of_mass(model, p, nodal_masses());
            equilibrium_parts.push_back(p);
            rigid_parts.push_back(unknowns);
          }
      // Rigid surfaces on their own bodies, or on a rigid part's (which
      // stands still).
      std::vector<unsigned int> body_of_part(model.parts.size(),
                                             numbers::invalid_unsigned_int);
      for (const RigidSurfaceDefinition &definition : model.rigid_surfaces)
        if (definition.rigid_part.empty())
          {
            surface_body.push_back(bodies.size());
            bodies.push_back(definition.body);
          }
        else
          {
            const unsigned int p = model.part_index(definition.rigid_part);
            if (body_of_part[p] == numbers::invalid_unsigned_int)
              {
                body_of_part[p] = bodies.size();
                RigidBody body;
                body.name = model.parts[p].name;
                bodies.push_back(body);
              }
            surface_body.push_back(body_of_part[p]);
          }
      setup::add_rigid_surfaces(
        model, surface_body, contacts, contact_forces, contributions);
      setup::add_contact_pairs(model, contact_pairs, contributions);
      history_nodes =
        std::make_unique<postprocess::HistoryNodes>(model,
                                                    output.history_nodes);
      newton = std::make_unique<time_integration::QuasiStaticSolver>(
        model.dof_handler,
        model.partitioner,
        *elements,
        *constraints,
        contributions,
        time_integration.quasi_static,
        model.comm,
        pretension_loads,
        bodies,
        bodies_follow_load_path(),
        rigid_parts);
      set_roundoff_floor();
      add_postprocessors();
    }



    void
    QuasiStaticSimulation::add_postprocessors()
    {
      std::vector<std::string> names;
      for (const Part &part : model.parts)
        names.push_back(part.name);
      postprocessors.push_back(
        std::make_unique<postprocess::InternalEnergyColumns>(names));
      names.clear();
      for (const BoundaryCondition &bc : model.boundary_conditions)
        names.push_back(bc.name);
      postprocessors.push_back(
        std::make_unique<postprocess::ReactionAndLoadColumns>(
          std::make_unique<postprocess::BoundaryReactionColumns>(
            names, condition_of_group, direction_of_group),
          surface_loads.get(),
          condition_of_load));
      if (!model.pretension_sections.empty())
        {
          names.clear();
          for (const PretensionSection &section : model.pretension_sections)
            names.push_back(section.name);
          postprocessors.push_back(
            std::make_unique<postprocess::PretensionSectionColumns>(names));
        }
      // The rigid surfaces where their bodies are, the rigid parts' forces
      // and the poses of those in equilibrium (no velocities or energies:
      // the explicit run's RigidBodyColumns have those).
      std::vector<const contact::RigidSurfaceForces *> surfaces;
      for (const auto &forces : contact_forces)
        surfaces.push_back(forces.get());
      postprocessors.push_back(
        std::make_unique<postprocess::LoadPathBodyColumns>(
          model,
          surface_body,
          surfaces,
          held_part_groups,
          equilibrium_parts,
          newton->rigid_part_poses()));
      // The pairs at the converged state (their last evaluation).
      if (auto columns = setup::contact_pair_columns(model, contact_pairs))
        postprocessors.push_back(std::move(columns));
      if (!output.history_nodes.empty())
        postprocessors.push_back(
          std::make_unique<postprocess::HistoryNodeColumns>(
            std::move(history_nodes)));
    }



    void
    QuasiStaticSimulation::set_roundoff_floor()
    {
      // Each part's volume and number of cells, over the ranks.
      std::vector<double> volume(model.parts.size(), 0.),
        n_cells(model.parts.size(), 0.);
      for (const auto &cell : model.triangulation.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const unsigned int p =
              model.part_of_material_id(cell->material_id());
            volume[p] += cell->measure();
            n_cells[p] += 1.;
          }
      Utilities::MPI::sum(ArrayView<const double>(volume),
                          model.comm,
                          ArrayView<double>(volume));
      Utilities::MPI::sum(ArrayView<const double>(n_cells),
                          model.comm,
                          ArrayView<double>(n_cells));
      double element_force = 0.;
      for (unsigned int p = 0; p < model.parts.size(); ++p)
        if (!model.parts[p].rigid && n_cells[p] > 0.)
          {
            const double h = std::cbrt(volume[p] / n_cells[p]);
            const double f = dilatational_modulus(model.parts[p]) * h * h;
            if (f > element_force)
              {
                element_force = f;
                roundoff_part = p;
                roundoff_size = h;
              }
          }
      newton->set_roundoff_floor(
        std::numeric_limits<double>::epsilon() * element_force *
        std::sqrt(static_cast<double>(model.dof_handler.n_dofs())));
    }



    void
    QuasiStaticSimulation::require_held_by_solid(const unsigned int p) const
    {
      // Mark the dofs of the deformable cells, then look for one among the
      // part's (what holds a part in equilibrium: the elements at its
      // nodes; a surface it carries is refused, a load on it holds
      // nothing).
      VectorType touched(model.partitioner);
      std::vector<types::global_dof_index> dofs(model.fe.n_dofs_per_cell());
      for (const auto &cell : model.dof_handler.active_cell_iterators())
        if (cell->is_locally_owned() &&
            !model.parts[model.part_of_material_id(cell->material_id())].rigid)
          {
            cell->get_dof_indices(dofs);
            for (const types::global_dof_index dof : dofs)
              touched.local_element(model.partitioner->global_to_local(dof)) =
                1.;
          }
      // (Summed at the owners, then seen at every rank's ghosts: a node of
      // an owned cell of the part may be owned by another rank.)
      touched.compress(VectorOperation::add);
      touched.update_ghost_values();
      bool held = false;
      for (const auto &cell : model.dof_handler.active_cell_iterators())
        if (cell->is_locally_owned() &&
            model.part_of_material_id(cell->material_id()) == p && !held)
          {
            cell->get_dof_indices(dofs);
            for (const types::global_dof_index dof : dofs)
              held = held || touched.local_element(
                               model.partitioner->global_to_local(dof)) > 0.;
          }
      if (!Utilities::MPI::logical_or(held, model.comm))
        throw InputError(
          "Parts/" + model.parts[p].name + "/Quasi-static motion",
          "'equilibrium' needs something that holds the rigid part '" +
            model.parts[p].name +
            "' in its free directions, but it shares no node with a "
            "deformable part: statics cannot place a body that nothing "
            "holds; use 'held' (it stands still on the load path), or hold "
            "its free directions (Rigid motion)");
    }



    bool
    QuasiStaticSimulation::bodies_follow_load_path() const
    {
      return time_integration.scheme == "quasi-static";
    }



    void
    QuasiStaticSimulation::cut_pretension_sections(
      elements::SolidHexElements &hexes)
    {
      const std::vector<PretensionSection> &sections =
        model.pretension_sections;
      if (sections.empty())
        return;
      cut_elements = setup::cut_pretension_sections(model, hexes);
      for (const PretensionSection &section : sections)
        {
          time_integration::PretensionLoad load;
          load.force_control = section.force_control;
          load.target_force  = section.target_force;
          load.shortening    = section.shortening;
          load.lock_time     = section.lock_time;
          pretension_loads.push_back(load);
        }
    }



    QuasiStaticSimulation::~QuasiStaticSimulation() = default;



    PreloadState
    QuasiStaticSimulation::preload_state() const
    {
      const auto *hexes =
        dynamic_cast<const elements::SolidHexElements *>(elements.get());
      AssertThrow(hexes != nullptr,
                  ExcMessage("A preload needs the F-bar or displacement "
                             "elements"));
      PreloadState state;
      state.displacement = newton->displacement();
      state.history        = hexes->history();
      state.shortenings    = newton->section_shortenings();
      state.section_forces = newton->section_forces();
      state.time           = newton->time();
      for (const auto &contact : contacts)
        state.contact_states.push_back(contact->state());
      // Then the mortar pairs' friction states (empty: frictionless, tied).
      for (const auto &pair : contact_pairs)
        state.contact_states.push_back(pair->friction_state());
      for (unsigned int k = 0; k < equilibrium_parts.size(); ++k)
        {
          const RigidBody &pose = newton->rigid_part_poses()[k];
          state.rigid_part_poses.push_back({equilibrium_parts[k],
                                            pose.reference_position,
                                            pose.displacement,
                                            pose.rotation});
        }
      return state;
    }



    void
    QuasiStaticSimulation::log_model(std::ostream &log) const
    {
      if (Utilities::MPI::this_mpi_process(model.comm) != 0)
        return;
      log << title
          << " (quasi-static): " << model.triangulation.n_global_active_cells()
          << " cells, " << model.dof_handler.n_dofs() << " dofs, "
          << Utilities::MPI::n_mpi_processes(model.comm) << " ranks\n";
      for (const Part &part : model.parts)
        {
          log << "  " << part.name << ": ";
          part.law->print_constants(log);
        }
      const parameters::QuasiStatic &q = time_integration.quasi_static;
      log << "  Load path t = 0 to " << time_integration.quasi_static_end_time
          << ", steps " << q.initial_step << " (first), " << q.minimum_step
          << " to " << q.maximum_step << "; linear solver "
          << newton->linear_solver_name() << std::endl;
      log << "  Converged: residual <= " << q.residual_tolerance
          << " x max(reactions, loads) or <= "
          << std::max(newton->roundoff_floor(), q.residual_floor) << " kN";
      if (roundoff_part != numbers::invalid_unsigned_int)
        log << " (round-off: eps (K + 4G/3) h^2 sqrt(dofs) of "
            << model.parts[roundoff_part].name << ", K + 4G/3 "
            << dilatational_modulus(model.parts[roundoff_part]) << " GPa, h "
            << roundoff_size << " mm)";
      log << ", and energy <= " << q.energy_tolerance << " x the step's first"
          << std::endl;
      for (unsigned int p = 0; p < model.parts.size(); ++p)
        if (model.parts[p].rigid)
          {
            const auto equilibrium = std::find(equilibrium_parts.begin(),
                                               equilibrium_parts.end(),
                                               p);
            log << "  Rigid part " << model.parts[p].name << ": ";
            if (equilibrium == equilibrium_parts.end())
              log << "stands still on the load path (no inertia; its motion "
                     "is the explicit run's)"
                  << std::endl;
            else
              {
                const RigidBody &pose = newton->rigid_part_poses()
                  [equilibrium - equilibrium_parts.begin()];
                std::string free;
                for (unsigned int d = 0; d < 6; ++d)
                  if (d < 3 ? model.parts[p].rigid_free_translation[d] :
                              model.parts[p].rigid_free_rotation[d - 3])
                    free += std::string(free.empty() ? "" : ", ") +
                            rigid_direction_names[d];
                log << "in equilibrium in " << free
                    << " (unknowns of the load path), about its centre of mass "
                    << pose.reference_position << std::endl;
              }
          }
      for (const RigidSurfaceDefinition &surface : model.rigid_surfaces)
        {
          if (!surface.rigid_part.empty())
            {
              log << "  Rigid surface " << surface.name
                  << ": stands still with the rigid part "
                  << surface.rigid_part << std::endl;
              continue;
            }
          std::string free;
          for (unsigned int d = 0; d < 3; ++d)
            if (surface.body.moves_freely(d))
              free += std::string(free.empty() ? "" : ", ") + "xyz"[d];
          log << "  Rigid surface " << surface.name << ": "
              << (!bodies_follow_load_path() ?
                    "stands still on the load path (its motion is the "
                    "explicit run's)" :
                  free.empty() ?
                    "follows its Velocity function over the pseudo-time" :
                    "follows its Velocity function over the pseudo-time, "
                    "held in its free directions (" +
                      free + ": no inertia)")
              << std::endl;
        }
      if (gravity_load)
        log << "  Gravity " << model.gravity
            << " mm/ms^2: the weight (" << gravity_load->total_weight()
            << " kN in all) grows with t to its full value at t = "
            << time_integration.quasi_static_end_time << std::endl;
      for (unsigned int s = 0; s < model.pretension_sections.size(); ++s)
        {
          const PretensionSection &section = model.pretension_sections[s];
          log << "  Pretension section " << section.name << ": "
              << cut_elements[s] << " elements of " << model.parts[section.part].name
              << " cut, "
              << (section.force_control ?
                    "force " + Utilities::to_string(section.target_force) +
                      " kN" :
                    "shortening " + Utilities::to_string(section.shortening) +
                      " mm")
              << " at t = " << section.lock_time << ", then locked"
              << std::endl;
        }
      setup::log_initial_penetrations(model, log);
    }



    void
    QuasiStaticSimulation::check(std::ostream &log)
    {
      log_model(log);
    }



    namespace
    {
      /**
       * The ParaView fields of the converged states of a load path: the
       * displacement, the elements' cell averages and the contact pairs'
       * pressure, gap and slip (their last evaluation: the converged
       * state); no velocity. Written every Field output interval of
       * pseudo-time and always for the last state, also of a run that
       * fails (write() skips a state it has written).
       */
      class ConvergedStateFields
      {
      public:
        ConvergedStateFields(
          const Model                                                    &model,
          const elements::ImplicitElements                               &elements,
          const std::vector<std::unique_ptr<contact::MortarContactPair>> &pairs,
          const parameters::Output                                       &output)
          : model(model)
          , elements(elements)
          , pairs(pairs)
          , interval(output.field_output_interval)
          , fields(output.directory,
                   "solution",
                   model.comm,
                   output.field_output_format)
        {}

        /** Whether the state at @p time is due (the interval's next). */
        bool
        due(const double time) const
        {
          return interval > 0. && time >= next_field * (1. - 1e-12);
        }

        /** Write the state of @p s unless written already (collective). */
        void
        write(const time_integration::QuasiStaticSolver &s)
        {
          if (s.time() == last_field)
            return;
          VectorType                             no_velocity(model.partitioner);
          VectorType                             pair_fields;
          std::vector<postprocess::NodalScalars> nodal_scalars;
          if (!pairs.empty())
            {
              pair_fields.reinit(model.partitioner);
              for (const auto &pair : pairs)
                pair->add_surface_fields(pair_fields);
              pair_fields.update_ghost_values();
              nodal_scalars.push_back(
                {{{"contact_pressure", "contact_gap", "contact_slip"}},
                 &pair_fields});
            }
          fields.write(model.dof_handler,
                       s.displacement(),
                       no_velocity,
                       postprocess::solid_cell_data(model,
                                                    elements,
                                                    s.displacement()),
                       s.time(),
                       nodal_scalars);
          last_field = s.time();
          if (interval > 0.)
            next_field =
              (std::floor(s.time() / interval + 1e-9) + 1.) * interval;
        }

        /** The index file ParaView opens. */
        std::string
        index_file() const
        {
          return fields.index_file();
        }

      private:
        const Model                                                    &model;
        const elements::ImplicitElements                               &elements;
        const std::vector<std::unique_ptr<contact::MortarContactPair>> &pairs;
        const double                                                    interval;
        postprocess::FieldOutput                                        fields;
        double next_field = 0., last_field = -1.;
      };
    } // namespace



    std::vector<std::string>
    QuasiStaticSimulation::history_columns() const
    {
      std::vector<std::string> columns = {"time", "newton_iterations"};
      for (const auto &plugin : postprocessors)
        for (const std::string &column : plugin->history_columns())
          columns.push_back(column);
      return columns;
    }



    void
    QuasiStaticSimulation::write_history_row(
      const postprocess::SimulationView &view,
      postprocess::TimeHistory          &history,
      std::ostream                      &log)
    {
      const time_integration::QuasiStaticSolver &s = *newton;
      std::vector<double> values = {s.time(),
                                    s.steps().empty() ?
                                      0. :
                                      double(s.steps().back().iterations)};
      for (const auto &plugin : postprocessors)
        plugin->history_values(view, values);
      const std::string row = history.write_row(values);
      if (Utilities::MPI::this_mpi_process(model.comm) == 0 &&
          output.echo_history)
        log << row;
      // Rows at every converged step (interval 0), else at the first step
      // on or after each multiple of the interval (pseudo-time).
      next_row =
        output.history_output_interval > 0. ?
          (std::floor(s.time() / output.history_output_interval + 1e-9) +
           1.) *
            output.history_output_interval :
          0.;
    }



    void
    QuasiStaticSimulation::run(std::ostream &log)
    {
      const bool root = Utilities::MPI::this_mpi_process(model.comm) == 0;
      const auto wall_start   = std::chrono::steady_clock::now();
      const auto wall_seconds = [&wall_start]() {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                             wall_start)
          .count();
      };
      log_model(log);
      std::filesystem::create_directories(output.directory);

      const std::vector<std::string> columns = history_columns();
      postprocess::TimeHistory history(output.directory + "/time_history.csv",
                                       columns,
                                       root);
      time_integration::QuasiStaticSolver &s = *newton;
      const QuasiStaticView                view(model, s, *elements);
      ConvergedStateFields fields(model, *elements, contact_pairs, output);

      s.initialize();
      next_row = 0.;
      write_history_row(view, history, log);
      if (output.field_output_interval > 0.)
        fields.write(s);
      const double end_time = time_integration.quasi_static_end_time;
      try
        {
          s.run(end_time, log, [&]() {
            if (s.time() >= next_row * (1. - 1e-12) ||
                s.time() >= end_time * (1. - 1e-12))
              write_history_row(view, history, log);
            if (fields.due(s.time()))
              fields.write(s);
            for (const auto &plugin : postprocessors)
              plugin->after_step(view);
          });
          fields.write(s);
          for (const auto &plugin : postprocessors)
            plugin->finish(view);
          history.make_durable();
          write_summary_and_plot(columns, wall_seconds(), "");
        }
      catch (const time_integration::QuasiStaticFailure &failure)
        {
          fields.write(s);
          history.make_durable();
          write_summary_and_plot(columns, wall_seconds(), failure.what());
          throw std::runtime_error(
            "Quasi-static run failed: " + std::string(failure.what()) +
            " (its rows are in " + output.directory +
            "/time_history.csv, the last converged state in " +
            fields.index_file() + ")");
        }
      if (root)
        log_totals(log);
    }



    void
    QuasiStaticSimulation::log_totals(std::ostream &log) const
    {
      const auto [iterations, linear, cutbacks, wasted] =
        iteration_totals(*newton);
      // (The converged attempts' iterations first: scripts read the number
      // before "Newton".)
      log << "Finished: " << newton->steps().size()
          << " load steps to t = " << newton->time() << ", " << iterations
          << " Newton iterations, " << linear << " linear iterations, "
          << cutbacks << " cut-backs";
      if (cutbacks > 0)
        log << " (which took " << wasted << " more iterations)";
      log << std::endl;
    }



    void
    QuasiStaticSimulation::write_summary_and_plot(
      const std::vector<std::string> &columns,
      const double                    wall_seconds,
      const std::string              &failure) const
    {
      if (Utilities::MPI::this_mpi_process(model.comm) != 0)
        return;
      const time_integration::QuasiStaticSolver &s = *newton;
      const auto [iterations, linear, cutbacks, wasted] = iteration_totals(s);
      using postprocess::json_number;
      std::vector<postprocess::SummaryEntry> entries = {
        {"scheme", postprocess::json_string(time_integration.scheme)},
        {"cells", std::to_string(model.triangulation.n_global_active_cells())},
        {"dofs", std::to_string(model.dof_handler.n_dofs())},
        {"ranks",
         std::to_string(Utilities::MPI::n_mpi_processes(model.comm))},
        {"linear_solver", postprocess::json_string(newton->linear_solver_name())},
        {"load_steps", std::to_string(s.steps().size())},
        {"end_time", json_number(s.time())},
        {"quasi_static_end_time",
         json_number(time_integration.quasi_static_end_time)},
        {"reached_end", failure.empty() ? "true" : "false"},
        {"newton_iterations", std::to_string(iterations)},
        {"linear_iterations", std::to_string(linear)},
        {"cutbacks", std::to_string(cutbacks)},
        {"cutback_iterations", std::to_string(wasted)},
        {"wall_seconds", json_number(wall_seconds)}};
      if (!failure.empty())
        entries.emplace_back("failure", postprocess::json_string(failure));
      postprocess::write_run_summary(output.directory + "/run_summary.json",
                                     entries);

      // The plot: energies, forces and the Newton iterations per step.
      const postprocess::PlotPanel energy{
        "Internal energy",
        "energy (J)",
        postprocess::columns_ending_with(columns, {"internal_energy"})};
      const postprocess::PlotPanel forces{
        "Reactions and forces",
        "force (kN)",
        postprocess::columns_ending_with(columns, postprocess::force_suffixes)};
      const postprocess::PlotPanel newton_panel{
        "Newton iterations per load step", "iterations", {"newton_iterations"}};
      std::vector<postprocess::PlotPanel> panels;
      for (const postprocess::PlotPanel &panel :
           {energy, forces, newton_panel})
        if (!panel.columns.empty())
          panels.push_back(panel);
      postprocess::write_time_history_plot(output.directory +
                                             "/time_history.csv",
                                           output.directory +
                                             "/time_history.svg",
                                           panels,
                                           "pseudo-time t (-)");
    }
  } // namespace simulation
} // namespace rubberdyn
