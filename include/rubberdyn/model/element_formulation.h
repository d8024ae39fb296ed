#ifndef rubberdyn_model_element_formulation_h
#define rubberdyn_model_element_formulation_h

namespace rubberdyn
{
  namespace model
  {
    /** Formulation of the solid element. */
    enum class Formulation
    {
      /** Plain displacement element, 2x2x2 Gauss points (locks). */
      displacement,
      /** F-bar: volumetric part of F taken at the element centre. */
      fbar,
      /**
       * Mixed u-p: triquadratic displacement with a condensed P1 pressure
       * and dilatation per cell (MixedUPElements; quasi-static only, on an
       * FE_Q(2) dof handler). SolidHexElements refuses it.
       */
      mixed_up
    };

  } // namespace model
} // namespace rubberdyn

#endif
