#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <rubberdyn/base/exceptions.h>
#include <rubberdyn/materials/elastic.h>
#include <rubberdyn/materials/material_registry.h>
#include <rubberdyn/model/model.h>
#include <rubberdyn/model/rigid_body.h>

#include <algorithm>
#include <iterator>
#include <memory>
#include <string>

#include "model_study_parsing.h"

// The Model study's `Parts` section: each part's cells, law, element
// formulation and initial motion, declared and parsed here.

namespace rubberdyn
{
  namespace studies
  {
    namespace model_study_parsing
    {
      void
      declare_parts(ParameterHandler &prm, const registry::ListedNames &names)
      {
        prm.enter_subsection("Parts");
        // Names: checked by listed_names() and the registry's name rules.
        prm.declare_entry("Names",
                          "",
                          Patterns::Anything(),
                          "Names of the parts, separated by commas (letters, "
                          "digits, '_', '-'). Each has a subsection of its "
                          "name; every cell of the mesh belongs to exactly "
                          "one part.");
        for (const std::string &name : names_with_template(names, "Parts"))
          {
            prm.enter_subsection(name);
            prm.declare_entry("Material ids",
                              "",
                              ids_pattern(),
                              "The material ids (Gmsh physical volume tags) "
                              "of this part's cells, separated by commas.");
            prm.declare_entry(
              "Element formulation",
              "F-bar",
              Patterns::Selection("F-bar|displacement|mixed u-p"),
              "'F-bar': volumetric part of F at the element centre (no "
              "volumetric locking; for rubber); 'displacement': plain "
              "trilinear hexahedron; 'mixed u-p': triquadratic hexahedron "
              "with a linear pressure and dilatation per cell, condensed "
              "(Q2-P1-P1, for accuracy studies; Time integration/Scheme = "
              "quasi-static only, hyperelastic laws only, and then for every "
              "deformable part; see doc/quasi_static.md).");
            // Empty or one number: a list of at most one item says both.
            prm.declare_entry(
              "F-bar stabilization",
              "",
              Patterns::List(Patterns::Double(0., 1.), 0, 1, ","),
              "F-bar parts only: this part's stiffness beta of the "
              "volumetric stabilisation (-, 0 to 1), instead of Time "
              "integration/F-bar stabilization, e.g. on for a crushed rubber "
              "part and off for bending metal parts (the stabilisation "
              "resists the Gauss-point volume changes of bending too: "
              "doc/theory.md 8.1, doc/bushing.md). Empty: Time "
              "integration/F-bar stabilization.");
            prm.declare_entry(
              "Selective mass scaling time step",
              "",
              Patterns::List(Patterns::Double(0.), 0, 1, ","),
              "Deformable parts only: this part's target step of selective "
              "mass scaling (ms), instead of Time integration/Selective mass "
              "scaling time step; 0: none for this part. Empty: the model's.");
            prm.declare_entry("Initial velocity",
                              "0, 0, 0",
                              vector_pattern(),
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
              "Rigid motion",
              "free",
              Patterns::MultipleSelection("free|fixed|x|y|z|rx|ry|rz"),
              "For Model = Rigid: 'free' (moves and turns under the forces "
              "on it and gravity), 'fixed' (held in place), or the list of "
              "its free directions from x, y, z (translations) and rx, ry, "
              "rz (rotations about axes through its centre of mass parallel "
              "to x, y, z), separated by commas; the others are held. Its "
              "Initial velocity (mm/ms) applies in its free translations.");
            prm.declare_entry(
              "Initial angular velocity",
              "0, 0, 0",
              vector_pattern(),
              "For Model = Rigid: angular velocity at t = 0 (rad/ms) about "
              "its centre of mass, x, y, z, in its free rotations.");
            prm.declare_entry(
              "Quasi-static motion",
              "held",
              Patterns::Selection("held|equilibrium"),
              "For Model = Rigid, on a quasi-static load path (Time "
              "integration/Scheme = quasi-static, and the preload of "
              "quasi-static then explicit): 'held' (it stands still: a drop "
              "weight waits above the specimen, its motion is the explicit "
              "run's), or 'equilibrium' (its free directions of Rigid motion "
              "are unknowns, found so that the forces on it, of the solid "
              "through its nodes and of the loads on its faces, have no "
              "resultant (kN) and no moment (kN mm) about its centre of mass "
              "in those directions; something must hold it in each of "
              "them). The explicit run takes its place from there.");
            prm.leave_subsection();
          }
        prm.leave_subsection();
      }



      namespace
      {
        /**
         * A rigid part's free directions from `Rigid motion` (the current
         * subsection of @p prm is the part's, at @p path): 'free', 'fixed'
         * or a list of x, y, z, rx, ry, rz.
         */
        void
        parse_rigid_motion(ParameterHandler  &prm,
                           const std::string &path,
                           model::Part       &part)
        {
          const std::string rigid_motion =
            Utilities::trim(prm.get("Rigid motion"));
          if (rigid_motion == "free")
            return;
          for (unsigned int d = 0; d < 3; ++d)
            part.rigid_free_translation[d] = part.rigid_free_rotation[d] =
              false;
          if (rigid_motion == "fixed")
            return;
          for (const std::string &item :
               Utilities::split_string_list(rigid_motion))
            {
              const auto &names = model::rigid_direction_names;
              const auto  found =
                std::find(std::begin(names), std::end(names), item);
              // The pattern lets 'free' or 'fixed' into a list.
              if (found == std::end(names))
                throw InputError(path + "/Rigid motion",
                                 "'" + item.substr(0, 40) +
                                   "' stands alone: give 'free', 'fixed' or "
                                   "a list of directions from x, y, z, rx, "
                                   "ry, rz");
              const unsigned int k = found - std::begin(names);
              (k < 3 ? part.rigid_free_translation[k] :
                       part.rigid_free_rotation[k - 3]) = true;
            }
        }



        /**
         * The entries that only a rigid part has must stay at their
         * defaults on a deformable one (its subsection is current).
         */
        void
        refuse_rigid_entries(ParameterHandler &prm, const std::string &path)
        {
          if (Utilities::trim(prm.get("Initial angular velocity")) != "0, 0, 0")
            throw InputError(path + "/Initial angular velocity",
                             "is for Model = Rigid only");
          if (Utilities::trim(prm.get("Rigid motion")) != "free")
            throw InputError(path + "/Rigid motion",
                             "is for Model = Rigid only; this part's Model "
                             "is " +
                               prm.get("Model"));
          if (prm.get("Quasi-static motion") != "held")
            throw InputError(path + "/Quasi-static motion",
                             "is for Model = Rigid only; this part's Model "
                             "is " +
                               prm.get("Model"));
        }



        /** The part @p name (its subsection of `Parts` is current). */
        model::Part
        parse_part(ParameterHandler                  &prm,
                   const std::string                 &name,
                   const parameters::TimeIntegration &time,
                   const MeshContents                &mesh)
        {
          const std::string path = "Parts/" + name;
          model::Part       part;
          part.name = name;
          part.material_ids =
            parse_ids<types::material_id>(prm.get("Material ids"),
                                          path + "/Material ids",
                                          numbers::invalid_material_id - 1);
          for (const types::material_id id : part.material_ids)
            if (mesh.material_ids.count(id) == 0)
              throw InputError(path + "/Material ids",
                               "the mesh " + mesh.file +
                                 " has no cell with material id " +
                                 std::to_string(id));
          const bool        rigid       = prm.get("Model") == "Rigid";
          const std::string formulation = prm.get("Element formulation");
          part.formulation =
            formulation == "F-bar"        ? model::Formulation::fbar :
            formulation == "displacement" ? model::Formulation::displacement :
                                            model::Formulation::mixed_up;
          if (part.formulation == model::Formulation::mixed_up &&
              time.scheme != "quasi-static")
            throw InputError(path + "/Element formulation",
                             "'mixed u-p' (part '" + name +
                               "') runs with Time integration/Scheme = "
                               "quasi-static only, not with '" +
                               time.scheme +
                               "'; use 'F-bar' for the explicit engine");
          const std::string stabilization =
            Utilities::trim(prm.get("F-bar stabilization"));
          if (!stabilization.empty())
            {
              if (rigid || part.formulation != model::Formulation::fbar)
                throw InputError(path + "/F-bar stabilization",
                                 "is for deformable parts of Element "
                                 "formulation = F-bar only; part '" +
                                   name + "' is " +
                                   (rigid ? std::string("rigid") :
                                            "of '" + formulation + "'"));
              part.fbar_stabilization =
                Utilities::string_to_double(stabilization);
            }
          const std::string scaling_step =
            Utilities::trim(prm.get("Selective mass scaling time step"));
          if (!scaling_step.empty())
            {
              if (rigid)
                throw InputError(path + "/Selective mass scaling time step",
                                 "is for deformable parts only; part '" +
                                   name + "' is rigid");
              part.selective_mass_scaling_time_step =
                Utilities::string_to_double(scaling_step);
            }
          part.initial_velocity = parse_vector(prm.get("Initial velocity"));
          if (!rigid)
            {
              refuse_rigid_entries(prm, path);
              part.law = materials::registry::create<3>(prm, path);
              return part;
            }
          // Density and the contact stiffness, with their checks.
          part.rigid = true;
          part.law   = std::make_unique<materials::Elastic<3>>(prm, path);
          part.initial_angular_velocity =
            parse_vector(prm.get("Initial angular velocity"));
          materials::check_derived_constants(*part.law, path);
          part.quasi_static_equilibrium =
            prm.get("Quasi-static motion") == "equilibrium";
          parse_rigid_motion(prm, path, part);
          return part;
        }
      } // namespace



      void
      parse_parts(ParameterHandler                  &prm,
                  const parameters::TimeIntegration &time,
                  const MeshContents                &mesh,
                  model::Model                      &m)
      {
        prm.enter_subsection("Parts");
        for (const std::string &name : listed_names(prm))
          {
            prm.enter_subsection(name);
            m.parts.push_back(parse_part(prm, name, time, mesh));
            prm.leave_subsection();
          }
        prm.leave_subsection();
        if (m.parts.empty())
          throw InputError("Parts/Names",
                           "names no part; every cell of the mesh must "
                           "belong to one");
      }
    } // namespace model_study_parsing
  }   // namespace studies
} // namespace rubberdyn
