#include <rubberdyn/elements/dead_loaded_elements.h>
#include <rubberdyn/elements/solid_hex_elements.h>

namespace rubberdyn
{
  namespace elements
  {
    DeadLoadedElements::DeadLoadedElements(ImplicitElements &inner,
                                           const VectorType &f_ext)
      : inner(inner)
      , f_ext(f_ext)
    {}



    unsigned int
    DeadLoadedElements::n_dofs_per_element() const
    {
      return inner.n_dofs_per_element();
    }



    unsigned int
    DeadLoadedElements::n_groups() const
    {
      return inner.n_groups();
    }



    void
    DeadLoadedElements::compute_residual(const VectorType  &u,
                                         VectorType        &f,
                                         ElementStepResult &result)
    {
      inner.compute_residual(u, f, result);
      for (unsigned int i = 0; i < f_ext.locally_owned_size(); ++i)
        f.local_element(i) -= load_factor * f_ext.local_element(i);
    }



    void
    DeadLoadedElements::compute_tangents(
      const VectorType                                                &u,
      const std::function<void(const unsigned int *, const double *)> &add)
      const
    {
      inner.compute_tangents(u, add);
    }



    CellAverages
    DeadLoadedElements::cell_averages(const VectorType  &u,
                                      const unsigned int n) const
    {
      return inner.cell_averages(u, n);
    }



    bool
    DeadLoadedElements::has_history() const
    {
      return inner.has_history();
    }



    void
    DeadLoadedElements::accept_history()
    {
      inner.accept_history();
    }
  } // namespace elements
} // namespace rubberdyn
