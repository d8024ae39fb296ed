#ifndef rubberdyn_parameters_contact_parameters_h
#define rubberdyn_parameters_contact_parameters_h

#include <string>

namespace dealii
{
  class ParameterHandler;
}

namespace rubberdyn
{
  namespace parameters
  {
    /**
     * What a run does with the slave nodes that penetrate their master
     * surface in the mesh, before it starts (`Contact pairs/<name>/Initial
     * penetration`, `Contact/Initial penetration` for the rigid surfaces;
     * contact::resolve_initial_penetrations()). As LS-DYNA's IGNORE and
     * its initial penetration check: a penalty contact that starts
     * penetrated by g pushes with the force eps A g from the first step,
     * and puts eps A g^2 / 2 of energy into the model that nothing paid
     * for.
     */
    enum class InitialPenetration
    {
      /** Run as meshed, with a line per interaction in the log. */
      report,
      /**
       * Move the penetrating slave nodes back onto the master surface (the
       * mesh's reference coordinates change), with a line in the log.
       */
      move_slave_nodes_out,
      /** Stop before the run with a message. */
      refuse
    };

    /** The pattern's names, "report|move slave nodes out|refuse". */
    std::string
    initial_penetration_names();

    /** The choice named @p name (one of initial_penetration_names()). */
    InitialPenetration
    parse_initial_penetration(const std::string &name);

    /** The name of @p choice, as in the parameter file. */
    std::string
    to_string(const InitialPenetration choice);

    /**
     * The documentation of an `Initial penetration` entry whose slave nodes
     * are described by @p slave_nodes (e.g. "the slave nodes") and whose
     * master surface by @p master_surface.
     */
    std::string
    initial_penetration_documentation(const std::string &slave_nodes,
                                      const std::string &master_surface);

    /**
     * The `Contact` subsection: settings shared by every contact
     * interaction of a study.
     */
    struct Contact
    {
      /** Scale s of the penalty stiffness s K A^2 / V (-). */
      double penalty_scale = 0.1;

      /**
       * What the rigid surfaces do with the boundary nodes that start
       * inside them (`Contact/Initial penetration`).
       */
      InitialPenetration initial_penetration = InitialPenetration::report;

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
