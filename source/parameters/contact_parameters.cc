#include <deal.II/base/parameter_handler.h>

#include <rubberdyn/base/parameter_tools.h>
#include <rubberdyn/parameters/contact_parameters.h>

namespace rubberdyn
{
  namespace parameters
  {
    using namespace dealii;

    void
    Contact::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Contact");
      prm.declare_entry("Penalty scale factor", "0.1", Patterns::Double(0.),
                        "Scale s of the penalty stiffness k = s K A^2 / V of "
                        "each contact face (-), as LS-DYNA's SLSFAC, with "
                        "the face's current area A and its element's "
                        "current volume V (K: bulk modulus).");
      prm.leave_subsection();
    }



    void
    Contact::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Contact");
      penalty_scale = prm.get_double("Penalty scale factor");
      prm.leave_subsection();
      parameter_tools::require_positive(penalty_scale,
                                        "Contact/Penalty scale factor");
    }
  } // namespace parameters
} // namespace rubberdyn
