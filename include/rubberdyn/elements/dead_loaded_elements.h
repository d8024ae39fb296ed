#ifndef rubberdyn_elements_dead_loaded_elements_h
#define rubberdyn_elements_dead_loaded_elements_h

#include <rubberdyn/elements/implicit_elements.h>

namespace rubberdyn
{
  namespace elements
  {
    /**
     * Elements under a dead load: the residual of @p inner minus
     * $\lambda f_{ext}$, with the load factor $\lambda$ (load_factor) set by
     * the caller's load stepping and $f_{ext}$ fixed in size and direction
     * (kN), so that the tangent is the elements' own. The benchmarks and
     * verifications that load a model by a force (Cook's membrane, deal.II's
     * step-44) drive the quasi-static solver through it.
     */
    class DeadLoadedElements : public ImplicitElements
    {
    public:
      /** @p inner and @p f_ext must outlive this object. */
      DeadLoadedElements(ImplicitElements &inner, const VectorType &f_ext);

      unsigned int
      n_dofs_per_element() const override;

      unsigned int
      n_groups() const override;

      /** The elements' residual minus load_factor times the dead load. */
      void
      compute_residual(const VectorType    &u,
                       VectorType          &f,
                       ElementStepResult   &result) override;

      void
      compute_tangents(
        const VectorType                                                &u,
        const std::function<void(const unsigned int *, const double *)> &add)
        const override;

      CellAverages
      cell_averages(const VectorType &u, const unsigned int n) const override;

      bool
      has_history() const override;

      void
      accept_history() override;

      /** The factor on the dead load (-). */
      double load_factor = 0.;

    private:
      ImplicitElements &inner;
      const VectorType &f_ext;
    };
  } // namespace elements
} // namespace rubberdyn

#endif
