#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>

#include <rubberdyn/base/partitioner.h>
#include <rubberdyn/base/exceptions.h>
#include <rubberdyn/base/parameter_tools.h>
#include <rubberdyn/contact/rigid_surface_contact.h>
#include <rubberdyn/elements/solid_hex_elements.h>
#include <rubberdyn/geometry/standing_cylinder.h>
#include <rubberdyn/materials/material_registry.h>
#include <rubberdyn/postprocess/field_output.h>
#include <rubberdyn/studies/drop_test.h>
#include <rubberdyn/time_integration/explicit_solver.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <map>
#include <ostream>
#include <sstream>

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

      /** Thrown by the monitor to end the run after the rebound. */
      struct StopAfterRebound
      {};

      /**
       * Area-weighted sums of the z displacement over the boundary faces
       * with one boundary id: the weight of a node is the integral of its
       * trilinear shape function over those faces of the locally owned
       * cells (reference configuration, straight-sided faces as the
       * elements see them), so the weights of all ranks add up to the
       * faces' area and every face is counted once.
       */
      class FaceAverage
      {
      public:
        FaceAverage(const DoFHandler<3> &              dof_handler,
                    const Utilities::MPI::Partitioner &partitioner,
                    const types::boundary_id           boundary_id,
                    const MPI_Comm                     comm)
        {
          const FiniteElement<3> &fe = dof_handler.get_fe();
          FEFaceValues<3>         fe_face_values(fe,
                                         QGauss<2>(2),
                                         update_values | update_JxW_values);
          std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
          std::map<types::global_dof_index, double> weight_of_dof;
          for (const auto &cell : dof_handler.active_cell_iterators())
            if (cell->is_locally_owned())
              for (const unsigned int f : cell->face_indices())
                if (cell->face(f)->at_boundary() &&
                    cell->face(f)->boundary_id() == boundary_id)
                  {
                    fe_face_values.reinit(cell, f);
                    cell->get_dof_indices(dofs);
                    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
                      if (fe.system_to_component_index(i).first == 2)
                        for (const unsigned int q :
                             fe_face_values.quadrature_point_indices())
                          weight_of_dof[dofs[i]] +=
                            fe_face_values.shape_value(i, q) *
                            fe_face_values.JxW(q);
                  }
          double local_area = 0.;
          for (const auto &[dof, weight] : weight_of_dof)
            {
              local_indices.push_back(partitioner.global_to_local(dof));
              weights.push_back(weight);
              local_area += weight;
            }
          area = Utilities::MPI::sum(local_area, comm);
        }

        /** This rank's share of the integral of u_z over the faces. */
        double
        local_integral(const VectorType &u) const
        {
          double sum = 0.;
          for (unsigned int k = 0; k < weights.size(); ++k)
            sum += weights[k] * u.local_element(local_indices[k]);
          return sum;
        }

        /** Area of the faces, summed over all ranks (mm^2). */
        double area = 0.;

      private:
        std::vector<unsigned int> local_indices;
        std::vector<double>       weights;
      };



      /** Smallest Jacobian determinants of the mesh, over all ranks. */
      struct MinimumJacobian
      {
        /** At the 2x2x2 Gauss points of the elements. */
        double gauss_points;
        /** At the element centres (the F-bar element's volume change). */
        double centres;
      };

      /**
       * The smallest J = det(I + grad u) at the Gauss points and at the
       * centres of all elements (trilinear geometry, as the elements use).
       * Collective; meant for output times, not every step.
       */
      MinimumJacobian
      minimum_jacobian(const DoFHandler<3> &dof_handler,
                       const VectorType &   u,
                       const MPI_Comm       comm)
      {
        const FEValuesExtractors::Vector displacement(0);
        FEValues<3> gauss(dof_handler.get_fe(), QGauss<3>(2), update_gradients);
        FEValues<3> centre(dof_handler.get_fe(),
                           QMidpoint<3>(),
                           update_gradients);
        const Tensor<2, 3>        identity = unit_symmetric_tensor<3>();
        std::vector<Tensor<2, 3>> gradients(8), centre_gradient(1);
        double min_gauss  = std::numeric_limits<double>::max();
        double min_centre = min_gauss;
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              gauss.reinit(cell);
              gauss[displacement].get_function_gradients(u, gradients);
              for (const Tensor<2, 3> &H : gradients)
                min_gauss = std::min(min_gauss, determinant(identity + H));
              centre.reinit(cell);
              centre[displacement].get_function_gradients(u, centre_gradient);
              min_centre =
                std::min(min_centre, determinant(identity + centre_gradient[0]));
            }
        double values[2] = {min_gauss, min_centre};
        Utilities::MPI::min(ArrayView<const double>(values, 2),
                            comm,
                            ArrayView<double>(values, 2));
        return {values[0], values[1]};
      }

      // The header and the rows of the CSV file @p path whose first column
      // (the time) is below @p time.
      std::string
      rows_before(const std::string &path, const double time)
      {
        std::ifstream file(path);
        std::string   line, kept;
        if (!std::getline(file, line))
          throw InputError("Output/Restart from checkpoint",
                           "cannot read " + path);
        kept = line + '\n';
        while (std::getline(file, line))
          if (!line.empty() && std::stod(line.substr(0, line.find(','))) < time)
            kept += line + '\n';
        return kept;
      }
    } // namespace



    struct DropTest::Parameters
    {
      double       impactor_mass, impact_velocity, diameter, height;
      double       friction, gravity;
      unsigned int refinement;
      bool         stop_after_rebound;
      double       end_time, time_step_scale, minimum_time_step;
      double       mass_scaling_time_step;
      bool         fbar;
      double       bulk_viscosity_linear, bulk_viscosity_quadratic;
      double       fbar_stabilization;
      double       penalty_scale;
      std::string  output_directory;
      postprocess::FieldOutput::Format field_output_format;
      double       field_output_interval, history_output_interval;
      bool         echo_history;
      double       checkpoint_interval;
      bool         restart;
      /**
       * The model's parameters (all but End time and the Output
       * subsection) as text: a restart must find the same in its checkpoint.
       */
      std::string  model_parameters;
      std::unique_ptr<materials::MaterialModel<3>> rubber;
    };



    void
    DropTest::declare_parameters(ParameterHandler &prm)
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
      prm.declare_entry("End time", "30", Patterns::Double(0.),
                        "Simulated time (ms).");
      prm.declare_entry("Time step scale factor", "0.9",
                        Patterns::Double(0., 1.),
                        "Factor on the smallest stable element and contact "
                        "time step (reference study eq. 2.12).");
      prm.declare_entry("Minimum time step", "1e-7", Patterns::Double(0.),
                        "The run stops with an error if the time step falls "
                        "below this (ms).");
      prm.declare_entry("Mass scaling time step", "0", Patterns::Double(0.),
                        "Target time step for mass scaling (ms): elements "
                        "whose stable step is smaller get added density; the "
                        "added mass is reported. 0 switches it off.");
      prm.declare_entry("Element formulation", "F-bar",
                        Patterns::Selection("F-bar|displacement"),
                        "'F-bar': volumetric part of F at the element centre "
                        "(no volumetric locking); 'displacement': plain "
                        "trilinear hexahedron (locks for nearly "
                        "incompressible rubber).");
      prm.declare_entry("Bulk viscosity linear", "0.06", Patterns::Double(0.),
                        "Linear bulk viscosity coefficient (-), LS-DYNA's Q2.");
      prm.declare_entry("F-bar stabilization", "0", Patterns::Double(0., 1.),
                        "F-bar only: stiffness beta of the volumetric "
                        "stabilisation kappa/2 (r + 1/r - 2), r = J_q / J_0, "
                        "kappa = beta K (-): it resists Gauss-point volume "
                        "changes at a fixed element-centre volume, which F-bar "
                        "leaves to the shear stiffness alone (doc/theory.md "
                        "8.1). 0 switches it off.");
      prm.declare_entry("Bulk viscosity quadratic", "1.5", Patterns::Double(0.),
                        "Quadratic bulk viscosity coefficient (-), LS-DYNA's "
                        "Q1.");
      prm.leave_subsection();

      prm.enter_subsection("Contact");
      prm.declare_entry("Penalty scale factor", "0.1", Patterns::Double(0.),
                        "Scale s of the penalty stiffness k = s K A^2 / V of "
                        "each contact face (-), as LS-DYNA's SLSFAC.");
      prm.leave_subsection();

      prm.enter_subsection("Output");
      prm.declare_entry("Field output interval", "1", Patterns::Double(0.),
                        "Time between ParaView outputs (ms); 0 writes none.");
      prm.declare_entry(
        "Field output format", "vtu",
        Patterns::Selection(postprocess::FieldOutput::format_names()),
        "'vtu': per output time a solution_NNNN.pvtu with one .vtu per rank, "
        "indexed by solution.pvd. 'hdf5' (for large runs): per output time "
        "one solution_NNNN.h5 written by all ranks in parallel (MPI-IO), "
        "holding the mesh, the nodal vectors and the cell fields, indexed by "
        "solution.xdmf. Both open in ParaView as a time series: reference "
        "mesh with displacement, velocity (nodal), Cauchy stress "
        "components, von Mises stress, pressure (GPa), J and MPI rank "
        "(cell averages).");
      prm.declare_entry("Echo time history", "false", Patterns::Bool(),
                        "Also print every row of time_history.csv to the "
                        "terminal (for regression tests).");
      prm.declare_entry("History output interval", "0.05",
                        Patterns::Double(0.),
                        "Time between rows of time_history.csv (ms); 0 "
                        "writes every step.");
      prm.declare_entry("Checkpoint interval", "0", Patterns::Double(0.),
                        "Time between checkpoints (ms), written to the "
                        "directory 'checkpoint' in the output directory (one "
                        "binary file per rank plus study.txt, each replacing "
                        "the previous one); 0 writes none.");
      prm.declare_entry("Restart from checkpoint", "false", Patterns::Bool(),
                        "Continue from the checkpoint in the output "
                        "directory instead of starting at t = 0, with the "
                        "same number of ranks and the same model parameters "
                        "(End time and the output settings may differ). The "
                        "run continues exactly as the original would have; "
                        "time_history.csv keeps its rows before the "
                        "checkpoint, the ParaView series goes on in "
                        "solution_restart.pvd (.xdmf).");
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
      Parameters &p = *parameters;
      {
        std::ostringstream all;
        prm.print_parameters(all, ParameterHandler::ShortPRM);
        std::istringstream lines(all.str());
        std::string        line;
        unsigned int       output_depth = 0;
        while (std::getline(lines, line))
          {
            const auto first = line.find_first_not_of(' ');
            const std::string text =
              first == std::string::npos ? "" : line.substr(first);
            if (output_depth > 0)
              {
                if (text.rfind("subsection", 0) == 0)
                  ++output_depth;
                else if (text == "end")
                  --output_depth;
                continue;
              }
            if (text == "subsection Output")
              {
                output_depth = 1;
                continue;
              }
            if (text.rfind("set End time", 0) == 0 || text.empty() ||
                text[0] == '#')
              continue;
            p.model_parameters += text + '\n';
          }
      }
      prm.enter_subsection("Drop test");
      p.impactor_mass   = prm.get_double("Impactor mass");
      p.impact_velocity = prm.get_double("Impact velocity");
      p.diameter        = prm.get_double("Cylinder diameter");
      p.height          = prm.get_double("Cylinder height");
      p.friction        = prm.get_double("Friction coefficient");
      p.refinement      = prm.get_integer("Global refinement");
      p.gravity         = prm.get_double("Gravity");
      p.stop_after_rebound = prm.get_bool("Stop after rebound");
      prm.leave_subsection();
      require_positive(p.impactor_mass, "Drop test/Impactor mass");
      require_positive(p.diameter, "Drop test/Cylinder diameter");
      require_positive(p.height, "Drop test/Cylinder height");

      prm.enter_subsection("Time integration");
      p.end_time               = prm.get_double("End time");
      p.time_step_scale        = prm.get_double("Time step scale factor");
      p.minimum_time_step      = prm.get_double("Minimum time step");
      p.mass_scaling_time_step = prm.get_double("Mass scaling time step");
      p.fbar = (prm.get("Element formulation") == "F-bar");
      p.bulk_viscosity_linear    = prm.get_double("Bulk viscosity linear");
      p.bulk_viscosity_quadratic = prm.get_double("Bulk viscosity quadratic");
      p.fbar_stabilization       = prm.get_double("F-bar stabilization");
      prm.leave_subsection();
      require_positive(p.end_time, "Time integration/End time");
      require_positive(p.time_step_scale,
                       "Time integration/Time step scale factor");

      prm.enter_subsection("Contact");
      p.penalty_scale = prm.get_double("Penalty scale factor");
      prm.leave_subsection();
      require_positive(p.penalty_scale, "Contact/Penalty scale factor");

      prm.enter_subsection("Output");
      p.output_directory        = prm.get("Output directory");
      p.field_output_interval   = prm.get_double("Field output interval");
      p.field_output_format =
        postprocess::FieldOutput::parse_format(prm.get("Field output format"));
      p.history_output_interval = prm.get_double("History output interval");
      p.echo_history            = prm.get_bool("Echo time history");
      p.checkpoint_interval     = prm.get_double("Checkpoint interval");
      p.restart                 = prm.get_bool("Restart from checkpoint");
      prm.leave_subsection();

      prm.enter_subsection("Materials");
      prm.enter_subsection("Rubber");
      p.rubber = materials::registry::create<3>(prm, "Materials/Rubber");
      prm.leave_subsection();
      prm.leave_subsection();
    }



    DropTest::~DropTest() = default;



    void
    DropTest::run(std::ostream &log)
    {
      const Parameters &p    = *parameters;
      const MPI_Comm    comm = MPI_COMM_WORLD;
      const bool root = (Utilities::MPI::this_mpi_process(comm) == 0);
      const auto wall_start = std::chrono::steady_clock::now();

      parallel::distributed::Triangulation<3> triangulation(comm);
      geometry::make_standing_cylinder(triangulation, p.diameter, p.height,
                                       p.refinement);

      const FESystem<3> fe(FE_Q<3>(1), 3);
      DoFHandler<3>     dof_handler(triangulation);
      dof_handler.distribute_dofs(fe);
      const auto partitioner = rubberdyn::ghosted_partitioner(dof_handler);

      if (root)
        {
          log << "Drop test: " << triangulation.n_global_active_cells()
              << " cells, " << dof_handler.n_dofs() << " dofs, "
              << Utilities::MPI::n_mpi_processes(comm) << " ranks\n  Rubber: ";
          p.rubber->print_constants(log);
        }

      // Elements, mass scaling, contact, rigid bodies.
      elements::SolidHexElements elements;
      elements.initialize(
        dof_handler, partitioner, {{0, p.rubber.get()}},
        {p.fbar ? elements::Formulation::fbar :
                  elements::Formulation::displacement,
         p.bulk_viscosity_linear, p.bulk_viscosity_quadratic,
         p.fbar_stabilization});
      std::vector<double> density_scaling(elements.n_elements(), 1.);
      if (p.mass_scaling_time_step > 0.)
        {
          const std::vector<double> steps = elements.reference_time_steps();
          for (unsigned int e = 0; e < steps.size(); ++e)
            {
              const double step = p.time_step_scale * steps[e];
              if (step < p.mass_scaling_time_step)
                density_scaling[e] =
                  std::pow(p.mass_scaling_time_step / step, 2);
            }
        }

      contact::RigidSurfaceContact plates;
      const Tensor<1, 3>         up({0., 0., 1.});
      plates.initialize(dof_handler, partitioner,
                        {geometry::cylinder_boundary::hull,
                         geometry::cylinder_boundary::bottom,
                         geometry::cylinder_boundary::top},
                        {p.rubber->bulk_modulus()}, p.penalty_scale,
                        {{Point<3>(0., 0., 0.), up, p.friction},
                         {Point<3>(0., 0., p.height), -up, p.friction}});

      std::vector<time_integration::RigidBody> bodies(2);
      bodies[1].mass        = p.impactor_mass;
      bodies[1].free[2]     = true;
      bodies[1].velocity[2] = -p.impact_velocity;

      time_integration::ExplicitSettings settings;
      settings.time_step_scale        = p.time_step_scale;
      settings.minimum_time_step      = p.minimum_time_step;
      settings.gravity                = -p.gravity * up;
      time_integration::ExplicitSolver solver(dof_handler, elements, plates,
                                              bodies, partitioner,
                                              density_scaling, settings, comm);
      // Added mass of mass scaling per part (one part here).
      std::vector<double> added_mass_by_part =
        elements.mass_by_law(density_scaling);
      {
        const std::vector<double> physical = elements.mass_by_law(
          std::vector<double>(density_scaling.size(), 1.));
        for (unsigned int i = 0; i < added_mass_by_part.size(); ++i)
          added_mass_by_part[i] -= physical[i];
        Utilities::MPI::sum(ArrayView<const double>(added_mass_by_part),
                            comm,
                            ArrayView<double>(added_mass_by_part));
      }
      if (root)
        log << "  Lumped mass " << solver.physical_mass() << " kg, added mass "
            << solver.added_mass() << " kg (Rubber " << added_mass_by_part[0]
            << " kg)" << std::endl;

      // Probes of the rubber's top and bottom faces: the impactor's
      // position includes the penetration of the penalty contact, the
      // rubber's own height does not.
      const FaceAverage top_face(dof_handler, *partitioner,
                                 geometry::cylinder_boundary::top, comm);
      const FaceAverage bottom_face(dof_handler, *partitioner,
                                    geometry::cylinder_boundary::bottom, comm);

      // Output.
      std::filesystem::create_directories(p.output_directory);
      std::ofstream history;
      if (root)
        {
          // A restart rewrites the file only once its checkpoint has been
          // accepted (below), so that a refused restart loses nothing.
          history << std::setprecision(9);
          if (!p.restart)
            {
              history.open(p.output_directory + "/time_history.csv");
              history << "time,time_step,kinetic_energy,internal_energy,"
                         "external_work,contact_work,bulk_viscosity_work,"
                         "added_mass,energy_error,impactor_displacement,"
                         "impactor_force,rubber_top_displacement,"
                         "rubber_bottom_displacement,friction_work\n";
            }
        }
      postprocess::FieldOutput fields(p.output_directory,
                                      p.restart ? "solution_restart" :
                                                  "solution",
                                      comm,
                                      p.field_output_format);
      MinimumJacobian min_jacobian{std::numeric_limits<double>::max(),
                                   std::numeric_limits<double>::max()};
      double time_of_min_jacobian = 0.;
      const auto write_fields = [&]() {
        const auto averages = elements.cell_averages(
          solver.displacement(), triangulation.n_active_cells());
        const char *names[6] = {"cauchy_stress_xx", "cauchy_stress_yy",
                                "cauchy_stress_zz", "cauchy_stress_xy",
                                "cauchy_stress_xz", "cauchy_stress_yz"};
        std::vector<std::pair<std::string, std::vector<float>>> cell_data;
        for (unsigned int k = 0; k < 6; ++k)
          cell_data.emplace_back(names[k], averages.cauchy_stress[k]);
        cell_data.emplace_back("von_mises_stress", averages.von_mises);
        cell_data.emplace_back("pressure", averages.pressure);
        cell_data.emplace_back("J", averages.jacobian);
        fields.write(dof_handler, solver.displacement(), solver.velocity(),
                     cell_data, solver.time());
        const MinimumJacobian now =
          minimum_jacobian(dof_handler, solver.displacement(), comm);
        if (now.gauss_points < min_jacobian.gauss_points)
          time_of_min_jacobian = solver.time();
        min_jacobian.gauss_points =
          std::min(min_jacobian.gauss_points, now.gauss_points);
        min_jacobian.centres = std::min(min_jacobian.centres, now.centres);
      };

      double next_history = 0., next_field = 0., max_energy_error = 0.;
      double max_force = 0., max_displacement = 0.;
      double time_of_max_displacement = 0., max_rubber_compression = 0.;
      double last_history_time = -1.;
      // Rebound: the impactor's velocity has turned upwards; separation:
      // after that, the contact force is zero (reset if contact resumes).
      bool   rebounding = false;
      double separation_time = -1., rebound_velocity = 0.;
      auto   last_progress = std::chrono::steady_clock::now();
      const auto write_history_row = [&]() {
        const double t = solver.time();
        const auto & e = solver.energies();
        // One MPI sum per row (never per step) for the two face probes.
        double face_integrals[2] = {
          top_face.local_integral(solver.displacement()),
          bottom_face.local_integral(solver.displacement())};
        Utilities::MPI::sum(ArrayView<const double>(face_integrals, 2),
                            comm,
                            ArrayView<double>(face_integrals, 2));
        const double top    = -face_integrals[0] / top_face.area;
        const double bottom = -face_integrals[1] / bottom_face.area;
        max_rubber_compression =
          std::max(max_rubber_compression, top - bottom);
        std::ostringstream row;
        row << std::setprecision(9);
        row << t << ',' << solver.time_step() << ',' << e.kinetic << ','
            << e.internal << ',' << e.external_work << ',' << e.contact << ','
            << e.bulk_viscosity_work << ',' << solver.added_mass() << ','
            << e.relative_error() << ',' << -bodies[1].displacement[2] << ','
            << bodies[1].contact_force[2] << ',' << top << ',' << bottom
            << ',' << e.friction_work << '\n';
        if (root)
          {
            history << row.str();
            if (p.echo_history)
              log << row.str();
          }
        last_history_time = t;
      };
      const auto monitor = [&]() {
        const double t = solver.time();
        const auto & e = solver.energies();
        // The energy error is meaningful once energy has been exchanged.
        max_energy_error = std::max(max_energy_error, e.relative_error());
        max_force        = std::max(max_force, bodies[1].contact_force[2]);
        if (-bodies[1].displacement[2] > max_displacement)
          {
            max_displacement         = -bodies[1].displacement[2];
            time_of_max_displacement = t;
          }
        // Every rank holds the same (reduced) impactor force and velocity,
        // so all ranks take the same decisions below.
        if (bodies[1].velocity[2] > 0.)
          rebounding = true;
        if (rebounding)
          {
            if (bodies[1].contact_force[2] > 0.)
              separation_time = -1.;
            else if (separation_time < 0.)
              {
                separation_time  = t;
                rebound_velocity = bodies[1].velocity[2];
              }
          }
        if (t >= next_history * (1. - 1e-12))
          {
            write_history_row();
            next_history += p.history_output_interval;
          }
        if (p.field_output_interval > 0. &&
            t >= next_field * (1. - 1e-12))
          {
            write_fields();
            next_field += p.field_output_interval;
          }
        if (p.stop_after_rebound && separation_time >= 0. &&
            t >= separation_time + rebound_margin)
          {
            if (last_history_time < t)
              write_history_row();
            throw StopAfterRebound();
          }
        const auto now = std::chrono::steady_clock::now();
        if (root && now - last_progress > std::chrono::seconds(5))
          {
            const double elapsed =
              std::chrono::duration<double>(now - wall_start).count();
            log << "  step " << solver.step() << ", t = " << t
                << " ms, dt = " << solver.time_step() << " ms, about "
                << static_cast<int>(elapsed * (p.end_time - t) /
                                    std::max(t, 1e-12))
                << " s left" << std::endl;
            last_progress = now;
          }
      };

      // Checkpoints: the solver's state per rank, and the monitor's own
      // state (what it has seen and when it writes next) in study.txt.
      const std::string checkpoint_directory =
        p.output_directory + "/checkpoint";
      const std::string rank_file =
        checkpoint_directory + "/rank_" +
        std::to_string(Utilities::MPI::this_mpi_process(comm)) + ".bin";
      double next_checkpoint = p.checkpoint_interval;
      // The monitor's state, in a fixed order.
      const auto monitor_state = [&]() {
        return std::vector<double *>{&next_history,
                                     &next_field,
                                     &max_energy_error,
                                     &max_force,
                                     &max_displacement,
                                     &time_of_max_displacement,
                                     &max_rubber_compression,
                                     &last_history_time,
                                     &separation_time,
                                     &rebound_velocity,
                                     &min_jacobian.gauss_points,
                                     &min_jacobian.centres,
                                     &time_of_min_jacobian,
                                     &next_checkpoint};
      };
      const auto write_checkpoint = [&]() {
        if (root)
          std::filesystem::create_directories(checkpoint_directory);
        MPI_Barrier(comm);
        {
          std::ofstream out(rank_file + ".new", std::ios::binary);
          solver.save(out);
        }
        MPI_Barrier(comm);
        std::filesystem::rename(rank_file + ".new", rank_file);
        if (root)
          {
            std::ofstream study(checkpoint_directory + "/study.txt.new");
            study << std::setprecision(17) << "time " << solver.time() << '\n'
                  << "ranks " << Utilities::MPI::n_mpi_processes(comm)
                  << '\n'
                  << "rebounding " << (rebounding ? 1 : 0) << '\n';
            for (const double *value : monitor_state())
              study << *value << '\n';
            study << "model parameters\n" << p.model_parameters;
            study.close();
            std::filesystem::rename(checkpoint_directory + "/study.txt.new",
                                    checkpoint_directory + "/study.txt");
          }
      };
      if (p.restart)
        {
          std::ifstream study(checkpoint_directory + "/study.txt");
          std::ifstream in(rank_file, std::ios::binary);
          if (!study || !in)
            throw InputError("Output/Restart from checkpoint",
                             "there is no complete checkpoint in " +
                               checkpoint_directory);
          // "time" and "ranks" are for the reader: load() restores the time
          // and checks the number of ranks itself.
          std::string  key;
          double       time_value;
          unsigned int ranks, rebounding_flag;
          study >> key >> time_value >> key >> ranks >> key >> rebounding_flag;
          for (double *value : monitor_state())
            study >> *value;
          if (!study)
            throw InputError("Output/Restart from checkpoint",
                             checkpoint_directory + "/study.txt is damaged");
          std::string line, stored_parameters;
          std::getline(study, line); // the end of the last number's line
          std::getline(study, line);
          if (line != "model parameters")
            throw InputError("Output/Restart from checkpoint",
                             checkpoint_directory + "/study.txt is damaged");
          while (std::getline(study, line))
            stored_parameters += line + '\n';
          if (stored_parameters != p.model_parameters)
            {
              // Name the first entry that differs.
              std::istringstream stored(stored_parameters),
                now(p.model_parameters);
              std::string a, b;
              while (std::getline(stored, a) && std::getline(now, b) && a == b)
                ;
              throw InputError("Output/Restart from checkpoint",
                               "the model differs from the checkpoint's ('" +
                                 b + "' here, '" + a +
                                 "' there); only End time and the Output "
                                 "settings may change on a restart");
            }
          rebounding = (rebounding_flag != 0);
          try
            {
              solver.load(in);
            }
          catch (const time_integration::SolverFailure &failure)
            {
              throw InputError("Output/Restart from checkpoint",
                               "cannot continue from " + checkpoint_directory +
                                 ": " + failure.what());
            }
          if (root)
            {
              // Keep the rows before the checkpoint; the restarted run
              // writes the rest.
              const std::string path =
                p.output_directory + "/time_history.csv";
              const std::string kept = rows_before(path, solver.time());
              history.open(path);
              history << kept;
              log << "  Restarted from the checkpoint at t = " << solver.time()
                  << " ms, step " << solver.step() << std::endl;
            }
        }

      bool stopped_after_rebound = false;
      try
        {
          // Run in segments that end at the checkpoint times (a segmented
          // run is the same arithmetic as an unsegmented one).
          while (solver.time() < p.end_time * (1. - 1e-12))
            {
              const double stop =
                p.checkpoint_interval > 0. ?
                  std::min(p.end_time, next_checkpoint) :
                  p.end_time;
              solver.run(stop, monitor);
              if (p.checkpoint_interval > 0. &&
                  solver.time() >= next_checkpoint * (1. - 1e-12))
                {
                  next_checkpoint += p.checkpoint_interval;
                  write_checkpoint();
                }
            }
        }
      catch (const StopAfterRebound &)
        {
          stopped_after_rebound = true;
        }
      catch (const time_integration::SolverFailure &failure)
        {
          write_fields();
          throw std::runtime_error(std::string("drop test stopped: ") +
                                   failure.what() +
                                   "; the last state is in " +
                                   fields.index_file());
        }
      write_fields();

      const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                      wall_start)
          .count();
      const double element_cycles =
        double(triangulation.n_global_active_cells()) * solver.step();
      // Slowest rank's time in each part of the steps, per element-cycle.
      time_integration::StepTimings timings = solver.timings();
      for (double *t : {&timings.element_forces, &timings.contact,
                        &timings.vector_updates, &timings.communication,
                        &timings.output})
        *t = Utilities::MPI::max(*t, comm);
      const auto per_cycle = [&](const double seconds) {
        return 1e9 * seconds * Utilities::MPI::n_mpi_processes(comm) /
               element_cycles;
      };
      if (root)
        {
          const auto json_time = [](const double t) {
            return t >= 0. ? std::to_string(t) : std::string("null");
          };
          std::ofstream summary(p.output_directory + "/run_summary.json");
          summary << std::setprecision(9);
          summary << "{\n  \"cells\": " << triangulation.n_global_active_cells()
                  << ",\n  \"dofs\": " << dof_handler.n_dofs()
                  << ",\n  \"ranks\": " << Utilities::MPI::n_mpi_processes(comm)
                  << ",\n  \"time_steps\": " << solver.step()
                  << ",\n  \"end_time\": " << solver.time()
                  << ",\n  \"stopped_after_rebound\": "
                  << (stopped_after_rebound ? "true" : "false")
                  << ",\n  \"wall_seconds\": " << wall
                  << ",\n  \"ns_per_element_cycle\": "
                  << 1e9 * wall * Utilities::MPI::n_mpi_processes(comm) /
                       element_cycles
                  << ",\n  \"ns_per_element_cycle_breakdown\": {"
                  << "\"element_forces\": " << per_cycle(timings.element_forces)
                  << ", \"contact\": " << per_cycle(timings.contact)
                  << ", \"vector_updates\": "
                  << per_cycle(timings.vector_updates)
                  << ", \"communication\": " << per_cycle(timings.communication)
                  << ", \"output\": " << per_cycle(timings.output) << "}"
                  << ",\n  \"max_energy_error\": " << max_energy_error
                  << ",\n  \"added_mass_fraction\": "
                  << solver.added_mass() / solver.physical_mass()
                  << ",\n  \"added_mass_by_part\": {\"Rubber\": "
                  << added_mass_by_part[0] << "}"
                  << ",\n  \"friction_work\": "
                  << solver.energies().friction_work
                  << ",\n  \"rubber_mass\": " << solver.physical_mass()
                  << ",\n  \"top_face_area\": " << top_face.area
                  << ",\n  \"bottom_face_area\": " << bottom_face.area
                  << ",\n  \"max_impactor_force\": " << max_force
                  << ",\n  \"max_impactor_displacement\": " << max_displacement
                  << ",\n  \"time_of_max_impactor_displacement\": "
                  << time_of_max_displacement
                  << ",\n  \"max_rubber_compression\": "
                  << max_rubber_compression
                  << ",\n  \"separation_time\": " << json_time(separation_time)
                  << ",\n  \"rebound_velocity\": " << rebound_velocity
                  << ",\n  \"min_jacobian_gauss_points\": "
                  << min_jacobian.gauss_points
                  << ",\n  \"min_jacobian_centres\": " << min_jacobian.centres
                  << ",\n  \"time_of_min_jacobian\": " << time_of_min_jacobian
                  << "\n}\n";
          // Wall time and speed are in run_summary.json only, so that the
          // log of a run is reproducible.
          if (stopped_after_rebound)
            log << "Stopped " << rebound_margin
                << " ms after the impactor left the rubber at t = "
                << separation_time << " ms, rebound velocity "
                << rebound_velocity << " mm/ms" << std::endl;
          log << "Finished: " << solver.step() << " steps to t = "
              << solver.time() << " ms; largest energy error "
              << max_energy_error * 100. << " %" << std::endl;
          log << "  Largest impactor force " << max_force
              << " kN, largest compression " << max_displacement << " mm"
              << std::endl;
          if (max_energy_error > 0.01)
            log << "WARNING: the energy error exceeded 1 %" << std::endl;
        }
    }

    RUBBERDYN_REGISTER_STUDY(
      DropTest,
      "Drop test",
      "chapter 4 of the reference study: a rigid impactor dropped on a "
      "rubber cylinder standing on a rigid plate (explicit dynamics)")
  } // namespace studies
} // namespace rubberdyn
