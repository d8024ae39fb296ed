#include <deal.II/base/parameter_handler.h>

#include <rubberdyn/base/exceptions.h>
#include <rubberdyn/base/parameter_tools.h>
#include <rubberdyn/model/model.h>
#include <rubberdyn/parameters/contact_parameters.h>

#include <algorithm>
#include <iterator>
#include <string>
#include <vector>

#include "model_study_parsing.h"

namespace rubberdyn
{
  namespace studies
  {
    namespace model_study_parsing
    {
      void
      declare_contact_pairs(ParameterHandler            &prm,
                            const registry::ListedNames &names)
      {
        prm.enter_subsection("Contact pairs");
        prm.declare_entry(
          "Names",
          "",
          Patterns::Anything(),
          "Names of the contact pairs between surfaces of the mesh, "
          "separated by commas; each has a subsection of its name. A pair "
          "is segment-to-segment mortar contact (Puso & Laursen 2004; "
          "doc/contact.md) of the slave faces against the master faces, "
          "in the explicit and the quasi-static scheme (with its exact "
          "tangent). The time history gets <name>_normal_force, "
          "<name>_tangential_force, <name>_force_x/_y/_z (kN, on the slave "
          "side), <name>_max_pressure, <name>_min_pressure (GPa), "
          "<name>_contact_area (mm^2), <name>_max_penetration (mm), "
          "<name>_active_nodes, <name>_slipping_nodes and "
          "<name>_friction_work (J).");
        for (const std::string &name :
             names_with_template(names, "Contact pairs"))
          {
            prm.enter_subsection(name);
            prm.declare_entry("Slave boundary ids",
                              "",
                              Patterns::Anything(),
                              "Physical surface tags of the slave faces "
                              "(the finer or softer side, whose nodes carry "
                              "the gaps and pressures).");
            prm.declare_entry("Master boundary ids",
                              "",
                              Patterns::Anything(),
                              "Physical surface tags of the master faces. "
                              "The same tags as the slave's make a "
                              "self-contact pair (symmetric: each facet "
                              "touches the facets it faces as slave and as "
                              "master, with half the penalty each).");
            prm.declare_entry("Type",
                              "frictionless",
                              Patterns::Selection("frictionless|Coulomb|tied"),
                              "'frictionless': normal contact; 'Coulomb': "
                              "with Coulomb friction; 'tied': the surfaces "
                              "are bonded where they start within the Tie "
                              "tolerance, keeping their initial offset.");
            prm.declare_entry("Static friction coefficient",
                              "0",
                              Patterns::Double(),
                              "FS of LS-DYNA (-, >= 0): "
                              "mu = FD + (FS - FD) exp(-DC * slip rate).");
            prm.declare_entry("Dynamic friction coefficient",
                              "0",
                              Patterns::Double(),
                              "FD (-, 0 <= FD <= FS).");
            prm.declare_entry("Decay coefficient",
                              "0",
                              Patterns::Double(),
                              "DC (ms/mm, >= 0; 0: mu = FS).");
            prm.declare_entry("Penalty scale",
                              "1",
                              Patterns::Double(),
                              "s (-, > 0): the penalty per area is s times "
                              "the smaller of the two sides' mean bulk "
                              "modulus over element thickness V/A (GPa/mm), "
                              "A the facets' current area. Its own default: "
                              "Contact/Penalty scale factor (0.1) is the "
                              "rigid surfaces' node-to-surface stiffness "
                              "per node, which a mortar pair does not use.");
            prm.declare_entry(
              "Penalty time step",
              "0",
              Patterns::Double(0.),
              "Explicit runs: the smallest stable step the pair's penalty "
              "springs may have (ms; 0: no bound). Where the material-based "
              "penalty (Penalty scale) would give a smaller one, the penalty "
              "is lowered to the value from the nodal masses and this step, "
              "k = 2 m / dt^2 per node (LS-DYNA SOFT = 1), so that the "
              "contact does not set the time step: a softer contact, deeper "
              "penetrations (doc/contact.md, section 4). The factor is in "
              "the log.");
            prm.declare_entry("Two-pass",
                              "false",
                              Patterns::Bool(),
                              "Also treat the master faces as slaves of the "
                              "slave faces (symmetric; each pass with half "
                              "the penalty; a self-contact pair is "
                              "symmetric already).");
            prm.declare_entry("Tie tolerance",
                              "0",
                              Patterns::Double(),
                              "Tied pairs: the largest initial normal gap "
                              "of a slave node that is tied (mm, >= 0).");
            prm.declare_entry(
              "Segment reuse slip",
              "0",
              Patterns::Double(),
              "Explicit runs, frictionless and Coulomb pairs: a slave facet "
              "keeps the mortar segments (the overlap integrals) of its last "
              "integration while no corner of it or of the master facets it "
              "overlaps has moved along the facet's plane, relative to the "
              "facet's mean motion since then, by more than this (mm, >= 0); "
              "the gaps and slips are still those of the current positions "
              "(the integrals are held, as in a tied pair). A search, which "
              "comes with every motion of a quarter of the capture margin, "
              "integrates all anew. 0: every step. A clamped interface that "
              "barely slides costs a fraction; its error is of the order of "
              "this distance over the facets' size, relative.");
            prm.declare_entry(
              "Initial penetration",
              "report",
              Patterns::Selection(parameters::initial_penetration_names()),
              "Frictionless and Coulomb pairs (a tied pair keeps its initial "
              "offset): " +
                parameters::initial_penetration_documentation(
                  "the slave nodes",
                  "the master surface"));
            prm.leave_subsection();
          }
        prm.leave_subsection();
      }



      void
      parse_contact_pairs(ParameterHandler      &prm,
                          const BoundaryIdCheck &require_boundary_ids,
                          model::Model          &m)
      {
        using Definition = model::ContactPairDefinition;
        prm.enter_subsection("Contact pairs");
        for (const std::string &name : listed_names(prm))
          {
            const std::string path = "Contact pairs/" + name;
            prm.enter_subsection(name);
            // The ids of @p entry, which must name faces of the mesh.
            const auto boundary_ids = [&](const std::string &entry) {
              const std::set<types::boundary_id> ids =
                parse_ids<types::boundary_id>(
                  prm.get(entry),
                  path + "/" + entry,
                  numbers::internal_face_boundary_id - 1);
              require_boundary_ids(ids, path + "/" + entry);
              return ids;
            };
            // The value of @p entry, which must not be negative.
            const auto non_negative = [&](const std::string &entry,
                                          const std::string &unit) {
              const double value = prm.get_double(entry);
              if (value < 0.)
                throw InputError(path + "/" + entry,
                                 "must be >= 0" + unit + ", not " +
                                   prm.get(entry));
              return value;
            };
            Definition pair;
            pair.name                = name;
            pair.slave_boundary_ids  = boundary_ids("Slave boundary ids");
            pair.master_boundary_ids = boundary_ids("Master boundary ids");
            const std::string type   = prm.get("Type");
            pair.type                = type == "tied" ? Definition::Type::tied :
                                       type == "Coulomb" ? Definition::Type::coulomb :
                                                           Definition::Type::frictionless;
            pair.static_friction =
              non_negative("Static friction coefficient", "");
            pair.dynamic_friction =
              non_negative("Dynamic friction coefficient", "");
            if (pair.dynamic_friction > pair.static_friction)
              throw InputError(path + "/Dynamic friction coefficient",
                               "FD = " +
                                 prm.get("Dynamic friction coefficient") +
                                 " exceeds the Static friction coefficient "
                                 "FS = " +
                                 prm.get("Static friction coefficient") +
                                 ": friction decays from FS to FD");
            // A Coulomb pair with FS = 0 would run frictionless without a
            // word: the coefficient is what the user forgot.
            if (pair.type == Definition::Type::coulomb &&
                pair.static_friction == 0.)
              throw InputError(path + "/Static friction coefficient",
                               "is 0 (the default) in a pair of Type = "
                               "Coulomb, which would then have no friction: "
                               "set the friction coefficient here (and "
                               "'Dynamic friction coefficient' if it decays), "
                               "or set Type = frictionless");
            if (pair.type != Definition::Type::coulomb &&
                pair.static_friction > 0.)
              throw InputError(path + "/Static friction coefficient",
                               "is " + prm.get("Static friction coefficient") +
                                 " in a pair of Type = " + type +
                                 ", which has no friction: set Type = Coulomb "
                                 "to use it, or remove the entry");
            pair.decay         = non_negative("Decay coefficient", "");
            pair.penalty_scale = prm.get_double("Penalty scale");
            pair.penalty_time_step = prm.get_double("Penalty time step");
            parameter_tools::require_positive(pair.penalty_scale,
                                              path + "/Penalty scale");
            pair.two_pass      = prm.get_bool("Two-pass");
            pair.tie_tolerance = non_negative("Tie tolerance", " mm");
            pair.segment_reuse_slip =
              non_negative("Segment reuse slip", " mm");
            pair.initial_penetration = parameters::parse_initial_penetration(
              prm.get("Initial penetration"));
            if (pair.initial_penetration !=
                  parameters::InitialPenetration::report &&
                pair.type == Definition::Type::tied)
              throw InputError(path + "/Initial penetration",
                               "is for frictionless and Coulomb pairs; a "
                               "tied pair keeps its initial offset, "
                               "penetration included (set report)");
            if (pair.segment_reuse_slip > 0. &&
                pair.type == Definition::Type::tied)
              throw InputError(path + "/Segment reuse slip",
                               "is for frictionless and Coulomb pairs; a "
                               "tied pair's segments are those of the "
                               "reference configuration already (set 0)");
            std::vector<types::boundary_id> shared;
            std::set_intersection(pair.slave_boundary_ids.begin(),
                                  pair.slave_boundary_ids.end(),
                                  pair.master_boundary_ids.begin(),
                                  pair.master_boundary_ids.end(),
                                  std::back_inserter(shared));
            if (!shared.empty() &&
                pair.slave_boundary_ids != pair.master_boundary_ids)
              throw InputError(path + "/Master boundary ids",
                               "shares the id " + std::to_string(shared[0]) +
                                 " with the Slave boundary ids, but not all "
                                 "its ids: a self-contact pair lists the same "
                                 "ids on both sides, another pair none of "
                                 "them");
            for (const Definition &other : m.contact_pairs)
              for (const types::boundary_id id : pair.slave_boundary_ids)
                if (other.slave_boundary_ids.count(id) &&
                    other.type != pair.type)
                  throw InputError(path + "/Slave boundary ids",
                                   "the surface " + std::to_string(id) +
                                     " is also the slave of the pair '" +
                                     other.name + "' with another Type");
            prm.leave_subsection();
            m.contact_pairs.push_back(pair);
          }
        prm.leave_subsection();
      }
    } // namespace model_study_parsing
  }   // namespace studies
} // namespace rubberdyn
