#ifndef rubberdyn_parameters_contact_parameters_h
#define rubberdyn_parameters_contact_parameters_h

namespace dealii
{
  class ParameterHandler;
}

namespace rubberdyn
{
  namespace parameters
  {
    /**
     * The `Contact` subsection: settings shared by every contact
     * interaction of a study.
     */
    struct Contact
    {
      /** Scale s of the penalty stiffness s K A^2 / V (-). */
      double penalty_scale = 0.1;

      /** Declare the entries in subsection `Contact`. */
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      /** Read them back (from the top level of @p prm). */
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };
  } // namespace parameters
} // namespace rubberdyn

#endif
