#include <deal.II/base/parameter_handler.h>
#include <deal.II/physics/elasticity/standard_tensors.h>

#include <rubberdyn/base/exceptions.h>
#include <rubberdyn/base/parameter_tools.h>
#include <rubberdyn/materials/material_registry.h>
#include <rubberdyn/materials/yeoh.h>
#include <rubberdyn/materials/yeoh_stress_kernel.h>

#include <cmath>
#include <ostream>

namespace rubberdyn
{
  namespace materials
  {
    using parameter_tools::format_number;
    using parameter_tools::format_short;
    using parameter_tools::require_positive;

    template <int dim>
    void
    Yeoh<dim>::declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry(
        "Constants from",
        "coefficients",
        Patterns::Selection("coefficients|initial shear modulus|"
                            "Shore A hardness"),
        "(Yeoh) Where C10, C20, C30 come from: 'coefficients' uses the "
        "entries C10, C20, C30; 'initial shear modulus' uses eq. 3.11 of the "
        "reference study, C10 = G/2, C20 = -G/20, C30 = G/200 with G = "
        "'Initial shear modulus'; 'Shore A hardness' takes Young's modulus "
        "from Gent's (1958) relation, G = E/3, then eq. 3.11.");
      prm.declare_entry("C10",
                        "0.00055",
                        Patterns::Double(),
                        "(Yeoh) Coefficient C10 (GPa). Must be positive; "
                        "G = 2 C10 at small strain.");
      prm.declare_entry("C20",
                        "-0.00005",
                        Patterns::Double(),
                        "(Yeoh) Coefficient C20 (GPa).");
      prm.declare_entry("C30",
                        "0.000015",
                        Patterns::Double(),
                        "(Yeoh) Coefficient C30 (GPa); governs large "
                        "strains.");
      prm.declare_entry("Initial shear modulus",
                        "0.0011",
                        Patterns::Double(0.),
                        "(Yeoh) Initial shear modulus G (GPa), used when "
                        "'Constants from = initial shear modulus'.");
      prm.declare_entry("Shore A hardness",
                        "52",
                        Patterns::Double(10., 90.),
                        "(Yeoh) Shore A hardness, in [10, 90], used when "
                        "'Constants from = Shore A hardness'. Gent's "
                        "relation is an empirical fit, best between 40 and "
                        "80 Shore A.");
      prm.declare_entry(
        "Volumetric model",
        "Poisson's ratio",
        Patterns::Selection("Poisson's ratio|bulk modulus|polynomial"),
        "(Yeoh) How the volumetric term sum_k (1/d_k)(J-1)^(2k) is set: "
        "from 'Poisson's ratio' (K = 2G(1+nu)/(3(1-2nu)), G = 2 C10, "
        "d1 = 2/K), from 'Bulk modulus' (d1 = 2/K), or from 'D1', 'D2', "
        "'D3' ('polynomial', eq. 3.16).");
      prm.declare_entry(
        "Volumetric function",
        "polynomial",
        Patterns::Selection(volumetric_function_names()),
        "(Yeoh) Which volumetric energy U(J) (GPa): 'polynomial' is the "
        "reference study's sum_k (1/d_k)(J-1)^(2k) (eq. 3.16), which stays "
        "finite as J -> 0 (U(0) = sum_k 1/d_k: a point can be crushed with "
        "finite work); 'log squared' is (K/2)(ln J)^2 and 'Simo-Taylor' is "
        "(K/4)(J^2 - 1 - 2 ln J), both infinite as J -> 0 and as J -> "
        "infinity. All three have the same small-strain bulk modulus K "
        "(from 'Volumetric model'; K = 2/D1), hence the same wave speed and "
        "stable step; they differ at finite volume change (doc/theory.md). "
        "The logarithmic ones take no D2, D3.");
      prm.declare_entry("Bulk modulus",
                        "1.1",
                        Patterns::Double(0.),
                        "(Yeoh) Small-strain bulk modulus K (GPa), used when "
                        "'Volumetric model = bulk modulus'. Rubber: 1000 to "
                        "2000 times the shear modulus.");
      prm.declare_entry("D1",
                        "0.002",
                        Patterns::Double(0.),
                        "(Yeoh) d1 of eq. 3.16 (1/GPa), used when "
                        "'Volumetric model = polynomial'. Must be positive; "
                        "K = 2/d1.");
      prm.declare_entry("D2",
                        "0",
                        Patterns::Double(0.),
                        "(Yeoh) d2 of eq. 3.16 (1/GPa); 0 omits the term.");
      prm.declare_entry("D3",
                        "0",
                        Patterns::Double(0.),
                        "(Yeoh) d3 of eq. 3.16 (1/GPa); 0 omits the term.");
    }



    template <int dim>
    double
    Yeoh<dim>::youngs_modulus_from_shore_a(const double hardness)
    {
      // Gent (1958), E in MPa; converted to GPa.
      const double E_MPa = 0.0981 * (56. + 7.62336 * hardness) /
                           (0.137505 * (254. - 2.54 * hardness));
      return 1e-3 * E_MPa;
    }



    template <int dim>
    Yeoh<dim>::Yeoh(const double                 C10,
                    const double                 C20,
                    const double                 C30,
                    const std::array<double, 3> &d,
                    const double                 density,
                    const VolumetricFunction     volumetric_function)
      : C10(C10)
      , C20(C20)
      , C30(C30)
      , rho(density)
      , volumetric_function(volumetric_function)
    {
      require_positive(C10, "C10");
      require_positive(d[0], "D1");
      require_positive(density, "Density");
      for (unsigned int k = 0; k < 3; ++k)
        {
          if (d[k] < 0.)
            throw InputError("D" + std::to_string(k + 1),
                             "must not be negative");
          inverse_d[k] = (d[k] > 0. ? 1. / d[k] : 0.);
        }
      if (volumetric_function != VolumetricFunction::polynomial &&
          (d[1] != 0. || d[2] != 0.))
        throw InputError(d[1] != 0. ? "D2" : "D3",
                         "D2 and D3 must be 0 with the volumetric function '" +
                           volumetric_function_name(volumetric_function) +
                           "', which takes only K = 2/D1");
    }



    template <int dim>
    Yeoh<dim>::Yeoh(const ParameterHandler &prm, const std::string &path)
    {
      const std::string constants_from = prm.get("Constants from");
      if (constants_from == "coefficients")
        {
          C10 = prm.get_double("C10");
          C20 = prm.get_double("C20");
          C30 = prm.get_double("C30");
          require_positive(C10, path + "/C10");
        }
      else
        {
          double G = 0.;
          shear_entry = (constants_from == "initial shear modulus" ?
                           "Initial shear modulus" :
                           "Shore A hardness");
          if (constants_from == "initial shear modulus")
            {
              G = prm.get_double("Initial shear modulus");
              require_positive(G, path + "/Initial shear modulus");
            }
          else
            G = youngs_modulus_from_shore_a(
                  prm.get_double("Shore A hardness")) /
                3.;
          // Reference study, eq. 3.11.
          C10 = G / 2.;
          C20 = -G / 20.;
          C30 = G / 200.;
        }

      rho = prm.get_double("Density");
      require_positive(rho, path + "/Density");

      const double      G                = 2. * C10;
      const std::string volumetric_model = prm.get("Volumetric model");
      volumetric_function =
        volumetric_function_from_name(prm.get("Volumetric function"));
      inverse_d = {{0., 0., 0.}};
      if (volumetric_model == "polynomial")
        {
          // The logarithmic functions have one constant, K = 2/D1: refuse
          // higher terms rather than drop them silently.
          if (volumetric_function != VolumetricFunction::polynomial &&
              (prm.get_double("D2") != 0. || prm.get_double("D3") != 0.))
            throw InputError(path +
                               (prm.get_double("D2") != 0. ? "/D2" : "/D3"),
                             "D2 and D3 must be 0 with 'Volumetric function "
                             "= " +
                               volumetric_function_name(volumetric_function) +
                               "', which takes only K = 2/D1");
          const char *names[3] = {"D1", "D2", "D3"};
          for (unsigned int k = 0; k < 3; ++k)
            {
              const double d = prm.get_double(names[k]);
              if (k == 0)
                require_positive(d, path + "/D1");
              inverse_d[k] = (d > 0. ? 1. / d : 0.);
            }
        }
      else
        {
          double K = 0.;
          bulk_entry = (volumetric_model == "bulk modulus" ? "Bulk modulus" :
                                                             "Poisson's ratio");
          if (volumetric_model == "bulk modulus")
            {
              K = prm.get_double("Bulk modulus");
              require_positive(K, path + "/Bulk modulus");
            }
          else
            {
              const double nu = prm.get_double("Poisson's ratio");
              if (!(nu >= 0. && nu < 0.5))
                throw InputError(
                  path + "/Poisson's ratio",
                  "must lie in [0, 0.5), but is " + format_number(nu) +
                    " (a compressible law needs a finite bulk modulus; "
                    "use 0.499 for nearly incompressible rubber)");
              K = 2. * G * (1. + nu) / (3. * (1. - 2. * nu));
            }
          inverse_d[0] = K / 2.;
        }
    }



    template <int dim>
    std::string
    Yeoh<dim>::name() const
    {
      return "Yeoh";
    }



    template <int dim>
    double
    Yeoh<dim>::density() const
    {
      return rho;
    }



    template <int dim>
    double
    Yeoh<dim>::shear_modulus() const
    {
      return 2. * C10;
    }



    template <int dim>
    double
    Yeoh<dim>::bulk_modulus() const
    {
      // U''(1) = 2/d1.
      return 2. * inverse_d[0];
    }



    template <int dim>
    double
    Yeoh<dim>::reference_wave_speed() const
    {
      return std::sqrt((bulk_modulus() + 4. / 3. * shear_modulus()) / rho);
    }



    template <int dim>
    std::vector<DerivedConstant>
    Yeoh<dim>::derived_constants() const
    {
      using parameter_tools::Sign;
      const bool from_coefficients = (shear_entry == "C10");
      // With 'Poisson's ratio', K is computed from G as well.
      std::vector<std::string> bulk_from = {bulk_entry};
      if (bulk_entry == "Poisson's ratio")
        bulk_from.push_back(shear_entry);
      return {{"the density", rho, "kg/mm^3", {"Density"}, Sign::positive},
              {"C10", C10, "GPa", {shear_entry}, Sign::positive},
              // As they enter dW/dI1 and its derivative.
              {"2 C20",
               2. * C20,
               "GPa",
               {from_coefficients ? "C20" : shear_entry},
               Sign::any},
              {"6 C30",
               6. * C30,
               "GPa",
               {from_coefficients ? "C30" : shear_entry},
               Sign::any},
              {"the shear modulus G = 2 C10",
               shear_modulus(),
               "GPa",
               {shear_entry},
               Sign::positive},
              {"the bulk modulus K = 2/d1",
               bulk_modulus(),
               "GPa",
               bulk_from,
               Sign::positive},
              {"1/d2", inverse_d[1], "GPa", {"D2"}, Sign::non_negative},
              {"1/d3", inverse_d[2], "GPa", {"D3"}, Sign::non_negative},
              {"the dilatational wave speed sqrt((K + 4G/3)/density)",
               reference_wave_speed(),
               "mm/ms",
               {shear_entry, bulk_entry, "Density"},
               Sign::positive}};
    }



    template <int dim>
    void
    Yeoh<dim>::print_constants(std::ostream &out) const
    {
      out << "Yeoh: C10 = " << format_short(C10)
          << " GPa, C20 = " << format_short(C20)
          << " GPa, C30 = " << format_short(C30)
          << " GPa, G = " << format_short(shear_modulus())
          << " GPa, K = " << format_short(bulk_modulus()) << " GPa, D1 = "
          << format_short(inverse_d[0] > 0 ? 1. / inverse_d[0] : 0.)
          << " 1/GPa, density = " << format_short(rho)
          << " kg/mm^3, wave speed = " << format_short(reference_wave_speed())
          << " mm/ms";
      // Only a non-default choice is named, so that the logs of existing
      // studies stay as they were.
      if (volumetric_function != VolumetricFunction::polynomial)
        out << ", volumetric function " +
                 volumetric_function_name(volumetric_function);
      out << std::endl;
    }



    template <int dim>
    std::unique_ptr<StressKernel>
    Yeoh<dim>::create_stress_kernel() const
    {
      return std::make_unique<YeohStressKernel>(
        std::array<double, 3>{{C10, C20, C30}},
        inverse_d,
        rho,
        volumetric_function);
    }



    template <int dim>
    void
    Yeoh<dim>::evaluate_3d(const Tensor<2, 3> & F,
                           const bool           compute_tangent,
                           MaterialResponse<3> &response) const
    {
      using Tensors = Physics::Elasticity::StandardTensors<3>;

      const double J = determinant(F);
      if (!(J > 0.) || !std::isfinite(J))
        throw InvertedMaterialError(J);

      // Isochoric left Cauchy-Green tensor and its invariant (eq. 3.15).
      const double                  J_m23 = std::pow(J, -2. / 3.);
      const SymmetricTensor<2, 3>   b_bar =
        J_m23 * symmetrize(Tensor<2, 3>(F * transpose(F)));
      const double                  I1_bar    = trace(b_bar);
      const SymmetricTensor<2, 3>   dev_b_bar = deviator(b_bar);
      const double                  x         = I1_bar - 3.;
      const double W1 = C10 + 2. * C20 * x + 3. * C30 * x * x; // dW/dI1bar
      const double W2 = 2. * C20 + 6. * C30 * x; // d2W/dI1bar2

      // Volumetric part: U, the Kirchhoff pressure tau_vol = J U' and
      // J^2 U'' (doc/theory.md, "Volumetric functions").
      double U = 0., tau_vol = 0., J2_d2U = 0.;
      if (volumetric_function == VolumetricFunction::polynomial)
        {
          // U(J) = sum_k (1/d_k)(J-1)^(2k) and its derivatives.
          const double y       = J - 1.;
          double       dU      = 0.;
          double       d2U     = 0.;
          double       y_power = 1.; // y^(2k-2)
          for (unsigned int k = 1; k <= 3; ++k)
            {
              const double c = inverse_d[k - 1];
              d2U += c * (2. * k) * (2. * k - 1.) * y_power;
              dU += c * (2. * k) * y_power * y;
              U += c * y_power * y * y;
              y_power *= y * y;
            }
          tau_vol = J * dU;
          J2_d2U  = J * J * d2U;
        }
      else
        {
          const double           K = 2. * inverse_d[0];
          const VolumetricValues v =
            (volumetric_function == VolumetricFunction::log_squared ?
               logarithmic_volumetric_values<VolumetricFunction::log_squared>(
                 J,
                 std::log(J),
                 K) :
               logarithmic_volumetric_values<VolumetricFunction::simo_taylor>(
                 J,
                 std::log(J),
                 K));
          U       = v.U;
          tau_vol = v.J_dU;
          J2_d2U  = v.J2_d2U;
        }

      const SymmetricTensor<2, 3> tau_iso = 2. * W1 * dev_b_bar;
      response.kirchhoff_stress           = tau_vol * Tensors::I + tau_iso;
      response.strain_energy_density =
        x * (C10 + x * (C20 + x * C30)) + U;

      // Upper estimate of the largest longitudinal acoustic modulus, exact
      // at F = I (K + 4G/3); see doc/theory.md. The volumetric part adds
      // the eigenvalue max(J^2 U'', 0): J^2 U'' < 0 only for log squared
      // beyond J = e.
      const double mu_bar = 2. / 3. * W1 * I1_bar;
      const double longitudinal_modulus =
        std::max(J2_d2U, 0.) + 4. / 3. * std::abs(mu_bar) + tau_iso.norm() +
        4. * std::max(W2, 0.) * dev_b_bar.norm() * dev_b_bar.norm();
      response.dilatational_wave_speed =
        std::sqrt(std::max(longitudinal_modulus, 0.) / rho);

      if (compute_tangent)
        response.spatial_tangent =
          2. * mu_bar * Tensors::dev_P -
          2. / 3. *
            (outer_product(tau_iso, Tensors::I) +
             outer_product(Tensors::I, tau_iso)) +
          4. * W2 * outer_product(dev_b_bar, dev_b_bar) +
          (tau_vol + J2_d2U) * Tensors::IxI - 2. * tau_vol * Tensors::S;
    }



    template <int dim>
    void
    Yeoh<dim>::evaluate(const Tensor<2, dim> &F,
                        const ArrayView<const double> &,
                        const ArrayView<double> &,
                        const bool             compute_tangent,
                        MaterialResponse<dim> &response) const
    {
      if constexpr (dim == 3)
        evaluate_3d(F, compute_tangent, response);
      else
        {
          MaterialResponse<3> response_3d;
          evaluate_3d(internal::embed_in_3d(F), compute_tangent, response_3d);
          internal::restrict_from_3d(response_3d, compute_tangent, response);
        }
    }

    template class Yeoh<2>;
    template class Yeoh<3>;

    RUBBERDYN_REGISTER_MATERIAL(
      Yeoh,
      "Yeoh",
      "nearly incompressible Yeoh rubber, W = sum_i Ci0 (I1bar-3)^i + sum_k "
      "(1/d_k)(J-1)^(2k) (reference study eq. 3.16), or with (K/2)(ln J)^2 "
      "or (K/4)(J^2-1-2 ln J) as the volumetric term")
  } // namespace materials
} // namespace rubberdyn

