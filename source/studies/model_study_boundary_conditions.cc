#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <rubberdyn/base/exceptions.h>
#include <rubberdyn/model/model.h>

#include <memory>
#include <string>

#include "model_study_parsing.h"

// The Model study's `Boundary conditions` section: kinematic conditions
// and surface loads on boundary ids, declared and parsed here.

namespace rubberdyn
{
  namespace studies
  {
    namespace model_study_parsing
    {
      void
      declare_boundary_conditions(ParameterHandler            &prm,
                                  const registry::ListedNames &names)
      {
        prm.enter_subsection("Boundary conditions");
        // Names: checked by listed_names() and the registry's name rules.
        prm.declare_entry("Names",
                          "",
                          Patterns::Anything(),
                          "Names of the boundary conditions, separated by "
                          "commas; each has a subsection of its name. The "
                          "time history gets <name>_force_x/_y/_z (kN) and "
                          "<name>_moment_x/_y/_z (kN mm): the reaction the "
                          "condition exerts on the body.");
        for (const std::string &name :
             names_with_template(names, "Boundary conditions"))
          {
            prm.enter_subsection(name);
            prm.declare_entry("Boundary ids",
                              "",
                              ids_pattern(),
                              "The boundary ids (Gmsh physical surface tags) "
                              "of its faces, separated by commas.");
            prm.declare_entry(
              "Type",
              "fixed",
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
            prm.declare_entry("Components",
                              "x, y, z",
                              Patterns::MultipleSelection("x|y|z"),
                              "The directions it acts on, from x, y, z, "
                              "separated by commas.");
            // An expression of x, y, z, t: muparser parses it (make_function).
            prm.declare_entry(
              "Function expression",
              "0",
              Patterns::Anything(),
              "For 'displacement', 'velocity' and 'traction': one expression "
              "per listed component, separated by ';'; for 'pressure' one "
              "scalar expression; of x, y, z (mm, reference position) and t "
              "(ms), in deal.II's FunctionParser syntax (muparser), e.g. "
              "'0.1*t; 0' for two components. Must be 0 for the other "
              "types. In 'quasi-static then explicit' a displacement, "
              "traction or pressure whose value at the Quasi-static end "
              "time differs from its value at t = 0 is a preload: ramped "
              "on the load path, then held at its end value through the "
              "explicit run (doc/quasi_static.md, the hand-off).");
            // "name = value, ...": read by make_function().
            prm.declare_entry("Function constants",
                              "",
                              Patterns::Anything(),
                              "Constants used in the expression, e.g. "
                              "'v0 = 2, h = 10'.");
            prm.declare_entry("Moment point",
                              "0, 0, 0",
                              vector_pattern(),
                              "Point about which the reaction moment is "
                              "reported (mm).");
            prm.leave_subsection();
          }
        prm.leave_subsection();
      }



      namespace
      {
        /** The condition @p name (its subsection is current). */
        model::BoundaryCondition
        parse_boundary_condition(ParameterHandler   &prm,
                                 const std::string  &name,
                                 const MeshContents &mesh)
        {
          const std::string        path = "Boundary conditions/" + name;
          model::BoundaryCondition bc;
          bc.name = name;
          bc.boundary_ids =
            parse_ids<types::boundary_id>(prm.get("Boundary ids"),
                                          path + "/Boundary ids",
                                          numbers::internal_face_boundary_id -
                                            1);
          mesh.require_boundary_ids(bc.boundary_ids, path + "/Boundary ids");
          const std::string type = prm.get("Type");
          using Type             = model::BoundaryCondition::Type;
          bc.type                = type == "fixed"        ? Type::fixed :
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
          bc.moment_point = Point<3>(parse_vector(prm.get("Moment point")));
          const std::string expression = prm.get("Function expression");
          if (bc.type == Type::displacement || bc.type == Type::velocity ||
              bc.type == Type::traction || bc.type == Type::pressure)
            {
              const unsigned int n_functions =
                bc.type == Type::pressure ? 1 : bc.components.size();
              const std::shared_ptr<FunctionParser<3>> function =
                make_function(expression,
                              prm.get("Function constants"),
                              n_functions,
                              path,
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
          return bc;
        }
      } // namespace



      void
      parse_boundary_conditions(ParameterHandler   &prm,
                                const MeshContents &mesh,
                                model::Model       &m)
      {
        prm.enter_subsection("Boundary conditions");
        for (const std::string &name : listed_names(prm))
          {
            prm.enter_subsection(name);
            m.boundary_conditions.push_back(
              parse_boundary_condition(prm, name, mesh));
            prm.leave_subsection();
          }
        prm.leave_subsection();
      }
    } // namespace model_study_parsing
  }   // namespace studies
} // namespace rubberdyn
