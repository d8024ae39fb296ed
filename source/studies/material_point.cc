#include <deal.II/base/parameter_handler.h>

#include <rubberdyn/base/exceptions.h>
#include <rubberdyn/base/parameter_tools.h>
#include <rubberdyn/materials/finite_strain_j2.h>
#include <rubberdyn/materials/material_registry.h>
#include <rubberdyn/studies/material_point.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <ostream>
#include <vector>

namespace rubberdyn
{
  namespace studies
  {
    namespace hd = materials::homogeneous_deformation;

    void
    MaterialPoint::declare_parameters(dealii::ParameterHandler &prm,
                                     const registry::ListedNames &)
    {
      prm.enter_subsection("Material point");
      prm.declare_entry(
        "Deformation mode",
        "uniaxial stress",
        dealii::Patterns::Selection(hd::mode_names()),
        "Homogeneous deformation of the specimen: 'uniaxial stress' F = "
        "diag(l, m, m), 'equibiaxial stress' F = diag(l, l, m), 'pure shear' "
        "F = diag(l, 1, m) (the free stretch m found so that the free faces "
        "carry no stress), 'simple shear' F = I + g e1 x e2, 'dilatation' "
        "F = l I.");
      prm.declare_entry("Final stretch",
                        "0.3",
                        dealii::Patterns::Double(0.),
                        "Stretch l reached at the end of loading (-), or the "
                        "amount of shear g for simple shear. Below 1 is "
                        "compression.");
      prm.declare_entry("Number of steps",
                        "70",
                        dealii::Patterns::Integer(1, 1000000),
                        "Number of equal load steps from the undeformed "
                        "state to the final stretch.");
      prm.declare_entry("Unload",
                        "false",
                        dealii::Patterns::Bool(),
                        "Return to the undeformed state after loading, in "
                        "as many steps (shows the unloading slope and "
                        "permanent set of J2 plasticity).");
      prm.leave_subsection();

      prm.enter_subsection("Materials");
      prm.enter_subsection("Specimen");
      // Defaults: the rubber of the reference study's drop test (ch. 4).
      materials::registry::declare_part_parameters(prm,
                                                   {"Yeoh", 1.1e-6, 0.499});
      prm.leave_subsection();
      prm.leave_subsection();
    }



    MaterialPoint::MaterialPoint(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Material point");
      mode       = hd::mode_from_name(prm.get("Deformation mode"));
      final_load = prm.get_double("Final stretch");
      n_steps    = prm.get_integer("Number of steps");
      unload     = prm.get_bool("Unload");
      prm.leave_subsection();
      if (mode != hd::Mode::simple_shear)
        parameter_tools::require_positive(final_load,
                                          "Material point/Final stretch");

      prm.enter_subsection("Output");
      output_directory = prm.get("Output directory");
      prm.leave_subsection();

      prm.enter_subsection("Materials");
      prm.enter_subsection("Specimen");
      material = materials::registry::create<3>(prm, "Materials/Specimen");
      prm.leave_subsection();
      prm.leave_subsection();
    }



    void
    MaterialPoint::compute(const std::function<void(const Row &)> &row) const
    {
      const unsigned int  n_state = material->n_state_variables();
      std::vector<double> state_old(n_state), state_new(n_state);
      material->initialize_state(dealii::make_array_view(state_old));

      const double start_load = (mode == hd::Mode::simple_shear ? 0. : 1.);
      double       mu         = 1.;
      const unsigned int n_total = (unload ? 2 * n_steps : n_steps);
      materials::MaterialResponse<3> response;
      for (unsigned int step = 0; step <= n_total; ++step)
        {
          const double fraction =
            (step <= n_steps ? double(step) / n_steps :
                               double(n_total - step) / n_steps);
          const double load =
            start_load + fraction * (final_load - start_load);
          // A state the law cannot reach (Newton fails, the material
          // inverts) or a result that is not finite is bad input: the
          // stretch, or a constant of the specimen, is out of range.
          const auto refuse = [&](const std::string &what) {
            throw InputError(
              "Material point/Final stretch",
              "the specimen cannot be taken to load " +
                parameter_tools::format_short(load) + " (step " +
                std::to_string(step) + " of " + std::to_string(n_total) +
                "): " + what +
                "; the stretch or a constant in 'Materials/Specimen' is out "
                "of range");
          };
          try
            {
              mu = hd::solve(*material,
                             mode,
                             load,
                             mu,
                             dealii::make_array_view(std::as_const(state_old)),
                             dealii::make_array_view(state_new),
                             response);
            }
          catch (const InputError &)
            {
              throw;
            }
          catch (const std::exception &error)
            {
              refuse(error.what());
            }
          state_old = state_new;

          Row r;
          r.step = step;
          r.load = load;
          r.F    = hd::deformation_gradient(mode, load, mu);
          r.J    = dealii::determinant(r.F);
          r.tau  = response.kirchhoff_stress;
          // First Piola-Kirchhoff P = tau F^{-T}.
          r.P = dealii::Tensor<2, 3>(r.tau) *
                dealii::transpose(dealii::invert(r.F));
          r.strain_energy_density = response.strain_energy_density;
          r.equivalent_plastic_strain =
            (n_state == materials::finite_strain_j2::n_state_variables ?
               state_new[materials::finite_strain_j2::
                           equivalent_plastic_strain_index] :
               0.);
          r.wave_speed = response.dilatational_wave_speed;

          bool finite = std::isfinite(r.J) && std::isfinite(r.tau.norm()) &&
                        std::isfinite(r.P.norm()) &&
                        std::isfinite(r.strain_energy_density) &&
                        std::isfinite(r.wave_speed) && r.J > 0.;
          if (!finite)
            refuse("the deformation or the response is not finite (J = " +
                   parameter_tools::format_short(r.J) + ", |tau| = " +
                   parameter_tools::format_short(r.tau.norm()) + " GPa)");
          row(r);
        }
    }



    void
    MaterialPoint::check(std::ostream &)
    {
      // The whole load path is cheap: compute it, write nothing.
      compute([](const Row &) {});
    }



    void
    MaterialPoint::run(std::ostream &log)
    {
      log << "Material point study, specimen material:\n  ";
      material->print_constants(log);

      // First without writing, so that a load path the specimen cannot
      // follow is refused before anything is written.
      check(log);

      std::filesystem::create_directories(output_directory);
      const std::string filename = output_directory + "/material_point.csv";
      std::ofstream     csv(filename);
      if (!csv)
        throw std::runtime_error("cannot write " + filename);
      csv << "step,load,F_11,F_22,F_33,F_12,J,cauchy_11,cauchy_22,cauchy_33,"
             "cauchy_12,nominal_11,strain_energy_density,"
             "equivalent_plastic_strain,wave_speed\n";
      csv << std::setprecision(10);

      Row last;
      compute([&](const Row &r) {
        const double J = r.J;
        csv << r.step << ',' << r.load << ',' << r.F[0][0] << ',' << r.F[1][1]
            << ',' << r.F[2][2] << ',' << r.F[0][1] << ',' << J << ','
            << r.tau[0][0] / J << ',' << r.tau[1][1] / J << ','
            << r.tau[2][2] / J << ',' << r.tau[0][1] / J << ',' << r.P[0][0]
            << ',' << r.strain_energy_density << ','
            << r.equivalent_plastic_strain << ',' << r.wave_speed << '\n';
        last = r;
      });
      log << "Wrote " << last.step + 1 << " steps to " << filename << std::endl;
      log << "Final state: load " << parameter_tools::format_short(last.load)
          << ", J = " << parameter_tools::format_short(last.J)
          << ", nominal stress P_11 = "
          << parameter_tools::format_short(last.P[0][0])
          << " GPa, strain energy density = "
          << parameter_tools::format_short(last.strain_energy_density) << " GPa"
          << std::endl;
    }

    RUBBERDYN_REGISTER_STUDY(
      MaterialPoint,
      "Material point",
      "one material point of 'Materials/Specimen' under a homogeneous "
      "deformation; writes material_point.csv")
  } // namespace studies
} // namespace rubberdyn
