#ifndef rubberdyn_base_partitioner_h
#define rubberdyn_base_partitioner_h

#include <deal.II/base/partitioner.h>

#include <memory>

namespace dealii
{
  template <int dim, int spacedim>
  class DoFHandler;
}

namespace rubberdyn
{
  /**
   * The partitioner of the vectors of a (serial or distributed) DoFHandler:
   * its locally owned dofs, with the locally relevant ones (those of ghost
   * cells) as ghosts, on the triangulation's communicator. This is the
   * layout the element, contact and output loops read with
   * `local_element()`.
   */
  std::shared_ptr<dealii::Utilities::MPI::Partitioner>
  ghosted_partitioner(const dealii::DoFHandler<3, 3> &dof_handler);
} // namespace rubberdyn

#endif
