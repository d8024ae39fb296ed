#include <deal.II/base/parameter_handler.h>

#include <rubberdyn/base/exceptions.h>
#include <rubberdyn/base/parameter_tools.h>
#include <rubberdyn/geometry/standing_cylinder.h>
#include <rubberdyn/materials/material_registry.h>
#include <rubberdyn/simulation/explicit_simulation.h>
#include <rubberdyn/model/model.h>
#include <rubberdyn/postprocess/drop_test_monitor.h>
#include <rubberdyn/postprocess/history_columns.h>
#include <rubberdyn/studies/drop_test.h>

#include <ostream>

namespace rubberdyn
{
  namespace studies
  {
    using namespace dealii;

    namespace
    {
      /**
       * Time after the impactor's separation from the rubber at which
       * `Stop after rebound` ends the run (ms): long enough to see the
       * contact force stay zero and the rebound velocity settle.
       */
      constexpr double rebound_margin = 1.;
    } // namespace



    struct DropTest::Parameters
    {
      double       impactor_mass, impact_velocity, diameter, height;
      double       friction, gravity;
      unsigned int refinement;
      bool         stop_after_rebound;
      bool         fbar;
      parameters::TimeIntegration time_integration;
      parameters::Contact         contact;
      parameters::Output          output;
      /**
       * The model's parameters (all but End time and the Output
       * subsection) as text: a restart must find the same in its checkpoint.
       */
      std::string  model_parameters;
      std::unique_ptr<materials::MaterialModel<3>> rubber;
    };



    void
    DropTest::declare_parameters(ParameterHandler &prm,
                                 const registry::ListedNames &)
    {
      prm.enter_subsection("Drop test");
      prm.declare_entry("Impactor mass", "5", Patterns::Double(0.),
                        "Mass of the rigid impactor (kg), free only along "
                        "the cylinder axis. Must be positive.");
      prm.declare_entry("Impact velocity", "2", Patterns::Double(0.),
                        "Downward velocity of the impactor when it touches "
                        "the cylinder (mm/ms = m/s).");
      prm.declare_entry("Cylinder diameter", "25", Patterns::Double(0.),
                        "Diameter of the rubber cylinder (mm).");
      prm.declare_entry("Cylinder height", "24", Patterns::Double(0.),
                        "Height of the rubber cylinder (mm).");
      prm.declare_entry("Friction coefficient", "0", Patterns::Double(0.),
                        "Coulomb friction coefficient between the rubber and "
                        "both plates (-); 0 (the reference study's choice) "
                        "keeps the compression homogeneous.");
      prm.declare_entry("Global refinement", "2", Patterns::Integer(0, 6),
                        "Number of global refinements of the coarse cylinder "
                        "mesh (5 cells per cross-section, 2 along the axis): "
                        "1 gives 80 cells, 2 gives 640 cells (about 3 mm), 3 "
                        "gives 5120 cells (about 1.5 mm).");
      prm.declare_entry("Gravity", "9.81e-3", Patterns::Double(0.),
                        "Gravitational acceleration (mm/ms^2), acting "
                        "downwards on the impactor and the rubber; 0 switches "
                        "it off.");
      prm.declare_entry("Stop after rebound", "false", Patterns::Bool(),
                        "End the run 1 ms after the impactor has separated "
                        "from the rubber on its way back up (contact force "
                        "zero after the impactor's velocity turned upwards), "
                        "or at the End time, whichever comes first. The "
                        "separation time and the rebound velocity are in "
                        "run_summary.json either way.");
      prm.leave_subsection();

      prm.enter_subsection("Time integration");
      prm.declare_entry("Element formulation", "F-bar",
                        Patterns::Selection("F-bar|displacement"),
                        "Drop test only (a Model chooses per part): 'F-bar': "
                        "volumetric part of F at the element centre (no "
                        "volumetric locking); 'displacement': plain "
                        "trilinear hexahedron (locks for nearly "
                        "incompressible rubber).");
      prm.leave_subsection();

      prm.enter_subsection("Materials");
      prm.enter_subsection("Rubber");
      materials::registry::declare_part_parameters(prm,
                                                   {"Yeoh", 1.1e-6, 0.499});
      prm.leave_subsection();
      prm.leave_subsection();
    }



    DropTest::DropTest(ParameterHandler &prm)
      : parameters(std::make_unique<Parameters>())
    {
      using parameter_tools::require_positive;
      Parameters &p      = *parameters;
      p.model_parameters = simulation::ExplicitSimulation::model_parameters_text(prm);
      prm.enter_subsection("Drop test");
      p.impactor_mass      = prm.get_double("Impactor mass");
      p.impact_velocity    = prm.get_double("Impact velocity");
      p.diameter           = prm.get_double("Cylinder diameter");
      p.height             = prm.get_double("Cylinder height");
      p.friction           = prm.get_double("Friction coefficient");
      p.refinement         = prm.get_integer("Global refinement");
      p.gravity            = prm.get_double("Gravity");
      p.stop_after_rebound = prm.get_bool("Stop after rebound");
      prm.leave_subsection();
      require_positive(p.impactor_mass, "Drop test/Impactor mass");
      require_positive(p.diameter, "Drop test/Cylinder diameter");
      require_positive(p.height, "Drop test/Cylinder height");

      p.time_integration.parse_parameters(prm);
      // The drop test is an impact: rigid surfaces and initial velocities,
      // which the quasi-static scheme cannot run.
      if (p.time_integration.scheme != "explicit")
        throw InputError("Time integration/Scheme",
                         "the Drop test study runs 'explicit' only, not '" +
                           p.time_integration.scheme + "'");
      prm.enter_subsection("Time integration");
      p.fbar = (prm.get("Element formulation") == "F-bar");
      prm.leave_subsection();
      p.contact.parse_parameters(prm);
      p.output.parse_parameters(prm);

      prm.enter_subsection("Materials");
      prm.enter_subsection("Rubber");
      p.rubber = materials::registry::create<3>(prm, "Materials/Rubber");
      prm.leave_subsection();
      prm.leave_subsection();
    }



    DropTest::~DropTest() = default;



    void
    DropTest::build_model(model::Model &model)
    {
      Parameters &p = *parameters;
      geometry::make_standing_cylinder(model.triangulation, p.diameter,
                                       p.height, p.refinement);

      model::Part rubber;
      rubber.name         = "Rubber";
      rubber.material_ids = {0};
      rubber.law          = std::move(p.rubber);
      rubber.formulation  = p.fbar ? model::Formulation::fbar :
                                     model::Formulation::displacement;
      model.parts.push_back(std::move(rubber));

      // The fixed bottom plate and the impactor, a plate of mass M free
      // only along the axis; both touch every face of the cylinder.
      const Tensor<1, 3> up({0., 0., 1.});
      const std::set<types::boundary_id> faces = {
        geometry::cylinder_boundary::hull,
        geometry::cylinder_boundary::bottom,
        geometry::cylinder_boundary::top};
      model::RigidSurfaceDefinition plate;
      plate.name                     = "bottom_plate";
      plate.surface                  = {Point<3>(0., 0., 0.), up, p.friction};
      plate.boundary_ids             = faces;
      plate.penalty_scale            = p.contact.penalty_scale;
      plate.initial_penetration      = p.contact.initial_penetration;
      plate.body.name                = plate.name;
      model.rigid_surfaces.push_back(plate);

      model::RigidSurfaceDefinition impactor;
      impactor.name          = "impactor";
      impactor.surface       = {Point<3>(0., 0., p.height), -up, p.friction};
      impactor.boundary_ids  = faces;
      impactor.penalty_scale = p.contact.penalty_scale;
      impactor.initial_penetration = p.contact.initial_penetration;
      impactor.body.name     = impactor.name;
      impactor.body.mass     = p.impactor_mass;
      impactor.body.free[2]  = true;
      impactor.body.velocity[2]      = -p.impact_velocity;
      impactor.body.reference_position = Point<3>(0., 0., p.height);
      model.rigid_surfaces.push_back(impactor);

      model.gravity = -p.gravity * up;
      model.setup();
    }



    void
    DropTest::check(std::ostream &log)
    {
      model::Model model(MPI_COMM_WORLD);
      build_model(model);
      simulation::ExplicitSimulation simulation(model, parameters->time_integration,
                                           parameters->output, "Drop test",
                                           parameters->model_parameters);
      simulation.check(log);
    }



    void
    DropTest::run(std::ostream &log)
    {
      const Parameters &p = *parameters;
      model::Model      model(MPI_COMM_WORLD);
      build_model(model);
      simulation::ExplicitSimulation simulation(model, p.time_integration, p.output,
                                           "Drop test", p.model_parameters);
      simulation.add_postprocessor(
        std::make_unique<postprocess::EnergyColumns>(false));
      simulation.add_postprocessor(
        std::make_unique<postprocess::DropTestMonitor>(
          model.dof_handler, *model.partitioner,
          geometry::cylinder_boundary::top,
          geometry::cylinder_boundary::bottom, 1, p.stop_after_rebound,
          rebound_margin, model.comm));
      simulation.run(log);
    }

    RUBBERDYN_REGISTER_STUDY(
      DropTest,
      "Drop test",
      "chapter 4 of the reference study: a rigid impactor dropped on a "
      "rubber cylinder standing on a rigid plate (explicit dynamics)")
  } // namespace studies
} // namespace rubberdyn
