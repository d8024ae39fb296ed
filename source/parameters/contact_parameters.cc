#include <deal.II/base/parameter_handler.h>

#include <rubberdyn/base/parameter_tools.h>
#include <rubberdyn/parameters/contact_parameters.h>

#include <stdexcept>

namespace rubberdyn
{
  namespace parameters
  {
    using namespace dealii;

    std::string
    initial_penetration_names()
    {
      return "report|move slave nodes out|refuse";
    }



    InitialPenetration
    parse_initial_penetration(const std::string &name)
    {
      if (name == "report")
        return InitialPenetration::report;
      if (name == "move slave nodes out")
        return InitialPenetration::move_slave_nodes_out;
      if (name == "refuse")
        return InitialPenetration::refuse;
      throw std::invalid_argument("unknown choice '" + name + "' (valid: " +
                                  initial_penetration_names() + ")");
    }



    std::string
    to_string(const InitialPenetration choice)
    {
      switch (choice)
        {
          case InitialPenetration::report:
            return "report";
          case InitialPenetration::move_slave_nodes_out:
            return "move slave nodes out";
          case InitialPenetration::refuse:
            return "refuse";
        }
      return "";
    }



    std::string
    initial_penetration_documentation(const std::string &slave_nodes,
                                      const std::string &master_surface)
    {
      return "what the run does with " + slave_nodes + " that start inside " +
             master_surface +
             " (penetration: minus the gap at t = 0, in mm, more than "
             "1e-9 of the model's size; doc/contact.md, 'Initial "
             "penetrations'). 'report': run as meshed, with a line in the "
             "log and (explicit runs) in run_summary.json (how many nodes, "
             "the largest "
             "penetration in mm and where); the penalty then pushes them "
             "out with the force eps A g at the first step and adds "
             "eps A g^2 / 2 of energy (J). 'move slave nodes out': move them "
             "back onto " +
             master_surface +
             ", along the gap's normal, "
             "before the run (the mesh's reference coordinates change, "
             "stress free; logged with the largest move in mm). 'refuse': "
             "stop with a message. The default 'report' keeps a deliberate "
             "overlap (an interference fit; block_on_slope.prm starts its "
             "block 1e-3 mm into the slope) and earlier results as they "
             "were.";
    }



    void
    Contact::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Contact");
      prm.declare_entry("Penalty scale factor", "0.1", Patterns::Double(0.),
                        "Scale s (-, > 0) of the node-to-surface penalty "
                        "stiffness k = s K A^2 / V of each solid face "
                        "touching a rigid surface, as LS-DYNA's SLSFAC, with "
                        "the face's current area A and its element's "
                        "current volume V (K: bulk modulus): the default of "
                        "every Rigid surfaces/<name>/Penalty scale factor "
                        "(and of the drop test's plates). Not used by the "
                        "mortar Contact pairs: their Contact pairs/<name>/"
                        "Penalty scale (default 1) scales another stiffness, "
                        "a pressure per gap integrated over the facets "
                        "(doc/contact.md), so the two numbers differ on "
                        "purpose.");
      prm.declare_entry(
        "Initial penetration",
        "report",
        Patterns::Selection(initial_penetration_names()),
        "Rigid surfaces: " +
          initial_penetration_documentation(
            "the boundary nodes of a rigid surface's Boundary ids",
            "the surface") +
          " (Contact pairs have an entry of their own.)");
      prm.leave_subsection();
    }



    void
    Contact::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Contact");
      penalty_scale = prm.get_double("Penalty scale factor");
      initial_penetration =
        parse_initial_penetration(prm.get("Initial penetration"));
      prm.leave_subsection();
      parameter_tools::require_positive(penalty_scale,
                                        "Contact/Penalty scale factor");
    }
  } // namespace parameters
} // namespace rubberdyn
