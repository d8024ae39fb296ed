#ifndef rubberdyn_base_vector_h
#define rubberdyn_base_vector_h

#include <deal.II/lac/la_parallel_vector.h>

namespace rubberdyn
{
  /**
   * The distributed vector of the explicit solver (deal.II's own: cheap
   * ghost exchange, direct access to owned and ghost entries by local
   * index), shared by the element, contact and time-integration layers.
   */
  using VectorType = dealii::LinearAlgebra::distributed::Vector<double>;
} // namespace rubberdyn

#endif
