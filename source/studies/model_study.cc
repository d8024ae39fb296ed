#include <deal.II/base/parameter_handler.h>

#include <rubberdyn/base/exceptions.h>
#include <rubberdyn/model/model.h>
#include <rubberdyn/simulation/explicit_simulation.h>
#include <rubberdyn/simulation/preloaded_simulation.h>
#include <rubberdyn/simulation/quasi_static_simulation.h>
#include <rubberdyn/studies/model_study.h>

#include <memory>
#include <ostream>
#include <set>
#include <string>

#include "model_study_parsing.h"

// The Model study: its own section `Model` (gravity) and the order in
// which the sections are read; each section is declared and parsed in a
// file of its own (model_study_parsing.h lists them).

namespace rubberdyn
{
  namespace studies
  {
    using namespace dealii;

    using namespace model_study_parsing;

    void
    ModelStudy::declare_parameters(ParameterHandler            &prm,
                                   const registry::ListedNames &names)
    {
      prm.enter_subsection("Model");
      prm.declare_entry("Gravity",
                        "0, 0, 0",
                        vector_pattern(),
                        "Gravitational acceleration (mm/ms^2), three "
                        "components x, y, z; acts on the parts and on the "
                        "rigid bodies with mass. Earth: 0, 0, -9.81e-3. On a "
                        "quasi-static load path the weight grows with the "
                        "pseudo-time to its full value at the Quasi-static "
                        "end time.");
      prm.leave_subsection();

      declare_mesh(prm);
      declare_parts(prm, names);
      declare_boundary_conditions(prm, names);
      declare_rigid_surfaces(prm, names);
      declare_part_sections(prm, names);
      declare_contact_pairs(prm, names);
    }



    ModelStudy::ModelStudy(ParameterHandler  &prm,
                           const std::string &parameter_file)
    {
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

      // Every section is read and checked before anything is written.
      model           = std::make_unique<model::Model>(MPI_COMM_WORLD);
      model::Model &m = *model;
      prm.enter_subsection("Model");
      m.gravity = parse_vector(prm.get("Gravity"));
      prm.leave_subsection();
      const MeshContents mesh = parse_mesh(prm, parameter_file, m);
      parse_parts(prm, time_integration, mesh, m);
      parse_boundary_conditions(prm, mesh, m);
      parse_rigid_surfaces(prm, contact, mesh, m);
      parse_part_sections(prm, time_integration, m);
      parse_contact_pairs(
        prm,
        [&mesh](const std::set<types::boundary_id> &ids,
                const std::string                  &path) {
          mesh.require_boundary_ids(ids, path);
        },
        m);

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
