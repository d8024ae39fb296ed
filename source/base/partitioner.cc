#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>

#include <rubberdyn/base/partitioner.h>

namespace rubberdyn
{
  std::shared_ptr<dealii::Utilities::MPI::Partitioner>
  ghosted_partitioner(const dealii::DoFHandler<3, 3> &dof_handler)
  {
    dealii::IndexSet relevant;
    dealii::DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
    return std::make_shared<dealii::Utilities::MPI::Partitioner>(
      dof_handler.locally_owned_dofs(),
      relevant,
      dof_handler.get_triangulation().get_communicator());
  }
} // namespace rubberdyn
