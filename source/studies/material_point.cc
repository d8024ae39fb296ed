#include <deal.II/base/parameter_handler.h>

#include <rubberdyn/base/exceptions.h>
#include <rubberdyn/base/parameter_tools.h>
#include <rubberdyn/materials/finite_strain_j2.h>
#include <rubberdyn/materials/material_registry.h>
#include <rubberdyn/studies/material_point.h>

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
    MaterialPoint::run(std::ostream &log)
    {
      log << "Material point study, specimen material:\n  ";
      material->print_constants(log);

      std::filesystem::create_directories(output_directory);
      const std::string filename = output_directory + "/material_point.csv";
      std::ofstream     csv(filename);
      if (!csv)
        throw std::runtime_error("cannot write " + filename);
      csv << "step,load,F_11,F_22,F_33,F_12,J,cauchy_11,cauchy_22,cauchy_33,"
             "cauchy_12,nominal_11,strain_energy_density,"
             "equivalent_plastic_strain,wave_speed\n";
      csv << std::setprecision(10);

      const unsigned int  n_state = material->n_state_variables();
      std::vector<double> state_old(n_state), state_new(n_state);
      material->initialize_state(dealii::make_array_view(state_old));

      const double start_load = (mode == hd::Mode::simple_shear ? 0. : 1.);
      double       mu         = 1.;
      const unsigned int n_total = (unload ? 2 * n_steps : n_steps);
      materials::MaterialResponse<3> response;
      double last_load = 0., last_J = 1., last_nominal_stress = 0.;
      for (unsigned int step = 0; step <= n_total; ++step)
        {
          const double fraction =
            (step <= n_steps ? double(step) / n_steps :
                               double(n_total - step) / n_steps);
          const double load =
            start_load + fraction * (final_load - start_load);
          mu = hd::solve(*material,
                         mode,
                         load,
                         mu,
                         dealii::make_array_view(std::as_const(state_old)),
                         dealii::make_array_view(state_new),
                         response);
          state_old = state_new;

          const dealii::Tensor<2, 3> F = hd::deformation_gradient(mode, load, mu);
          const double               J = dealii::determinant(F);
          const dealii::SymmetricTensor<2, 3> &tau = response.kirchhoff_stress;
          // First Piola-Kirchhoff P = tau F^{-T}.
          const dealii::Tensor<2, 3> P =
            dealii::Tensor<2, 3>(tau) * dealii::transpose(dealii::invert(F));
          const double alpha =
            (n_state == materials::finite_strain_j2::n_state_variables ?
               state_new[materials::finite_strain_j2::
                           equivalent_plastic_strain_index] :
               0.);
          csv << step << ',' << load << ',' << F[0][0] << ',' << F[1][1]
              << ',' << F[2][2] << ',' << F[0][1] << ',' << J << ','
              << tau[0][0] / J << ',' << tau[1][1] / J << ',' << tau[2][2] / J
              << ',' << tau[0][1] / J << ',' << P[0][0] << ','
              << response.strain_energy_density << ',' << alpha << ','
              << response.dilatational_wave_speed << '\n';
          last_load           = load;
          last_J              = J;
          last_nominal_stress = P[0][0];
        }
      log << "Wrote " << n_total + 1 << " steps to " << filename << std::endl;
      log << "Final state: load " << parameter_tools::format_short(last_load)
          << ", J = " << parameter_tools::format_short(last_J)
          << ", nominal stress P_11 = "
          << parameter_tools::format_short(last_nominal_stress)
          << " GPa, strain energy density = "
          << parameter_tools::format_short(response.strain_energy_density)
          << " GPa" << std::endl;
    }

    RUBBERDYN_REGISTER_STUDY(
      MaterialPoint,
      "Material point",
      "one material point of 'Materials/Specimen' under a homogeneous "
      "deformation; writes material_point.csv")
  } // namespace studies
} // namespace rubberdyn
