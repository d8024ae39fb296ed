#include <deal.II/base/mpi.h>

#include <rubberdyn/model/gravity_load.h>
#include <rubberdyn/model/model.h>

#include <algorithm>

namespace rubberdyn
{
  namespace model
  {
    GravityLoad::GravityLoad(const Model                   &model,
                             const std::vector<VectorType> &masses,
                             const double                   full_at)
      : weight(model.partitioner)
      , full_at(full_at)
    {
      AssertThrow(full_at > 0., ExcMessage("gravity's ramp needs a time"));
      // The component of each owned dof, from the cells that have it.
      std::vector<types::global_dof_index> dofs(model.fe.n_dofs_per_cell());
      for (const auto &cell : model.dof_handler.active_cell_iterators())
        if (cell->is_locally_owned() || cell->is_ghost())
          {
            cell->get_dof_indices(dofs);
            for (unsigned int i = 0; i < dofs.size(); ++i)
              if (model.partitioner->in_local_range(dofs[i]))
                {
                  const unsigned int local =
                    model.partitioner->global_to_local(dofs[i]);
                  double m = 0.;
                  for (const VectorType &mass : masses)
                    m += mass.local_element(local);
                  weight.local_element(local) =
                    m * model.gravity[model.fe.system_to_component_index(i)
                                        .first];
                }
          }
      // The total weight: the mass of all nodes (each at its three dofs)
      // times g.
      double m = 0.;
      for (const VectorType &mass : masses)
        for (unsigned int i = 0; i < mass.locally_owned_size(); ++i)
          m += mass.local_element(i);
      total = Utilities::MPI::sum(m, model.comm) / 3. * model.gravity;
    }



    void
    GravityLoad::add_forces(const EvaluationPoint &point,
                            VectorType            &f,
                            ContributionResults   &results)
    {
      (void)results;
      const double ramp = std::min(point.time / full_at, 1.);
      for (unsigned int i = 0; i < weight.locally_owned_size(); ++i)
        f.local_element(i) += ramp * weight.local_element(i);
    }
  } // namespace model
} // namespace rubberdyn
