#include <deal.II/base/mpi.h>

#include <rubberdyn/base/exceptions.h>
#include <rubberdyn/elements/solid_hex_elements.h>
#include <rubberdyn/model/model.h>
#include <rubberdyn/simulation/selective_mass_scaling_setup.h>
#include <rubberdyn/time_integration/selective_mass_scaling.h>

#include <algorithm>
#include <cmath>
#include <ostream>

namespace rubberdyn
{
  namespace simulation
  {
    using namespace dealii;

    SelectiveMassScalingSetup::SelectiveMassScalingSetup() = default;
    SelectiveMassScalingSetup::SelectiveMassScalingSetup(
      SelectiveMassScalingSetup &&) noexcept = default;
    SelectiveMassScalingSetup::~SelectiveMassScalingSetup() = default;

    namespace setup
    {
      namespace
      {
        // 1 on the locally relevant dofs of the rigid parts' cells (owned
        // and ghost cells: every cell next to an owned one is one of them).
        std::vector<bool>
        rigid_part_dofs(const model::Model &model)
        {
          const auto &partitioner = *model.partitioner;
          std::vector<bool> rigid(partitioner.locally_owned_size() +
                                    partitioner.n_ghost_indices(),
                                  false);
          std::vector<types::global_dof_index> dofs(
            model.fe.n_dofs_per_cell());
          for (const auto &cell : model.dof_handler.active_cell_iterators())
            if ((cell->is_locally_owned() || cell->is_ghost()) &&
                model.parts[model.part_of_material_id(cell->material_id())]
                  .rigid)
              {
                cell->get_dof_indices(dofs);
                for (const types::global_dof_index dof : dofs)
                  if (partitioner.in_local_range(dof) ||
                      partitioner.is_ghost_entry(dof))
                    rigid[partitioner.global_to_local(dof)] = true;
              }
          return rigid;
        }
      } // namespace



      SelectiveMassScalingSetup
      selective_mass_scaling(
        const model::Model                &model,
        const parameters::TimeIntegration &time_integration,
        const elements::SolidHexElements  &elements)
      {
        SelectiveMassScalingSetup result;
        result.parts.resize(model.parts.size());
        bool any_target = false;
        for (unsigned int p = 0; p < model.parts.size(); ++p)
          {
            const model::Part &part = model.parts[p];
            if (part.rigid)
              continue;
            result.parts[p].target_time_step =
              part.selective_mass_scaling_time_step.value_or(
                time_integration.selective_mass_scaling_time_step);
            if (part.selective_mass_scaling_time_step)
              time_integration.require_step_within_run(
                "Parts/" + part.name + "/Selective mass scaling time step",
                *part.selective_mass_scaling_time_step);
            any_target |= result.parts[p].target_time_step > 0.;
          }
        if (!any_target)
          return result;
        // Both kinds at once would scale the same elements twice, the
        // second time on masses the first has changed.
        if (time_integration.mass_scaling_time_step > 0.)
          throw InputError(
            "Time integration/Mass scaling time step",
            "is set together with selective mass scaling (Time "
            "integration/Selective mass scaling time step or a part's "
            "own); choose one: set either to 0");

        const std::vector<double> steps = elements.reference_time_steps();
        const std::vector<bool>   rigid = rigid_part_dofs(model);
        std::vector<time_integration::ScaledElement> scaled;
        result.time_step_factors.assign(elements.n_elements(), 1.);
        std::vector<double> counts(4 * model.parts.size(), 0.);
        for (unsigned int e = 0; e < elements.n_elements(); ++e)
          {
            const elements::SolidHexElements::NodalMasses nodes =
              elements.nodal_masses(e);
            const unsigned int p = nodes.group;
            double mass = 0.;
            for (const double m : nodes.mass)
              mass += m;
            counts[4 * p] += 1.;
            counts[4 * p + 3] += mass;
            const double target = result.parts[p].target_time_step;
            const double step   = time_integration.time_step_scale * steps[e];
            if (!(target > step))
              continue;
            bool next_to_rigid = false;
            for (const auto &node : nodes.dofs)
              next_to_rigid |= rigid[node[0]];
            if (next_to_rigid)
              {
                counts[4 * p + 2] += 1.;
                continue;
              }
            const double s = (target / step) * (target / step);
            const double largest =
              *std::max_element(nodes.mass.begin(), nodes.mass.end());
            const double smallest =
              *std::min_element(nodes.mass.begin(), nodes.mass.end());
            time_integration::ScaledElement element;
            element.dofs  = nodes.dofs;
            element.beta  = s * largest - smallest;
            element.group = p;
            element.set_geometry(nodes.position);
            element.node_mass = nodes.mass;
            result.time_step_factors[e] =
              std::sqrt((element.beta + smallest) / largest);
            scaled.push_back(element);
            counts[4 * p + 1] += 1.;
          }
        Utilities::MPI::sum(ArrayView<const double>(counts),
                            model.comm,
                            ArrayView<double>(counts));
        time_integration::SelectiveMassScalingSettings settings;
        settings.tolerance = time_integration.selective_mass_scaling_tolerance;
        result.scaling =
          std::make_unique<time_integration::SelectiveMassScaling>(
            std::move(scaled), model.partitioner, settings, model.comm);
        std::vector<double> added =
          result.scaling->added_mass_by_group(model.parts.size());
        Utilities::MPI::sum(ArrayView<const double>(added),
                            model.comm,
                            ArrayView<double>(added));
        for (unsigned int p = 0; p < model.parts.size(); ++p)
          {
            PartMassScaling &part = result.parts[p];
            part.n_elements       = counts[4 * p];
            part.n_scaled         = counts[4 * p + 1];
            part.n_next_to_rigid  = counts[4 * p + 2];
            part.mass             = counts[4 * p + 3];
            part.added_mass       = added[p];
          }
        return result;
      }



      void
      log_selective_mass_scaling(const model::Model                  &model,
                                 const std::vector<PartMassScaling> &parts,
                                 std::ostream                        &log)
      {
        if (Utilities::MPI::this_mpi_process(model.comm) != 0)
          return;
        bool any = false;
        for (const PartMassScaling &part : parts)
          any |= part.target_time_step > 0.;
        if (!any)
          return;
        log << "  Selective mass scaling (mass on the deformation modes; "
               "translation unchanged):\n";
        for (unsigned int p = 0; p < parts.size(); ++p)
          {
            const PartMassScaling &part = parts[p];
            if (part.target_time_step <= 0.)
              continue;
            log << "    " << model.parts[p].name << ": target step "
                << part.target_time_step << " ms, " << part.n_scaled << " of "
                << part.n_elements << " elements scaled, added mass "
                << part.added_mass << " kg per direction ("
                << (part.mass > 0. ? part.added_mass / part.mass : 0.)
                << " times the part's " << part.mass << " kg)";
            if (part.n_next_to_rigid > 0)
              log << "; " << part.n_next_to_rigid
                  << " elements below the target share nodes with a rigid "
                     "part and keep their mass";
            log << "\n";
          }
      }
    } // namespace setup
  }   // namespace simulation
} // namespace rubberdyn
