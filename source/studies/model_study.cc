#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>
#include <deal.II/grid/grid_tools.h>

#include <rubberdyn/base/exceptions.h>
#include <rubberdyn/base/parameter_tools.h>
#include <rubberdyn/elements/solid_hex_elements.h>
#include <rubberdyn/io/gmsh_mesh.h>
#include <rubberdyn/materials/elastic.h>
#include <rubberdyn/materials/material_registry.h>
#include <rubberdyn/simulation/explicit_simulation.h>
#include <rubberdyn/simulation/preloaded_simulation.h>
#include <rubberdyn/simulation/quasi_static_simulation.h>
#include <rubberdyn/model/model.h>
#include <rubberdyn/model/rigid_body.h>
#include <rubberdyn/studies/model_study.h>

#include "model_study_parsing.h"

#include <algorithm>
#include <iterator>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <functional>
#include <iostream>
#include <sstream>
#include <map>
#include <memory>
#include <ostream>
#include <set>
#include <utility>

namespace rubberdyn
{
  namespace studies
  {
    using namespace dealii;

    using namespace model_study_parsing;

    namespace
    {
      /** Three numbers "a, b, c" of entry @p path. */
      Tensor<1, 3>
      parse_vector(const std::string &text, const std::string &path)
      {
        const std::vector<std::string> items =
          Utilities::split_string_list(text, ',');
        if (items.size() != 3)
          throw InputError(path, "needs three numbers separated by commas, "
                                 "not '" + text.substr(0, 80) + "'");
        Tensor<1, 3> result;
        for (unsigned int d = 0; d < 3; ++d)
          {
            try
              {
                result[d] = Utilities::string_to_double(items[d]);
              }
            catch (...)
              {
                throw InputError(path, "'" + items[d].substr(0, 40) +
                                         "' is not a number");
              }
            if (!std::isfinite(result[d]))
              throw InputError(path, "'" + items[d].substr(0, 40) +
                                       "' is not a finite number");
          }
        return result;
      }

      /** Directions "x, z" as 0, 2. */
      std::vector<unsigned int>
      parse_components(const std::string &text, const std::string &path)
      {
        std::vector<unsigned int> components;
        for (const std::string &item : Utilities::split_string_list(text, ','))
          {
            if (item != "x" && item != "y" && item != "z")
              throw InputError(path, "'" + item.substr(0, 40) +
                                       "' is not a direction (x, y or z)");
            const unsigned int d = item[0] - 'x';
            for (const unsigned int c : components)
              if (c == d)
                throw InputError(path, "lists " + item + " twice");
            components.push_back(d);
          }
        if (components.empty())
          throw InputError(path, "lists no direction");
        return components;
      }

      /** Whether @p expression uses one of the variables x, y, z. */
      bool
      uses_position(const std::string &expression)
      {
        for (std::size_t i = 0; i < expression.size();)
          if (std::isalpha(static_cast<unsigned char>(expression[i])) ||
              expression[i] == '_')
            {
              std::size_t j = i;
              while (j < expression.size() &&
                     (std::isalnum(static_cast<unsigned char>(expression[j])) ||
                      expression[j] == '_'))
                ++j;
              const std::string word = expression.substr(i, j - i);
              if (word == "x" || word == "y" || word == "z")
                return true;
              i = j;
            }
          else
            ++i;
        return false;
      }

      /**
       * A deal.II FunctionParser of x, y, z, t with @p n_components
       * components separated by ';', from the entry @p path/@p entry.
       */
      std::shared_ptr<FunctionParser<3>>
      make_function(const std::string &expression,
                    const std::string &constants_text,
                    const unsigned int n_components,
                    const std::string &path,
                    const std::string &which = "one per listed component",
                    const std::string &entry = "Function expression")
      {
        const std::vector<std::string> parts =
          Utilities::split_string_list(expression, ';');
        if (parts.size() != n_components)
          throw InputError(path + "/" + entry,
                           "has " + std::to_string(parts.size()) +
                             " components (separated by ';'), but " +
                             std::to_string(n_components) +
                             (n_components == 1 ? " is" : " are") +
                             " needed, " + which);
        std::map<std::string, double> constants;
        for (const std::string &item :
             Utilities::split_string_list(constants_text, ','))
          {
            const auto equals = item.find('=');
            if (equals == std::string::npos)
              throw InputError(path + "/Function constants",
                               "'" + item.substr(0, 40) +
                                 "' is not of the form name = value");
            try
              {
                constants[Utilities::trim(item.substr(0, equals))] =
                  Utilities::string_to_double(
                    Utilities::trim(item.substr(equals + 1)));
              }
            catch (...)
              {
                throw InputError(path + "/Function constants",
                                 "'" + item.substr(0, 40) +
                                   "' has no numeric value");
              }
          }
        // pi is always known (as in deal.II's own parsed functions).
        constants.emplace("pi", numbers::PI);
        auto function = std::make_shared<FunctionParser<3>>(n_components);
        // deal.II prints muparser's diagnosis to std::cerr before it
        // throws; the InputError below says it in one line instead.
        std::ostringstream    diagnosis;
        std::streambuf *const cerr_buffer = std::cerr.rdbuf(diagnosis.rdbuf());
        try
          {
            function->initialize("x,y,z,t", parts, constants, true);
            // Evaluate once: an undefined name shows only here.
            function->set_time(0.);
            for (unsigned int c = 0; c < n_components; ++c)
              function->value(Point<3>(), c);
            std::cerr.rdbuf(cerr_buffer);
          }
        catch (const ExceptionBase &error)
          {
            std::cerr.rdbuf(cerr_buffer);
            std::ostringstream message;
            error.print_info(message);
            std::string text = message.str();
            for (char &c : text)
              if (c == '\n')
                c = ' ';
            // One space between words.
            std::string folded;
            for (const char c : text)
              if (!(c == ' ' && (folded.empty() || folded.back() == ' ')))
                folded += c;
            throw InputError(path + "/" + entry,
                             "'" + expression.substr(0, 80) +
                               "' does not parse: " + folded.substr(0, 200));
          }
        catch (...)
          {
            std::cerr.rdbuf(cerr_buffer);
            throw InputError(path + "/" + entry,
                             "'" + expression.substr(0, 80) +
                               "' does not parse");
          }
        return function;
      }



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
        prm.declare_entry("Part", "", Patterns::Anything(), part_doc);
        prm.declare_entry("Point", "0, 0, 0", Patterns::Anything(),
                          "A point of the plane (mm). Put the plane inside "
                          "a layer of elements, not on their faces.");
        prm.declare_entry("Normal", "0, 0, 1", Patterns::Anything(),
                          normal_doc);
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
        plane.point = Point<3>(parse_vector(prm.get("Point"), path + "/Point"));
        const Tensor<1, 3> normal =
          parse_vector(prm.get("Normal"), path + "/Normal");
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
        prm.declare_entry(
          "Names", "", Patterns::Anything(),
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
            prm.declare_entry("Control", "force",
                              Patterns::Selection("force|shortening"),
                              "'force': the force through the section "
                              "rises linearly from 0 at t = 0 to the Target "
                              "force at the Lock time; 'shortening': the "
                              "shortening rises linearly to Shortening at "
                              "the Lock time. Both are held from then on "
                              "(the shortening stays fixed: the force then "
                              "follows the other loads).");
            prm.declare_entry("Target force", "0", Patterns::Double(),
                              "Axial force at the Lock time (kN, > 0: "
                              "tension), Control = force.");
            prm.declare_entry("Shortening", "0", Patterns::Double(),
                              "Shortening at the Lock time (mm, > 0), "
                              "Control = shortening.");
            prm.declare_entry("Lock time", "1", Patterns::Double(),
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
                section.lock_time >
                  time.quasi_static_end_time * (1. + 1e-12))
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
        prm.declare_entry(
          "Names", "", Patterns::Anything(),
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
    ModelStudy::declare_parameters(ParameterHandler &           prm,
                                   const registry::ListedNames &names)
    {
      prm.enter_subsection("Model");
      prm.declare_entry("Gravity", "0, 0, 0", Patterns::Anything(),
                        "Gravitational acceleration (mm/ms^2), three "
                        "components x, y, z; acts on the parts and on the "
                        "rigid bodies with mass. Earth: 0, 0, -9.81e-3. On a "
                        "quasi-static load path the weight grows with the "
                        "pseudo-time to its full value at the Quasi-static "
                        "end time.");
      prm.leave_subsection();

      prm.enter_subsection("Mesh");
      prm.declare_entry("Mesh file", "", Patterns::Anything(),
                        "Gmsh mesh (.msh, format 2.2 ASCII) of hexahedra; a "
                        "relative path is relative to the parameter file's "
                        "folder. Physical volume tags become material ids "
                        "(name them in Parts/<name>/Material ids), physical "
                        "surface tags boundary ids (for boundary conditions "
                        "and rigid surfaces). Tag 0 is reserved.");
      prm.declare_entry("Global refinement", "0", Patterns::Integer(0, 5),
                        "Number of global refinements of the mesh (each "
                        "splits every hexahedron into 8).");
      prm.declare_entry("Scale", "1", Patterns::Double(0.),
                        "Factor on the mesh's coordinates, e.g. 1000 for a "
                        "mesh in m (the model is in mm).");
      prm.leave_subsection();

      prm.enter_subsection("Parts");
      prm.declare_entry("Names", "", Patterns::Anything(),
                        "Names of the parts, separated by commas (letters, "
                        "digits, '_', '-'). Each has a subsection of its "
                        "name; every cell of the mesh belongs to exactly one "
                        "part.");
      for (const std::string &name : names_with_template(names, "Parts"))
        {
          prm.enter_subsection(name);
          prm.declare_entry("Material ids", "", Patterns::Anything(),
                            "The material ids (Gmsh physical volume tags) of "
                            "this part's cells, separated by commas.");
          prm.declare_entry("Element formulation", "F-bar",
                            Patterns::Selection("F-bar|displacement|mixed u-p"),
                            "'F-bar': volumetric part of F at the element "
                            "centre (no volumetric locking; for rubber); "
                            "'displacement': plain trilinear hexahedron; "
                            "'mixed u-p': triquadratic hexahedron with a "
                            "linear pressure and dilatation per cell, "
                            "condensed (Q2-P1-P1, for accuracy studies; "
                            "Time integration/Scheme = quasi-static only, "
                            "hyperelastic laws only, and then for every "
                            "deformable part; see doc/quasi_static.md).");
          prm.declare_entry(
            "F-bar stabilization",
            "",
            Patterns::Anything(),
            "F-bar parts only: this part's stiffness beta of the volumetric "
            "stabilisation (-, 0 to 1), instead of Time integration/F-bar "
            "stabilization, e.g. on for a crushed rubber part and off for "
            "bending metal parts (the stabilisation resists the Gauss-point "
            "volume changes of bending too: doc/theory.md 8.1, "
            "doc/bushing.md). Empty: Time integration/F-bar stabilization.");
          prm.declare_entry("Initial velocity", "0, 0, 0",
                            Patterns::Anything(),
                            "Velocity of the part's nodes at t = 0 (mm/ms), "
                            "x, y, z.");
          materials::registry::declare_part_parameters(
            prm,
            {"Yeoh", 1.1e-6, 0.499},
            {{"Rigid",
              "a rigid part (LS-DYNA's MAT_RIGID): its nodes move with one "
              "rigid body whose mass, centre of mass and inertia come from "
              "its cells and Density; Young's modulus and Poisson's ratio "
              "only set the stiffness of its contact; see Rigid motion. "
              "Its cells compute no stresses and do not limit the time "
              "step."}});
          prm.declare_entry(
            "Rigid motion", "free", Patterns::Anything(),
            "For Model = Rigid: 'free' (moves and turns under the forces "
            "on it and gravity), 'fixed' (held in place), or the list of "
            "its free directions from x, y, z (translations) and rx, ry, rz "
            "(rotations about axes through its centre of mass parallel to "
            "x, y, z), separated by commas; the others are held. Its "
            "Initial velocity (mm/ms) applies in its free translations.");
          prm.declare_entry(
            "Initial angular velocity", "0, 0, 0", Patterns::Anything(),
            "For Model = Rigid: angular velocity at t = 0 (rad/ms) about "
            "its centre of mass, x, y, z, in its free rotations.");
          prm.declare_entry(
            "Quasi-static motion", "held", Patterns::Selection("held|equilibrium"),
            "For Model = Rigid, on a quasi-static load path (Time "
            "integration/Scheme = quasi-static, and the preload of "
            "quasi-static then explicit): 'held' (it stands still: a drop "
            "weight waits above the specimen, its motion is the explicit "
            "run's), or 'equilibrium' (its free directions of Rigid motion "
            "are unknowns, found so that the forces on it, of the solid "
            "through its nodes and of the loads on its faces, have no "
            "resultant (kN) and no moment (kN mm) about its centre of mass in "
            "those directions; something must hold it in each of them). "
            "The explicit run takes its place from there.");
          prm.leave_subsection();
        }
      prm.leave_subsection();

      prm.enter_subsection("Boundary conditions");
      prm.declare_entry("Names", "", Patterns::Anything(),
                        "Names of the boundary conditions, separated by "
                        "commas; each has a subsection of its name. The "
                        "time history gets <name>_force_x/_y/_z (kN) and "
                        "<name>_moment_x/_y/_z (kN mm): the reaction the "
                        "condition exerts on the body.");
      for (const std::string &name :
           names_with_template(names, "Boundary conditions"))
        {
          prm.enter_subsection(name);
          prm.declare_entry("Boundary ids", "", Patterns::Anything(),
                            "The boundary ids (Gmsh physical surface tags) "
                            "of its faces, separated by commas.");
          prm.declare_entry(
            "Type", "fixed",
            Patterns::Selection(
              "fixed|displacement|velocity|symmetry|pressure|traction"),
            "'fixed': zero displacement in the Components; 'displacement': "
            "u = Function expression (mm); 'velocity': v = Function "
            "expression (mm/ms); 'symmetry': zero normal displacement of a "
            "plane face normal to a coordinate axis (Components and the "
            "function are not used); 'pressure': a follower pressure p = "
            "Function expression (GPa = kN/mm^2, one scalar expression), "
            "positive when it pushes on the surface, acting on the current "
            "(deformed) faces along their normal, f = -p n da; Components "
            "is not used and must be left at its default; 'traction': a "
            "load per reference area t = Function expression (GPa, one "
            "expression per listed component, the others zero), fixed in "
            "direction, f = t dA. For the loads the reaction columns show "
            "the load's resultant force and moment on the body. A load may "
            "share boundary ids with a kinematic condition, e.g. a pressure "
            "and a prescribed x, y on the same face.");
          prm.declare_entry("Components", "x, y, z", Patterns::Anything(),
                            "The directions it acts on, from x, y, z, "
                            "separated by commas.");
          prm.declare_entry(
            "Function expression", "0", Patterns::Anything(),
            "For 'displacement', 'velocity' and 'traction': one expression "
            "per listed component, separated by ';'; for 'pressure' one "
            "scalar expression; of x, y, z (mm, reference position) and t "
            "(ms), in deal.II's FunctionParser syntax (muparser), e.g. "
            "'0.1*t; 0' for two components. Must be 0 for the other "
            "types.");
          prm.declare_entry("Function constants", "", Patterns::Anything(),
                            "Constants used in the expression, e.g. "
                            "'v0 = 2, h = 10'.");
          prm.declare_entry("Moment point", "0, 0, 0", Patterns::Anything(),
                            "Point about which the reaction moment is "
                            "reported (mm).");
          prm.leave_subsection();
        }
      prm.leave_subsection();

      prm.enter_subsection("Rigid surfaces");
      prm.declare_entry("Names", "", Patterns::Anything(),
                        "Names of the rigid surfaces (plates, pins, holes), "
                        "separated by commas; each has a subsection of its "
                        "name and is carried by a rigid body. The time "
                        "history gets <name>_position_x/_y/_z (mm), "
                        "<name>_velocity_x/_y/_z (mm/ms) and "
                        "<name>_force_x/_y/_z (kN, the force of the solid on "
                        "it).");
      for (const std::string &name :
           names_with_template(names, "Rigid surfaces"))
        {
          prm.enter_subsection(name);
          prm.declare_entry(
            "Shape", "plane",
            Patterns::Selection("plane|cylinder with the solid outside|"
                                "cylinder with the solid inside"),
            "'plane': the solid stays on the side its Direction points to; "
            "'cylinder with the solid outside': a rigid pin of the Radius "
            "around the axis through Point along Direction; 'cylinder with "
            "the solid inside': a rigid tube or hole.");
          prm.declare_entry("Point", "0, 0, 0", Patterns::Anything(),
                            "A point of the plane, or of the cylinder's axis "
                            "(mm), at t = 0; its position is reported.");
          prm.declare_entry("Direction", "0, 0, 1", Patterns::Anything(),
                            "Plane: its normal, pointing into the solid; "
                            "cylinder: its axis. Need not be a unit vector.");
          prm.declare_entry("Radius", "0", Patterns::Double(0.),
                            "Cylinder radius (mm).");
          prm.declare_entry("Mass", "0", Patterns::Double(0.),
                            "Mass of the rigid body (kg); 0: it moves as "
                            "prescribed by Velocity function (or is held).");
          prm.declare_entry("Free directions", "", Patterns::Anything(),
                            "With Mass > 0: the directions in which it moves "
                            "under contact forces and gravity, from x, y, z; "
                            "in the others it follows Velocity function.");
          prm.declare_entry("Initial velocity", "0, 0, 0",
                            Patterns::Anything(),
                            "Velocity at t = 0 in its free directions "
                            "(mm/ms).");
          prm.declare_entry("Velocity function", "0; 0; 0",
                            Patterns::Anything(),
                            "Prescribed velocity (mm/ms) in the directions "
                            "that are not free: three expressions of t (ms) "
                            "separated by ';'. In Scheme = quasi-static: mm "
                            "per unit of pseudo-time, integrated over the "
                            "load path (free directions stand still); in "
                            "the load path of 'quasi-static then explicit' "
                            "the surface stands still.");
          prm.declare_entry("Function constants", "", Patterns::Anything(),
                            "Constants used in Velocity function.");
          prm.declare_entry("Boundary ids", "", Patterns::Anything(),
                            "The boundary ids of the solid faces that may "
                            "touch it, separated by commas.");
          prm.declare_entry("Friction coefficient", "0", Patterns::Double(0.),
                            "Coulomb friction coefficient towards the solid "
                            "(-).");
          prm.declare_entry("Penalty scale factor", "inherit",
                            Patterns::Anything(),
                            "Scale of the penalty stiffness s K A^2 / V "
                            "(-), or 'inherit' for Contact/Penalty scale "
                            "factor.");
          prm.declare_entry(
            "Rigid part", "", Patterns::Anything(),
            "Name of a part with Model = Rigid that carries this surface: "
            "its Point and Direction are given at t = 0 and move and turn "
            "with the part, and its contact forces act on the part. Mass, "
            "Free directions, Initial velocity and Velocity function must "
            "then stay at their defaults (the part's own apply). Empty: the "
            "surface has a body of its own.");
          prm.leave_subsection();
        }
      prm.leave_subsection();

      declare_pretension_sections(prm, names);
      declare_cross_sections(prm, names);
      declare_contact_pairs(prm, names);
    }



    ModelStudy::ModelStudy(ParameterHandler &prm,
                           const std::string &parameter_file)
    {
      using parameter_tools::require_positive;
      const std::string model_parameters =
        simulation::ExplicitSimulation::model_parameters_text(prm);
      parameters::TimeIntegration time_integration;
      parameters::Contact         contact;
      parameters::Output          output;
      time_integration.parse_parameters(prm);
      contact.parse_parameters(prm);
      output.parse_parameters(prm);
      if (time_integration.scheme == "quasi-static" &&
          !output.history_expressions.empty())
        throw InputError("Output/History expressions",
                         "are computed in explicit runs only (Time "
                         "integration/Scheme is 'quasi-static')");

      model = std::make_unique<model::Model>(MPI_COMM_WORLD);
      model::Model &m = *model;

      prm.enter_subsection("Model");
      m.gravity = parse_vector(prm.get("Gravity"), "Model/Gravity");
      prm.leave_subsection();

      // The mesh, relative to the parameter file's folder.
      prm.enter_subsection("Mesh");
      std::string mesh_file = prm.get("Mesh file");
      const unsigned int refinement = prm.get_integer("Global refinement");
      const double       scale      = prm.get_double("Scale");
      prm.leave_subsection();
      if (mesh_file.empty())
        throw InputError("Mesh/Mesh file", "names no file; a Model needs a "
                                           "Gmsh mesh");
      require_positive(scale, "Mesh/Scale");
      if (std::filesystem::path(mesh_file).is_relative() &&
          !parameter_file.empty())
        mesh_file =
          (std::filesystem::path(parameter_file).parent_path() / mesh_file)
            .lexically_normal()
            .string();
      io::read_gmsh_mesh(m.triangulation, mesh_file, "Mesh/Mesh file");
      if (scale != 1.)
        GridTools::scale(scale, m.triangulation);
      m.triangulation.refine_global(refinement);

      // Material and boundary ids present in the mesh.
      std::set<types::material_id> material_ids_in_mesh;
      for (const auto &cell : m.triangulation.active_cell_iterators())
        if (cell->is_locally_owned())
          material_ids_in_mesh.insert(cell->material_id());
      {
        std::vector<types::material_id> local(material_ids_in_mesh.begin(),
                                               material_ids_in_mesh.end());
        for (const auto &ids : Utilities::MPI::all_gather(m.comm, local))
          material_ids_in_mesh.insert(ids.begin(), ids.end());
      }
      const std::set<types::boundary_id> boundary_ids_in_mesh =
        m.boundary_ids_in_mesh();
      const auto require_boundary_ids =
        [&](const std::set<types::boundary_id> &ids, const std::string &path) {
          for (const types::boundary_id id : ids)
            if (boundary_ids_in_mesh.count(id) == 0)
              throw InputError(path, "the mesh " + mesh_file +
                                       " has no boundary face with id " +
                                       std::to_string(id));
        };

      // Parts.
      prm.enter_subsection("Parts");
      for (const std::string &name : listed_names(prm))
        {
          const std::string path = "Parts/" + name;
          prm.enter_subsection(name);
          model::Part part;
          part.name = name;
          part.material_ids =
            parse_ids<types::material_id>(prm.get("Material ids"),
                                          path + "/Material ids",
                                          numbers::invalid_material_id - 1);
          for (const types::material_id id : part.material_ids)
            if (material_ids_in_mesh.count(id) == 0)
              throw InputError(path + "/Material ids",
                               "the mesh " + mesh_file +
                                 " has no cell with material id " +
                                 std::to_string(id));
          const bool        rigid       = prm.get("Model") == "Rigid";
          const std::string formulation = prm.get("Element formulation");
          part.formulation =
            formulation == "F-bar"        ? model::Formulation::fbar :
            formulation == "displacement" ? model::Formulation::displacement :
                                            model::Formulation::mixed_up;
          if (part.formulation == model::Formulation::mixed_up &&
              time_integration.scheme != "quasi-static")
            throw InputError(path + "/Element formulation",
                             "'mixed u-p' (part '" + name +
                               "') runs with Time integration/Scheme = "
                               "quasi-static only, not with '" +
                               time_integration.scheme +
                               "'; use 'F-bar' for the explicit engine");
          const std::string stabilization =
            Utilities::trim(prm.get("F-bar stabilization"));
          if (!stabilization.empty())
            {
              const std::string entry = path + "/F-bar stabilization";
              if (!Patterns::Double(0., 1.).match(stabilization))
                throw InputError(entry,
                                 "'" + stabilization.substr(0, 40) +
                                   "' is not a number from 0 to 1 (empty: " +
                                   elements::model_fbar_stabilization_entry +
                                   ")");
              if (rigid || part.formulation != model::Formulation::fbar)
                throw InputError(entry,
                                 "is for deformable parts of Element "
                                 "formulation = F-bar only; part '" +
                                   name + "' is " +
                                   (rigid ? std::string("rigid") :
                                            "of '" + formulation + "'"));
              part.fbar_stabilization =
                Utilities::string_to_double(stabilization);
            }
          part.initial_velocity =
            parse_vector(prm.get("Initial velocity"), path + "/Initial velocity");
          const std::string rigid_motion =
            Utilities::trim(prm.get("Rigid motion"));
          if (rigid)
            {
              // Density and the contact stiffness, with their checks.
              part.rigid = true;
              part.law   = std::make_unique<materials::Elastic<3>>(prm, path);
              part.initial_angular_velocity =
                parse_vector(prm.get("Initial angular velocity"),
                             path + "/Initial angular velocity");
              materials::check_derived_constants(*part.law, path);
              part.quasi_static_equilibrium =
                prm.get("Quasi-static motion") == "equilibrium";
              if (rigid_motion == "fixed")
                for (unsigned int d = 0; d < 3; ++d)
                  part.rigid_free_translation[d] =
                    part.rigid_free_rotation[d] = false;
              else if (rigid_motion != "free")
                {
                  for (unsigned int d = 0; d < 3; ++d)
                    part.rigid_free_translation[d] =
                      part.rigid_free_rotation[d] = false;
                  for (const std::string &item :
                       Utilities::split_string_list(rigid_motion))
                    {
                      const auto &names = model::rigid_direction_names;
                      const auto  found =
                        std::find(std::begin(names), std::end(names), item);
                      if (found == std::end(names))
                        throw InputError(
                          path + "/Rigid motion",
                          "'" + item.substr(0, 40) +
                            "' is none of free, fixed or a list of x, y, z, "
                            "rx, ry, rz");
                      const unsigned int k = found - std::begin(names);
                      (k < 3 ? part.rigid_free_translation[k] :
                               part.rigid_free_rotation[k - 3]) = true;
                    }
                }
            }
          else
            {
              if (Utilities::trim(prm.get("Initial angular velocity")) !=
                  "0, 0, 0")
                throw InputError(path + "/Initial angular velocity",
                                 "is for Model = Rigid only");
              if (rigid_motion != "free")
                throw InputError(path + "/Rigid motion",
                                 "is for Model = Rigid only; this part's "
                                 "Model is " +
                                   prm.get("Model"));
              if (prm.get("Quasi-static motion") != "held")
                throw InputError(path + "/Quasi-static motion",
                                 "is for Model = Rigid only; this part's "
                                 "Model is " +
                                   prm.get("Model"));
              part.law = materials::registry::create<3>(prm, path);
            }
          prm.leave_subsection();
          m.parts.push_back(std::move(part));
        }
      prm.leave_subsection();
      if (m.parts.empty())
        throw InputError("Parts/Names", "names no part; every cell of the "
                                        "mesh must belong to one");

      // Boundary conditions.
      prm.enter_subsection("Boundary conditions");
      for (const std::string &name : listed_names(prm))
        {
          const std::string path = "Boundary conditions/" + name;
          prm.enter_subsection(name);
          model::BoundaryCondition bc;
          bc.name = name;
          bc.boundary_ids =
            parse_ids<types::boundary_id>(prm.get("Boundary ids"),
                                          path + "/Boundary ids",
                                          numbers::internal_face_boundary_id -
                                            1);
          require_boundary_ids(bc.boundary_ids, path + "/Boundary ids");
          const std::string type = prm.get("Type");
          using Type = model::BoundaryCondition::Type;
          bc.type = type == "fixed"        ? Type::fixed :
                    type == "displacement" ? Type::displacement :
                    type == "velocity"     ? Type::velocity :
                    type == "pressure"     ? Type::pressure :
                    type == "traction"     ? Type::traction :
                                             Type::symmetry;
          bc.components =
            parse_components(prm.get("Components"), path + "/Components");
          if (bc.type == Type::pressure && bc.components.size() != 3)
            throw InputError(path + "/Components",
                             "is not used by Type = pressure (it acts along "
                             "the surface's normal); leave it at its "
                             "default x, y, z");
          bc.moment_point =
            Point<3>(parse_vector(prm.get("Moment point"), path + "/Moment point"));
          const std::string expression = prm.get("Function expression");
          if (bc.type == Type::displacement || bc.type == Type::velocity ||
              bc.type == Type::traction || bc.type == Type::pressure)
            {
              const unsigned int n_functions =
                bc.type == Type::pressure ? 1 : bc.components.size();
              const std::shared_ptr<FunctionParser<3>> function =
                make_function(expression, prm.get("Function constants"),
                              n_functions, path,
                              bc.type == Type::pressure ?
                                "a pressure is one scalar" :
                                "one per listed component");
              bc.depends_on_position = uses_position(expression);
              for (unsigned int k = 0; k < n_functions; ++k)
                bc.functions.push_back(
                  [function, k](const Point<3> &X, const double t) {
                    function->set_time(t);
                    return function->value(X, k);
                  });
            }
          else if (Utilities::trim(expression) != "0")
            throw InputError(path + "/Function expression",
                             "is not used by Type = " + type +
                               "; leave it at 0");
          prm.leave_subsection();
          m.boundary_conditions.push_back(std::move(bc));
        }
      prm.leave_subsection();

      // Rigid surfaces, each on its own body.
      prm.enter_subsection("Rigid surfaces");
      for (const std::string &name : listed_names(prm))
        {
          const std::string path = "Rigid surfaces/" + name;
          prm.enter_subsection(name);
          model::RigidSurfaceDefinition definition;
          definition.name = name;
          const std::string shape = prm.get("Shape");
          definition.surface.shape =
            shape == "plane" ?
              model::RigidSurface::Shape::plane :
              shape == "cylinder with the solid outside" ?
              model::RigidSurface::Shape::cylinder_solid_outside :
              model::RigidSurface::Shape::cylinder_solid_inside;
          definition.surface.point =
            Point<3>(parse_vector(prm.get("Point"), path + "/Point"));
          const Tensor<1, 3> direction =
            parse_vector(prm.get("Direction"), path + "/Direction");
          if (!(direction.norm() > 0.))
            throw InputError(path + "/Direction", "must not be zero");
          definition.surface.normal = direction / direction.norm();
          definition.surface.radius = prm.get_double("Radius");
          if (definition.surface.shape != model::RigidSurface::Shape::plane)
            require_positive(definition.surface.radius, path + "/Radius");
          definition.surface.friction_coefficient =
            prm.get_double("Friction coefficient");
          definition.boundary_ids =
            parse_ids<types::boundary_id>(prm.get("Boundary ids"),
                                          path + "/Boundary ids",
                                          numbers::internal_face_boundary_id -
                                            1);
          require_boundary_ids(definition.boundary_ids, path + "/Boundary ids");
          const std::string penalty = Utilities::trim(prm.get("Penalty scale factor"));
          if (penalty == "inherit")
            definition.penalty_scale = contact.penalty_scale;
          else
            {
              try
                {
                  definition.penalty_scale = Utilities::string_to_double(penalty);
                }
              catch (...)
                {
                  throw InputError(path + "/Penalty scale factor",
                                   "'" + penalty.substr(0, 40) +
                                     "' is neither a number nor 'inherit'");
                }
              require_positive(definition.penalty_scale,
                               path + "/Penalty scale factor");
            }

          definition.rigid_part = Utilities::trim(prm.get("Rigid part"));
          if (!definition.rigid_part.empty())
            {
              bool found = false;
              for (const model::Part &part : m.parts)
                if (part.name == definition.rigid_part)
                  {
                    if (!part.rigid)
                      throw InputError(path + "/Rigid part",
                                       "the part '" + part.name +
                                         "' is not rigid (Model = Rigid)");
                    found = true;
                  }
              if (!found)
                throw InputError(path + "/Rigid part",
                                 "names no part ('" +
                                   definition.rigid_part.substr(0, 40) +
                                   "' is not in Parts/Names)");
              // The body's own motion entries, with their defaults.
              const std::pair<const char *, const char *> own_motion[] = {
                {"Mass", "0"},
                {"Free directions", ""},
                {"Initial velocity", "0, 0, 0"},
                {"Velocity function", "0; 0; 0"}};
              for (const auto &[entry, default_value] : own_motion)
                if (Utilities::trim(prm.get(entry)) != default_value)
                  throw InputError(path + "/" + entry,
                                   "must stay at its default when the "
                                   "surface is carried by the rigid part '" +
                                     definition.rigid_part +
                                     "' (the part's motion applies)");
            }

          model::RigidBody &body  = definition.body;
          body.name               = name;
          body.mass               = prm.get_double("Mass");
          body.reference_position = definition.surface.point;
          const std::string free  = Utilities::trim(prm.get("Free directions"));
          if (!free.empty())
            {
              if (!(body.mass > 0.))
                throw InputError(path + "/Free directions",
                                 "a body without mass (Mass = 0) cannot move "
                                 "freely; give it a Mass");
              for (const unsigned int d :
                   parse_components(free, path + "/Free directions"))
                body.free[d] = true;
            }
          body.velocity = parse_vector(prm.get("Initial velocity"),
                                       path + "/Initial velocity");
          // Named as 'Velocity function' in the messages (it was reported
          // as a 'Function expression', which rigid surfaces do not have).
          const std::shared_ptr<FunctionParser<3>> velocity =
            make_function(prm.get("Velocity function"),
                          prm.get("Function constants"), 3, path,
                          "one per direction x, y, z", "Velocity function");
          if (uses_position(prm.get("Velocity function")))
            throw InputError(path + "/Velocity function",
                             "may depend on t only");
          body.prescribed_velocity = [velocity](const double t) {
            velocity->set_time(t);
            Tensor<1, 3> v;
            for (unsigned int d = 0; d < 3; ++d)
              v[d] = velocity->value(Point<3>(), d);
            return v;
          };
          prm.leave_subsection();
          m.rigid_surfaces.push_back(std::move(definition));
        }
      prm.leave_subsection();

      parse_pretension_sections(prm, time_integration, m);
      parse_cross_sections(prm, time_integration, m);
      parse_contact_pairs(prm, require_boundary_ids, m);

      m.setup();
      if (time_integration.scheme == "quasi-static then explicit")
        preloaded = std::make_unique<simulation::PreloadedSimulation>(
          m, time_integration, output, "Model", model_parameters);
      else if (time_integration.scheme == "quasi-static")
        quasi_static = std::make_unique<simulation::QuasiStaticSimulation>(
          m, time_integration, output, "Model");
      else
        {
          simulation = std::make_unique<simulation::ExplicitSimulation>(
            m, time_integration, output, "Model", model_parameters);
          simulation->add_standard_postprocessors();
        }
    }



    ModelStudy::~ModelStudy() = default;



    void
    ModelStudy::run(std::ostream &log)
    {
      if (preloaded)
        preloaded->run(log);
      else if (quasi_static)
        quasi_static->run(log);
      else
        simulation->run(log);
    }



    void
    ModelStudy::check(std::ostream &log)
    {
      if (preloaded)
        preloaded->check(log);
      else if (quasi_static)
        quasi_static->check(log);
      else
        simulation->check(log);
    }



    namespace
    {
      const int model_study_registered = registry::register_study(
        "Model",
        "any multi-part solid model from a Gmsh mesh: parts, boundary "
        "conditions and rigid surfaces named in the parameter file "
        "(explicit, quasi-static, or quasi-static then explicit: 'Time "
        "integration/Scheme'; see doc/model.md)",
        &ModelStudy::declare_parameters,
        [](ParameterHandler &prm, const std::string &parameter_file)
          -> std::unique_ptr<Study> {
          return std::make_unique<ModelStudy>(prm, parameter_file);
        });
    } // namespace
  } // namespace studies
} // namespace rubberdyn
