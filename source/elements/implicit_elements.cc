#include <deal.II/base/exceptions.h>

#include <rubberdyn/elements/implicit_elements.h>

namespace rubberdyn
{
  namespace elements
  {
    // Elements without pretension sections (the mixed u-p element): the
    // model refuses a section in such a part before they are built.
    void
    ImplicitElements::set_section_shortenings(
      const std::vector<double> &shortenings)
    {
      AssertThrow(shortenings.empty(),
                  dealii::ExcMessage(
                    "These elements do not take pretension sections"));
    }



    void
    ImplicitElements::compute_section_couplings(
      const VectorType &,
      const std::function<void(const unsigned int *,
                               const unsigned int,
                               const double *,
                               const double *,
                               const double)> &) const
    {}
  } // namespace elements
} // namespace rubberdyn
