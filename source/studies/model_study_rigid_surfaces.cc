#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <rubberdyn/base/exceptions.h>
#include <rubberdyn/base/parameter_tools.h>
#include <rubberdyn/model/model.h>
#include <rubberdyn/model/rigid_body.h>

#include <memory>
#include <string>
#include <utility>

#include "model_study_parsing.h"

// The Model study's `Rigid surfaces` section: planes and cylinders carried
// by rigid bodies (their own, or a rigid part), declared and parsed here.

namespace rubberdyn
{
  namespace studies
  {
    namespace model_study_parsing
    {
      void
      declare_rigid_surfaces(ParameterHandler            &prm,
                             const registry::ListedNames &names)
      {
        prm.enter_subsection("Rigid surfaces");
        // Names: checked by listed_names() and the registry's name rules.
        prm.declare_entry("Names",
                          "",
                          Patterns::Anything(),
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
              "Shape",
              "plane",
              Patterns::Selection("plane|cylinder with the solid outside|"
                                  "cylinder with the solid inside"),
              "'plane': the solid stays on the side its Direction points to; "
              "'cylinder with the solid outside': a rigid pin of the Radius "
              "around the axis through Point along Direction; 'cylinder with "
              "the solid inside': a rigid tube or hole.");
            prm.declare_entry("Point",
                              "0, 0, 0",
                              vector_pattern(),
                              "A point of the plane, or of the cylinder's axis "
                              "(mm), at t = 0; its position is reported.");
            prm.declare_entry("Direction",
                              "0, 0, 1",
                              vector_pattern(),
                              "Plane: its normal, pointing into the solid; "
                              "cylinder: its axis. Need not be a unit vector.");
            prm.declare_entry("Radius",
                              "0",
                              Patterns::Double(0.),
                              "Cylinder radius (mm).");
            prm.declare_entry("Mass",
                              "0",
                              Patterns::Double(0.),
                              "Mass of the rigid body (kg); 0: it moves as "
                              "prescribed by Velocity function (or is held).");
            prm.declare_entry("Free directions",
                              "",
                              Patterns::MultipleSelection("x|y|z"),
                              "With Mass > 0: the directions in which it moves "
                              "under contact forces and gravity, from x, y, z; "
                              "in the others it follows Velocity function.");
            prm.declare_entry("Initial velocity",
                              "0, 0, 0",
                              vector_pattern(),
                              "Velocity at t = 0 in its free directions "
                              "(mm/ms).");
            // Expressions of t: muparser parses them (make_function).
            prm.declare_entry("Velocity function",
                              "0; 0; 0",
                              Patterns::Anything(),
                              "Prescribed velocity (mm/ms) in the directions "
                              "that are not free: three expressions of t (ms) "
                              "separated by ';'. In Scheme = quasi-static: mm "
                              "per unit of pseudo-time, integrated over the "
                              "load path (free directions stand still); in "
                              "the load path of 'quasi-static then explicit' "
                              "the surface stands still.");
            // "name = value, ...": read by make_function().
            prm.declare_entry("Function constants",
                              "",
                              Patterns::Anything(),
                              "Constants used in Velocity function.");
            prm.declare_entry("Boundary ids",
                              "",
                              ids_pattern(),
                              "The boundary ids of the solid faces that may "
                              "touch it, separated by commas.");
            prm.declare_entry("Friction coefficient",
                              "0",
                              Patterns::Double(0.),
                              "Coulomb friction coefficient towards the solid "
                              "(-).");
            // A number or the word 'inherit': no deal.II pattern takes both.
            prm.declare_entry("Penalty scale factor",
                              "inherit",
                              Patterns::Anything(),
                              "Scale of the penalty stiffness s K A^2 / V "
                              "(-), or 'inherit' for Contact/Penalty scale "
                              "factor.");
            // A part's name, checked against Parts/Names when parsed.
            prm.declare_entry(
              "Rigid part",
              "",
              Patterns::Anything(),
              "Name of a part with Model = Rigid that carries this surface: "
              "its Point and Direction are given at t = 0 and move and turn "
              "with the part, and its contact forces act on the part. Mass, "
              "Free directions, Initial velocity and Velocity function must "
              "then stay at their defaults (the part's own apply). Empty: the "
              "surface has a body of its own.");
            prm.leave_subsection();
          }
        prm.leave_subsection();
      }



      namespace
      {
        using parameter_tools::require_positive;

        /**
         * The surface @p name's shape, place and contact (its subsection
         * is current); the penalty scale resolved: its own or the
         * model-wide @p contact's.
         */
        model::RigidSurfaceDefinition
        parse_surface(ParameterHandler          &prm,
                      const std::string         &name,
                      const parameters::Contact &contact,
                      const MeshContents        &mesh)
        {
          const std::string             path = "Rigid surfaces/" + name;
          model::RigidSurfaceDefinition definition;
          definition.name         = name;
          const std::string shape = prm.get("Shape");
          definition.surface.shape =
            shape == "plane" ?
              model::RigidSurface::Shape::plane :
            shape == "cylinder with the solid outside" ?
              model::RigidSurface::Shape::cylinder_solid_outside :
              model::RigidSurface::Shape::cylinder_solid_inside;
          definition.surface.point = Point<3>(parse_vector(prm.get("Point")));
          const Tensor<1, 3> direction = parse_vector(prm.get("Direction"));
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
          mesh.require_boundary_ids(definition.boundary_ids,
                                    path + "/Boundary ids");
          const std::string penalty =
            Utilities::trim(prm.get("Penalty scale factor"));
          if (penalty == "inherit")
            definition.penalty_scale = contact.penalty_scale;
          else
            {
              try
                {
                  definition.penalty_scale =
                    Utilities::string_to_double(penalty);
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
          definition.initial_penetration = contact.initial_penetration;
          return definition;
        }



        /**
         * Check `Rigid part` of the surface at @p path against @p m's parts:
         * a rigid part, and the surface's own motion entries left at their
         * defaults.
         */
        void
        check_carrying_part(ParameterHandler              &prm,
                            const std::string             &path,
                            const model::Model            &m,
                            model::RigidSurfaceDefinition &definition)
        {
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
        }



        /**
         * The motion of the body of the surface at @p path that carries it
         * when no rigid part does: mass, free directions, initial and
         * prescribed velocity.
         */
        void
        parse_surface_body(ParameterHandler              &prm,
                           const std::string             &path,
                           const std::string             &name,
                           model::RigidSurfaceDefinition &definition)
        {
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
          body.velocity = parse_vector(prm.get("Initial velocity"));
          // Named as 'Velocity function' in the messages (it was reported
          // as a 'Function expression', which rigid surfaces do not have).
          const std::shared_ptr<FunctionParser<3>> velocity =
            make_function(prm.get("Velocity function"),
                          prm.get("Function constants"),
                          3,
                          path,
                          "one per direction x, y, z",
                          "Velocity function");
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
        }
      } // namespace



      void
      parse_rigid_surfaces(ParameterHandler          &prm,
                           const parameters::Contact &contact,
                           const MeshContents        &mesh,
                           model::Model              &m)
      {
        prm.enter_subsection("Rigid surfaces");
        for (const std::string &name : listed_names(prm))
          {
            const std::string path = "Rigid surfaces/" + name;
            prm.enter_subsection(name);
            model::RigidSurfaceDefinition definition =
              parse_surface(prm, name, contact, mesh);
            check_carrying_part(prm, path, m, definition);
            parse_surface_body(prm, path, name, definition);
            prm.leave_subsection();
            m.rigid_surfaces.push_back(std::move(definition));
          }
        prm.leave_subsection();
      }
    } // namespace model_study_parsing
  }   // namespace studies
} // namespace rubberdyn
