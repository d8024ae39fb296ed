#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <rubberdyn/base/exceptions.h>
#include <rubberdyn/model/model.h>

#include <string>

#include "model_study_parsing.h"

// The Model study's planes across a deformable part: `Pretension sections`
// (the bolt preload of the quasi-static load path) and `Cross sections`
// (force resultants for output), declared and parsed here.

namespace rubberdyn
{
  namespace studies
  {
    namespace model_study_parsing
    {
      namespace
      {
        /** A plane across a deformable part, as a section gives it. */
        struct PartPlane
        {
          unsigned int part = 0;
          Point<3>     point;
          Tensor<1, 3> normal;
        };

        /**
         * Declare `Part`, `Point` and `Normal` of a section (pretension or
         * cross section) in the current subsection, what parse_part_plane()
         * reads; @p part_doc and @p normal_doc say what they mean for it.
         */
        void
        declare_part_plane(ParameterHandler  &prm,
                           const std::string &part_doc,
                           const std::string &normal_doc)
        {
          // A part's name, checked against Parts/Names when parsed.
          prm.declare_entry("Part", "", Patterns::Anything(), part_doc);
          prm.declare_entry("Point",
                            "0, 0, 0",
                            vector_pattern(),
                            "A point of the plane (mm). Put the plane inside "
                            "a layer of elements, not on their faces.");
          prm.declare_entry("Normal", "0, 0, 1", vector_pattern(), normal_doc);
        }



        /**
         * `Part`, `Point` and `Normal` of the section at @p path (the current
         * subsection of @p prm), for pretension and cross sections alike.
         *
         * @throws InputError naming the entry: an unknown, rigid or mixed u-p
         *   part (@p kind names the section in the message), a zero normal.
         */
        PartPlane
        parse_part_plane(ParameterHandler   &prm,
                         const std::string  &path,
                         const std::string  &kind,
                         const model::Model &m)
        {
          PartPlane         plane;
          const std::string part  = Utilities::trim(prm.get("Part"));
          bool              found = false;
          for (unsigned int p = 0; p < m.parts.size(); ++p)
            if (m.parts[p].name == part)
              {
                found      = true;
                plane.part = p;
              }
          if (!found)
            throw InputError(path + "/Part",
                             "names no part ('" + part.substr(0, 40) +
                               "' is not in Parts/Names)");
          const model::Part &cut_part = m.parts[plane.part];
          if (cut_part.rigid)
            throw InputError(path + "/Part",
                             "the part '" + part + "' is rigid: a " + kind +
                               " cuts a deformable part");
          if (cut_part.formulation == model::Formulation::mixed_up)
            throw InputError(path + "/Part",
                             "the part '" + part +
                               "' uses the mixed u-p element, which takes no " +
                               kind + " yet; use 'F-bar'");
          plane.point               = Point<3>(parse_vector(prm.get("Point")));
          const Tensor<1, 3> normal = parse_vector(prm.get("Normal"));
          if (!(normal.norm() > 0.))
            throw InputError(path + "/Normal", "must not be zero");
          plane.normal = normal / normal.norm();
          return plane;
        }



        /** `Pretension sections`: the names, then one subsection each. */
        void
        declare_pretension_sections(ParameterHandler            &prm,
                                    const registry::ListedNames &names)
        {
          prm.enter_subsection("Pretension sections");
          // Names: checked by listed_names() and the registry's name rules.
          prm.declare_entry(
            "Names",
            "",
            Patterns::Anything(),
            "Names of the bolt pretension sections, separated by commas; each "
            "has a subsection of its name. A section is a plane across a part "
            "(a bolt's shank): the elements of the part it cuts are made "
            "shorter across it by the section's shortening, which the "
            "quasi-static solver drives to the Target force (or the "
            "prescribed Shortening) and then holds (locks) from the Lock time "
            "on, as CalculiX's *PRE-TENSION SECTION. Quasi-static schemes "
            "only. The time history gets <name>_force (kN, the axial force "
            "through the section, tension positive) and <name>_shortening "
            "(mm).");
          for (const std::string &name :
               names_with_template(names, "Pretension sections"))
            {
              prm.enter_subsection(name);
              declare_part_plane(prm,
                                 "The deformable part the plane cuts (F-bar or "
                                 "displacement element); the cut elements must "
                                 "form one layer across the shank, clear of "
                                 "other parts.",
                                 "Normal of the plane, the bolt's axis (either "
                                 "sense; need not be a unit vector).");
              prm.declare_entry("Control",
                                "force",
                                Patterns::Selection("force|shortening"),
                                "'force': the force through the section "
                                "rises linearly from 0 at t = 0 to the Target "
                                "force at the Lock time; 'shortening': the "
                                "shortening rises linearly to Shortening at "
                                "the Lock time. Both are held from then on "
                                "(the shortening stays fixed: the force then "
                                "follows the other loads).");
              prm.declare_entry("Target force",
                                "0",
                                Patterns::Double(),
                                "Axial force at the Lock time (kN, > 0: "
                                "tension), Control = force.");
              prm.declare_entry("Shortening",
                                "0",
                                Patterns::Double(),
                                "Shortening at the Lock time (mm, > 0), "
                                "Control = shortening.");
              prm.declare_entry("Lock time",
                                "1",
                                Patterns::Double(),
                                "Pseudo-time of the quasi-static load path at "
                                "which the target is reached and the section "
                                "locked (-; in (0, Time integration/"
                                "Quasi-static end time]).");
              prm.leave_subsection();
            }
          prm.leave_subsection();
        }



        /**
         * Read `Pretension sections` into @p m (after its parts).
         *
         * @throws InputError naming the entry: an unknown, rigid or mixed u-p
         *   part, a zero normal, a target force or shortening <= 0, a lock
         *   time outside (0, Quasi-static end time], or a section in an
         *   explicit run.
         */
        void
        parse_pretension_sections(ParameterHandler                  &prm,
                                  const parameters::TimeIntegration &time,
                                  model::Model                      &m)
        {
          prm.enter_subsection("Pretension sections");
          for (const std::string &name : listed_names(prm))
            {
              const std::string path = "Pretension sections/" + name;
              if (time.scheme == "explicit")
                throw InputError("Time integration/Scheme",
                                 "the pretension section '" + name +
                                   "' needs 'quasi-static' or 'quasi-static "
                                   "then explicit': its force is reached on "
                                   "the quasi-static load path");
              prm.enter_subsection(name);
              model::PretensionSection section;
              section.name = name;
              const PartPlane plane =
                parse_part_plane(prm, path, "pretension section", m);
              section.part          = plane.part;
              section.point         = plane.point;
              section.normal        = plane.normal;
              section.force_control = prm.get("Control") == "force";
              section.target_force  = prm.get_double("Target force");
              section.shortening    = prm.get_double("Shortening");
              section.lock_time     = prm.get_double("Lock time");
              if (section.force_control && !(section.target_force > 0.))
                throw InputError(path + "/Target force",
                                 "must be > 0 kN (a tension) with Control = "
                                 "force, not " +
                                   prm.get("Target force"));
              if (!section.force_control && !(section.shortening > 0.))
                throw InputError(path + "/Shortening",
                                 "must be > 0 mm with Control = shortening, "
                                 "not " +
                                   prm.get("Shortening"));
              if (!(section.lock_time > 0.) ||
                  section.lock_time > time.quasi_static_end_time * (1. + 1e-12))
                throw InputError(path + "/Lock time",
                                 "must lie in (0, Time integration/Quasi-"
                                 "static end time = " +
                                   Utilities::to_string(
                                     time.quasi_static_end_time) +
                                   "], not " + prm.get("Lock time"));
              prm.leave_subsection();
              m.pretension_sections.push_back(section);
            }
          prm.leave_subsection();
        }



        /** `Cross sections`: the names, then one subsection each. */
        void
        declare_cross_sections(ParameterHandler            &prm,
                               const registry::ListedNames &names)
        {
          prm.enter_subsection("Cross sections");
          // Names: checked by listed_names() and the registry's name rules.
          prm.declare_entry(
            "Names",
            "",
            Patterns::Anything(),
            "Names of the cross sections for output, separated by commas; "
            "each has a subsection of its name. A cross section is a plane "
            "across a deformable part (LS-DYNA's *DATABASE_CROSS_SECTION); "
            "the explicit run's time history gets, at the plane, the "
            "resultant of the part's stresses on the side the Normal points "
            "from: <name>_force_x/_y/_z (kN), <name>_moment_x/_y/_z (kN mm, "
            "about the current centre of the cut elements), "
            "<name>_centre_x/_y/_z (mm, that centre), "
            "<name>_axial_force (kN, along the Normal: tension positive), "
            "<name>_shear_force (kN, magnitude across the Normal), "
            "<name>_torque (kN mm, about the Normal) and "
            "<name>_bending_moment (kN mm, magnitude across the Normal). "
            "Explicit runs (and the explicit part of 'quasi-static then "
            "explicit').");
          for (const std::string &name :
               names_with_template(names, "Cross sections"))
            {
              prm.enter_subsection(name);
              declare_part_plane(prm,
                                 "The deformable part the plane cuts (F-bar or "
                                 "displacement element): the resultant is that "
                                 "of the part's own elements that the plane "
                                 "cuts, whatever else is attached to them.",
                                 "Normal of the plane (need not be a unit "
                                 "vector): the resultant is that of the "
                                 "traction sigma n on the plane, the force "
                                 "the material on the Normal's side exerts on "
                                 "the other side (tension along the Normal "
                                 "positive).");
              prm.leave_subsection();
            }
          prm.leave_subsection();
        }



        /**
         * Read `Cross sections` into @p m (after its parts).
         *
         * @throws InputError naming the entry: an unknown, rigid or mixed u-p
         *   part, a zero normal, or a section in a quasi-static run.
         */
        void
        parse_cross_sections(ParameterHandler                  &prm,
                             const parameters::TimeIntegration &time,
                             model::Model                      &m)
        {
          prm.enter_subsection("Cross sections");
          for (const std::string &name : listed_names(prm))
            {
              const std::string path = "Cross sections/" + name;
              if (time.scheme == "quasi-static")
                throw InputError("Time integration/Scheme",
                                 "the cross section '" + name +
                                   "' reports in explicit runs only (use "
                                   "'explicit' or 'quasi-static then "
                                   "explicit')");
              prm.enter_subsection(name);
              model::CrossSection section;
              section.name = name;
              const PartPlane plane =
                parse_part_plane(prm, path, "cross section", m);
              section.part   = plane.part;
              section.point  = plane.point;
              section.normal = plane.normal;
              prm.leave_subsection();
              m.cross_sections.push_back(section);
            }
          prm.leave_subsection();
        }
      } // namespace



      void
      declare_part_sections(ParameterHandler            &prm,
                            const registry::ListedNames &names)
      {
        declare_pretension_sections(prm, names);
        declare_cross_sections(prm, names);
      }



      void
      parse_part_sections(ParameterHandler                  &prm,
                          const parameters::TimeIntegration &time,
                          model::Model                      &m)
      {
        parse_pretension_sections(prm, time, m);
        parse_cross_sections(prm, time, m);
      }
    } // namespace model_study_parsing
  }   // namespace studies
} // namespace rubberdyn
