#ifndef rubberdyn_source_contact_ad_number_h
#define rubberdyn_source_contact_ad_number_h
// The forward-mode automatic differentiation number of the contact tangent
// (private to source/contact): Sacado's dynamic Fad, with deal.II's traits
// so that it works in Tensor and Point.

#include <deal.II/differentiation/ad/sacado_math.h>
#include <deal.II/differentiation/ad/sacado_number_types.h>
#include <deal.II/differentiation/ad/sacado_product_types.h>

namespace rubberdyn
{
  namespace contact
  {
    /** Values with their derivatives with respect to a patch's dofs. */
    using ADNumber = Sacado::Fad::DFad<double>;

    /** The value of a number (decisions are taken on values). */
    inline double
    value_of(const double x)
    {
      return x;
    }

    /** The value of a number (decisions are taken on values). */
    inline double
    value_of(const ADNumber &x)
    {
      return x.val();
    }
  } // namespace contact
} // namespace rubberdyn

#endif
