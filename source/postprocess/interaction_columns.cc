#include <deal.II/base/mpi.h>

#include <rubberdyn/contact/rigid_surface_forces.h>
#include <rubberdyn/model/model.h>
#include <rubberdyn/model/surface_loads.h>
#include <rubberdyn/postprocess/interaction_columns.h>
#include <rubberdyn/time_integration/explicit_solver.h>

namespace rubberdyn
{
  namespace postprocess
  {
    using namespace dealii;
    using model::BoundaryCondition;
    using model::RigidSurfaceDefinition;
    using model::SurfaceLoads;

    ReactionAndLoadColumns::ReactionAndLoadColumns(
      std::unique_ptr<BoundaryReactionColumns> reactions,
      const SurfaceLoads                      *loads,
      const std::vector<unsigned int>         &condition_of_load)
      : reactions(std::move(reactions))
      , loads(loads)
      , condition_of_load(condition_of_load)
    {}



    std::string
    ReactionAndLoadColumns::name() const
    {
      return reactions->name();
    }



    std::vector<std::string>
    ReactionAndLoadColumns::history_columns() const
    {
      return reactions->history_columns();
    }



    void
    ReactionAndLoadColumns::history_values(const SimulationView &view,
                                           std::vector<double>  &values)
    {
      const std::size_t first = values.size();
      reactions->history_values(view, values);
      if (loads == nullptr)
        return;
      // A load condition has no constraint group: its columns are zero and
      // take the resultant.
      const std::vector<SurfaceLoads::Resultant> resultants =
        loads->resultants();
      for (unsigned int l = 0; l < resultants.size(); ++l)
        for (unsigned int d = 0; d < 3; ++d)
          {
            const std::size_t column = first + 6 * condition_of_load[l];
            values[column + d] += resultants[l].force[d];
            values[column + 3 + d] += resultants[l].moment[d];
          }
    }



    InteractionEnergyColumns::InteractionEnergyColumns(
      const model::Model                                     &model,
      const std::vector<unsigned int>                        &condition_of_group,
      const SurfaceLoads                                     *loads,
      const std::vector<unsigned int>                        &condition_of_load,
      const std::vector<const contact::RigidSurfaceForces *> &surfaces)
      : model(model)
      , condition_of_group(condition_of_group)
      , loads(loads)
      , condition_of_load(condition_of_load)
      , surfaces(surfaces)
    {}



    std::string
    InteractionEnergyColumns::name() const
    {
      return "interaction energies";
    }



    std::vector<std::string>
    InteractionEnergyColumns::history_columns() const
    {
      std::vector<std::string> columns;
      for (const BoundaryCondition &bc : model.boundary_conditions)
        columns.push_back(bc.name + "_work");
      for (const RigidSurfaceDefinition &surface : model.rigid_surfaces)
        {
          columns.push_back(surface.name + "_contact_energy");
          columns.push_back(surface.name + "_friction_work");
        }
      return columns;
    }



    void
    InteractionEnergyColumns::history_values(const SimulationView &view,
                                             std::vector<double>  &values)
    {
      std::vector<double>        work(model.boundary_conditions.size(), 0.);
      const std::vector<double> &by_group =
        explicit_solver_of(view, name()).reaction_works();
      for (unsigned int g = 0; g < by_group.size(); ++g)
        work[condition_of_group[g]] += by_group[g];
      if (loads != nullptr)
        {
          const std::vector<double> load_work = loads->works();
          for (unsigned int l = 0; l < load_work.size(); ++l)
            work[condition_of_load[l]] += load_work[l];
        }
      values.insert(values.end(), work.begin(), work.end());
      std::vector<double> energies;
      for (const contact::RigidSurfaceForces *surface : surfaces)
        {
          energies.push_back(surface->contact_energy());
          energies.push_back(surface->friction_work());
        }
      Utilities::MPI::sum(ArrayView<const double>(energies),
                          model.comm,
                          ArrayView<double>(energies));
      values.insert(values.end(), energies.begin(), energies.end());
    }
  } // namespace postprocess
} // namespace rubberdyn
