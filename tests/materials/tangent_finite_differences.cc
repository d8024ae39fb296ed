// Consistent tangents of all laws against central finite differences, and
// the stress of the hyperelastic laws against the energy.
//
// The spatial tangent c is defined by the directional derivative of the
// Kirchhoff stress (see MaterialResponse::spatial_tangent):
//   d tau = c : sym(l) + l tau + tau l^T,  l = dF F^{-1}.
// For each of the dim^2 unit directions dF = e_i x e_j this is compared
// with (tau(F + h dF) - tau(F - h dF)) / (2 h), h = 1e-6, at random
// deformation gradients F = Q U (Q a random rotation, U a random stretch
// with det U near 1: near-incompressibility). The error is the largest
// difference over all directions relative to the largest |d tau|; the
// central difference error is O(h^2) ~ 1e-12 and round-off ~ 1e-16/h =
// 1e-10 of the stress scale, so the required 1e-6 leaves no room for a wrong
// term (a missing geometric term gives errors of order 1).
//
// The hyperelastic laws (Yeoh with each volumetric function, Elastic) must
// also have the stress of their stored energy W: tau = P F^T with
// P_ij = dW/dF_ij by central differences of W (h = 1e-6; same error budget,
// relative to |tau|, and the same 1e-6; the energy's round-off divided
// by h makes it the looser check, measured up to 2e-9). Yeoh is checked with
// each volumetric function U(J) (polynomial, log squared, Simo-Taylor), near
// incompressibility and, at nu = 0.3, over J from 0.6 to 1.4, where the
// three differ most.
//
// J2 plasticity is checked on the elastic branch and on the plastic branch:
// the history is that of a point taken first to a plastic state; the
// perturbed states stay on the same branch (the trial stress is well
// inside/outside the yield surface, and away from the hardening table's
// kinks). Also checked: objectivity (tau(Q F) = Q tau(F) Q^T, same energy)
// to 1e-12, and zero stress and energy at F = I.
#include <rubberdyn/materials/elastic.h>
#include <rubberdyn/materials/finite_strain_j2.h>
#include <rubberdyn/materials/hardening_curve.h>
#include <rubberdyn/materials/j2_plasticity.h>
#include <rubberdyn/materials/yeoh.h>

#include <memory>
#include <random>
#include <vector>

#include "../tests.h"

using namespace dealii;
using namespace rubberdyn::materials;
using testing::check;
using testing::out;
using testing::sci;

std::mt19937 rng(20261123);

double
uniform(const double a, const double b)
{
  return std::uniform_real_distribution<double>(a, b)(rng);
}

template <int dim>
Tensor<2, dim>
random_rotation()
{
  // Product of rotations about the coordinate axes (one in 2D).
  Tensor<2, dim> Q;
  for (unsigned int i = 0; i < dim; ++i)
    Q[i][i] = 1.;
  for (unsigned int axis = 0; axis < (dim == 3 ? 3 : 1); ++axis)
    {
      const double   angle = uniform(-3., 3.);
      const unsigned i = (dim == 3 ? (axis + 1) % 3 : 0);
      const unsigned j = (dim == 3 ? (axis + 2) % 3 : 1);
      Tensor<2, dim> R;
      for (unsigned int k = 0; k < dim; ++k)
        R[k][k] = 1.;
      R[i][i] = R[j][j] = std::cos(angle);
      R[i][j]           = -std::sin(angle);
      R[j][i]           = std::sin(angle);
      Q                 = R * Q;
    }
  return Q;
}

// F = Q U with U symmetric, eigenvalues in [0.5, 1.8], det U scaled to
// within 2 % of 1 (rubber is nearly incompressible), or within
// @p J_spread times @p strain_scale of 1. With @p strain_scale small, U
// stays near I (metals).
template <int dim>
Tensor<2, dim>
random_deformation(const double strain_scale, const double J_spread = 0.02)
{
  Tensor<2, dim> A;
  for (unsigned int i = 0; i < dim; ++i)
    for (unsigned int j = 0; j < dim; ++j)
      A[i][j] = uniform(-1., 1.) * strain_scale;
  Tensor<2, dim> U = Tensor<2, dim>(symmetrize(A));
  for (unsigned int i = 0; i < dim; ++i)
    U[i][i] += 1.;
  const double J_target = 1. + uniform(-J_spread, J_spread) * strain_scale;
  U *= std::pow(J_target / determinant(U), 1. / dim);
  return random_rotation<dim>() * U;
}

template <int dim>
double
tangent_error(const MaterialModel<dim> &     material,
              const Tensor<2, dim> &         F,
              const std::vector<double> &    state_old,
              const bool                     print_sample)
{
  std::vector<double>   state_new(state_old.size());
  MaterialResponse<dim> response;
  material.evaluate(F, make_array_view(state_old),
                    make_array_view(state_new), true, response);

  const double h           = 1e-6;
  double       max_diff    = 0.;
  double       max_dtau    = 0.;
  for (unsigned int i = 0; i < dim; ++i)
    for (unsigned int j = 0; j < dim; ++j)
      {
        Tensor<2, dim> dF;
        dF[i][j] = 1.;
        const Tensor<2, dim> analytic =
          rubberdyn::materials::internal::kirchhoff_stress_derivative(response, F, dF);
        MaterialResponse<dim> plus, minus;
        material.evaluate(F + h * dF, make_array_view(state_old),
                          make_array_view(state_new), false, plus);
        material.evaluate(F - h * dF, make_array_view(state_old),
                          make_array_view(state_new), false, minus);
        const Tensor<2, dim> numeric =
          Tensor<2, dim>(plus.kirchhoff_stress - minus.kirchhoff_stress) /
          (2. * h);
        max_diff = std::max(max_diff, (analytic - numeric).norm());
        max_dtau = std::max(max_dtau, analytic.norm());
        if (print_sample && i == 0 && j == 0)
          {
            out() << "    d tau_00 / d F_00: analytic "
                  << std::setprecision(8) << analytic[0][0]
                  << ", finite difference " << numeric[0][0]
                  << std::setprecision(6) << std::endl;
          }
      }
  return max_diff / max_dtau;
}

// Largest difference between tau and P F^T with P = dW/dF by central
// differences of the stored energy, relative to |tau|.
template <int dim>
double
energy_stress_error(const MaterialModel<dim> &material, const Tensor<2, dim> &F)
{
  MaterialResponse<dim> response;
  material.evaluate(F, {}, {}, false, response);
  const double   h = 1e-6;
  Tensor<2, dim> P;
  for (unsigned int i = 0; i < dim; ++i)
    for (unsigned int j = 0; j < dim; ++j)
      {
        Tensor<2, dim> dF;
        dF[i][j] = 1.;
        MaterialResponse<dim> plus, minus;
        material.evaluate(F + h * dF, {}, {}, false, plus);
        material.evaluate(F - h * dF, {}, {}, false, minus);
        P[i][j] =
          (plus.strain_energy_density - minus.strain_energy_density) / (2. * h);
      }
  return (P * transpose(F) - Tensor<2, dim>(response.kirchhoff_stress)).norm() /
         response.kirchhoff_stress.norm();
}

template <int dim>
double
objectivity_error(const MaterialModel<dim> & material,
                  const Tensor<2, dim> &     F,
                  const std::vector<double> &state_old)
{
  std::vector<double>   state_new(state_old.size());
  MaterialResponse<dim> a, b;
  const Tensor<2, dim>  Q = random_rotation<dim>();
  material.evaluate(F, make_array_view(state_old),
                    make_array_view(state_new), false, a);
  material.evaluate(Q * F, make_array_view(state_old),
                    make_array_view(state_new), false, b);
  const Tensor<2, dim> rotated = Q * Tensor<2, dim>(a.kirchhoff_stress) *
                                 transpose(Q);
  return std::max((rotated - Tensor<2, dim>(b.kirchhoff_stress)).norm() /
                    a.kirchhoff_stress.norm(),
                  std::abs(a.strain_energy_density -
                           b.strain_energy_density) /
                    a.strain_energy_density);
}

// Take a J2 point to a plastic state by uniaxial-type straining and return
// its history.
template <int dim>
std::vector<double>
plastic_history(const J2Plasticity<dim> &material, const Tensor<2, dim> &F)
{
  std::vector<double> state_old(material.n_state_variables()),
    state_new(material.n_state_variables());
  material.initialize_state(make_array_view(state_old));
  MaterialResponse<dim> response;
  material.evaluate(F, make_array_view(state_old),
                    make_array_view(state_new), false, response);
  return state_new;
}

template <int dim>
double
run(std::ostream &log)
{
  double worst = 0.;
  log << "dim = " << dim << std::endl;

  struct Case
  {
    std::string                          name;
    std::shared_ptr<MaterialModel<dim>>  material;
    double                               strain_scale;
    double                               J_spread = 0.02;
  };
  // Chapter-4 rubber at nu = 0.49 and 0.499 (K = 1000 G), the study's
  // final bushing rubber (C30 = 0.95 MPa), a compressible rubber (nu = 0.3)
  // over a wide range of J, each with the three volumetric functions, and
  // an elastic steel.
  const auto yeoh = [](const double             C30,
                       const double             nu,
                       const VolumetricFunction function) {
    const double G = 1.1e-3;
    const double K = 2. * G * (1. + nu) / (3. * (1. - 2. * nu));
    return std::make_shared<Yeoh<dim>>(0.55e-3,
                                       -0.05e-3,
                                       C30,
                                       std::array<double, 3>{{2. / K, 0., 0.}},
                                       1.1e-6,
                                       function);
  };
  std::vector<Case> cases;
  for (const VolumetricFunction function : {VolumetricFunction::polynomial,
                                            VolumetricFunction::log_squared,
                                            VolumetricFunction::simo_taylor})
    {
      const std::string suffix = (function == VolumetricFunction::polynomial ?
                                    "" :
                                    ", " + volumetric_function_name(function));
      cases.push_back(
        {"Yeoh nu = 0.49" + suffix, yeoh(0.015e-3, 0.49, function), 0.4});
      cases.push_back(
        {"Yeoh nu = 0.499" + suffix, yeoh(0.015e-3, 0.499, function), 0.4});
      cases.push_back(
        {"Yeoh C30 = 0.95 MPa" + suffix, yeoh(0.95e-3, 0.499, function), 0.4});
      // J = 1 +- 0.4.
      cases.push_back({"Yeoh nu = 0.3, J in [0.6, 1.4]" + suffix,
                       yeoh(0.015e-3, 0.3, function),
                       0.4,
                       1.});
    }
  cases.push_back(
    {"Yeoh d1, d2, d3",
     std::make_shared<Yeoh<dim>>(0.55e-3,
                                 -0.05e-3,
                                 0.015e-3,
                                 std::array<double, 3>{{2e-3, 1e-2, 5e-2}},
                                 1.1e-6),
     0.4});
  cases.push_back(
    {"Elastic steel", std::make_shared<Elastic<dim>>(210., 0.3, 7.85e-6), 0.3});
  for (const Case &c : cases)
    {
      double tangent = 0., objectivity = 0., energy = 0.;
      for (unsigned int sample = 0; sample < 10; ++sample)
        {
          const Tensor<2, dim> F =
            random_deformation<dim>(c.strain_scale, c.J_spread);
          tangent = std::max(tangent, tangent_error(*c.material, F, {},
                                                    sample == 0));
          objectivity =
            std::max(objectivity, objectivity_error(*c.material, F, {}));
          energy = std::max(energy, energy_stress_error(*c.material, F));
        }
      MaterialResponse<dim> at_rest;
      Tensor<2, dim>        I;
      for (unsigned int i = 0; i < dim; ++i)
        I[i][i] = 1.;
      c.material->evaluate(I, {}, {}, false, at_rest);
      log << "  " << c.name << ": tangent error " << sci(tangent)
          << ", stress - dW/dF " << sci(energy) << ", objectivity error "
          << sci(objectivity)
          << ", |tau(I)| = " << at_rest.kirchhoff_stress.norm()
          << ", W(I) = " << at_rest.strain_energy_density << std::endl;
      check(tangent < 1e-6, c.name + ": tangent within 1e-6");
      check(energy < 1e-6, c.name + ": stress = dW/dF within 1e-6");
      check(objectivity < 1e-12, c.name + ": objective");
      check(at_rest.kirchhoff_stress.norm() == 0. &&
              std::abs(at_rest.strain_energy_density) < 1e-18,
            c.name + ": zero stress and energy at F = I");
      worst = std::max(worst, tangent);
    }

  // J2 plasticity of a 10.9 bolt steel: yield 0.94 GPa, hardening to 1.04
  // GPa at 8 % plastic strain, then on with the last slope.
  const J2Plasticity<dim> steel(
    210., 0.3, 7.85e-6,
    HardeningCurve(0.94, {0.02, 0.08}, {1.0, 1.04}, "test"));
  double elastic_branch = 0., plastic_branch = 0.;
  for (unsigned int sample = 0; sample < 10; ++sample)
    {
      // Pre-strain 3 % (plastic), then a further random increment: 1 %
      // more along the same stretch (plastic loading) or 0.3 % back
      // (elastic unloading).
      Tensor<2, dim> U0;
      for (unsigned int i = 0; i < dim; ++i)
        U0[i][i] = 1.;
      U0[0][0] = 1.03;
      U0[1][1] = 1. / std::sqrt(1.03);
      const Tensor<2, dim> Q = random_rotation<dim>();
      const std::vector<double> history = plastic_history(steel, Tensor<2, dim>(Q * U0));
      check(history[finite_strain_j2::equivalent_plastic_strain_index] > 0.,
            "pre-strain is plastic");

      Tensor<2, dim> U_load = U0, U_unload = U0;
      U_load[0][0] += 0.01 + uniform(0., 0.005);
      U_unload[0][0] -= 0.003 + uniform(0., 0.001);
      plastic_branch =
        std::max(plastic_branch,
                 tangent_error(steel, Tensor<2, dim>(Q * U_load), history,
                               sample == 0));
      elastic_branch =
        std::max(elastic_branch,
                 tangent_error(steel, Tensor<2, dim>(Q * U_unload), history,
                               false));
    }
  log << "  J2 plasticity, plastic loading: tangent error "
      << sci(plastic_branch) << std::endl;
  log << "  J2 plasticity, elastic unloading: tangent error "
      << sci(elastic_branch) << std::endl;
  check(plastic_branch < 1e-6, "J2 plastic tangent within 1e-6");
  check(elastic_branch < 1e-6, "J2 elastic tangent within 1e-6");
  return std::max({worst, plastic_branch, elastic_branch});
}

int
main()
{
  out() << std::setprecision(6);
  const double worst_3d = run<3>(out());
  const double worst_2d = run<2>(out());
  const double worst    = std::max(worst_3d, worst_2d);
  out() << "largest tangent error below 1e-6: " << (worst < 1e-6 ? "yes" : "no")
        << std::endl;
  std::cout << "largest tangent error: " << sci(worst) << std::endl;
}
