// Yeoh rubber under homogeneous deformations against closed forms.
//
// (1) The compressible law against its own closed form in principal
//     stretches: with J = l1 l2 l3, bbar_i = J^(-2/3) l_i^2, I1bar = sum
//     bbar_i,
//       tau_i = J U'(J) + 2 W'(I1bar) (bbar_i - I1bar/3)
//     (push-forward of eq. 3.17 of the reference study), evaluated here
//     without tensors. The lateral stretch is found by bisection on this
//     closed form, independently of the library's Newton solver. The
//     deformation is also applied after a rigid rotation Q (F -> Q F), and
//     Q^T tau Q must give the same principal stresses (objectivity).
//     Tolerance: 1e-12 relative to the largest stress, i.e. round-off.
//     Done for each volumetric function, with its own Kirchhoff pressure
//     J U'(J) = K J (J-1) (polynomial, one term), K ln J (log squared),
//     (K/2)(J^2 - 1) (Simo-Taylor), and its U in pure dilatation.
// (2) The nominal stress against the incompressible formulas (eq. 4.8 and
//     its equibiaxial and pure-shear analogues): the compressible law with
//     bulk modulus K differs by O(G/K). Checked by computing the difference
//     for nu = 0.499 and nu = 0.4999 (G/K smaller by a factor 10.0): the
//     difference must shrink by the same factor (within 10 %), which shows
//     it is the O(G/K) term and nothing else. (The 10 % allow for the
//     next-order term, which grows with the stress level: the ratio is 9.2
//     at stretch 3, where the stress reaches 2 % of K.)
#include <deal.II/base/parameter_handler.h>

#include <rubberdyn/materials/homogeneous_deformation.h>
#include <rubberdyn/materials/yeoh.h>

#include <array>
#include <vector>

#include "../tests.h"

using namespace dealii;
using namespace rubberdyn::materials;
using testing::check;
using testing::out;
using testing::sci;

// Chapter-4 rubber of the reference study (GPa).
const double C10 = 0.55e-3, C20 = -0.05e-3, C30 = 0.015e-3;

double
bulk_modulus(const double nu)
{
  const double G = 2. * C10;
  return 2. * G * (1. + nu) / (3. * (1. - 2. * nu));
}

// The volumetric function of part (1).
VolumetricFunction function = VolumetricFunction::polynomial;

// U(J) and J U'(J) of the volumetric function, written out here.
double
U_of(const double J, const double K)
{
  if (function == VolumetricFunction::polynomial)
    return 0.5 * K * (J - 1.) * (J - 1.);
  if (function == VolumetricFunction::log_squared)
    return 0.5 * K * std::log(J) * std::log(J);
  return 0.25 * K * (J * J - 1. - 2. * std::log(J));
}

double
pressure_of(const double J, const double K)
{
  if (function == VolumetricFunction::polynomial)
    return K * J * (J - 1.);
  if (function == VolumetricFunction::log_squared)
    return K * std::log(J);
  return 0.5 * K * (J * J - 1.);
}

// Principal Kirchhoff stresses of the compressible law with U = U_of().
std::array<double, 3>
closed_form_tau(const std::array<double, 3> &l, const double K)
{
  const double J  = l[0] * l[1] * l[2];
  const double a  = std::pow(J, -2. / 3.);
  const double I1 = a * (l[0] * l[0] + l[1] * l[1] + l[2] * l[2]);
  const double x  = I1 - 3.;
  const double W1 = C10 + 2. * C20 * x + 3. * C30 * x * x;
  std::array<double, 3> tau;
  for (unsigned int i = 0; i < 3; ++i)
    tau[i] = pressure_of(J, K) + 2. * W1 * (a * l[i] * l[i] - I1 / 3.);
  return tau;
}

// W'(I1) for the incompressible formulas.
double
W1_of(const double I1)
{
  const double x = I1 - 3.;
  return C10 + 2. * C20 * x + 3. * C30 * x * x;
}

enum Mode
{
  uniaxial,
  equibiaxial,
  pure_shear
};

std::array<double, 3>
stretches(const Mode mode, const double l, const double mu)
{
  if (mode == uniaxial)
    return {{l, mu, mu}};
  if (mode == equibiaxial)
    return {{l, l, mu}};
  return {{l, 1., mu}};
}

// Lateral stretch with a stress-free lateral face (tau_3 = 0), by bisection.
double
lateral_stretch(const Mode mode, const double l, const double K)
{
  double lo = 0.05, hi = 20.;
  for (unsigned int i = 0; i < 200; ++i)
    {
      const double mid = 0.5 * (lo + hi);
      if (closed_form_tau(stretches(mode, l, mid), K)[2] > 0.)
        hi = mid;
      else
        lo = mid;
    }
  return 0.5 * (lo + hi);
}

double
incompressible_nominal_stress(const Mode mode, const double l)
{
  if (mode == uniaxial)
    return 2. * (l - 1. / (l * l)) * W1_of(l * l + 2. / l);
  if (mode == equibiaxial)
    return 2. * (l - std::pow(l, -5)) * W1_of(2. * l * l + std::pow(l, -4));
  return 2. * (l - std::pow(l, -3)) * W1_of(l * l + 1. + 1. / (l * l));
}

Tensor<2, 3>
rotation()
{
  // Rotation by 0.7 rad about the axis (1, 2, 3)/|(1, 2, 3)| (Rodrigues).
  Tensor<1, 3> axis;
  axis[0] = 1.;
  axis[1] = 2.;
  axis[2] = 3.;
  axis /= axis.norm();
  const double theta = 0.7;
  Tensor<2, 3> K, I;
  for (unsigned int i = 0; i < 3; ++i)
    I[i][i] = 1.;
  K[0][1] = -axis[2];
  K[0][2] = axis[1];
  K[1][0] = axis[2];
  K[1][2] = -axis[0];
  K[2][0] = -axis[1];
  K[2][1] = axis[0];
  return I + std::sin(theta) * K + (1. - std::cos(theta)) * K * K;
}

// Largest deviation of the library's stresses from the closed form, for F =
// diag(l) and for Q diag(l), relative to the largest principal stress.
double
closed_form_error(const Yeoh<3> &material, const std::array<double, 3> &l,
                  const double K)
{
  const std::array<double, 3> tau_exact = closed_form_tau(l, K);
  const double scale = std::max({std::abs(tau_exact[0]), std::abs(tau_exact[1]),
                                 std::abs(tau_exact[2]), 1e-3 * C10});
  Tensor<2, 3> F;
  for (unsigned int i = 0; i < 3; ++i)
    F[i][i] = l[i];
  const Tensor<2, 3> Q = rotation();
  double             error = 0.;
  for (const bool rotated : {false, true})
    {
      MaterialResponse<3> response;
      material.evaluate(rotated ? Tensor<2, 3>(Q * F) : F, {}, {}, false,
                        response);
      // Back to the principal frame: Q^T tau Q.
      const Tensor<2, 3> R =
        (rotated ? Q : Tensor<2, 3>(unit_symmetric_tensor<3>()));
      const Tensor<2, 3> tau =
        transpose(R) * Tensor<2, 3>(response.kirchhoff_stress) * R;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          error = std::max(error,
                           std::abs(tau[i][j] - (i == j ? tau_exact[i] : 0.)) /
                             scale);
    }
  return error;
}

int
main()
{
  out() << std::setprecision(6);

  // F = I: no stress, no energy.
  {
    const Yeoh<3>       material(C10, C20, C30, {{2. / bulk_modulus(0.499),
                                                  0., 0.}}, 1.1e-6);
    MaterialResponse<3> response;
    material.evaluate(unit_symmetric_tensor<3>(), {}, {}, true, response);
    out() << "F = I: |tau| = " << response.kirchhoff_stress.norm()
          << ", W = " << response.strain_energy_density << std::endl;
    check(response.kirchhoff_stress.norm() == 0. &&
            response.strain_energy_density == 0.,
          "zero stress and energy at F = I");
  }

  const std::vector<std::pair<Mode, std::string>> modes = {
    {uniaxial, "uniaxial"}, {equibiaxial, "equibiaxial"},
    {pure_shear, "pure shear"}};
  // Uniaxial down to stretch 0.3 (70 % compression, the deep drop test);
  // equibiaxial and pure shear from 0.6 to 2 (at equibiaxial stretch 3 the
  // stress reaches 10 % of K and the O(G/K) expansion no longer holds).
  const auto loads = [](const Mode mode) {
    return (mode == uniaxial ? std::vector<double>{0.3, 0.5, 0.8, 1.2, 2., 3.} :
                               std::vector<double>{0.6, 0.8, 1.2, 2.});
  };

  double max_error = 0.;
  for (const VolumetricFunction f : {VolumetricFunction::polynomial,
                                     VolumetricFunction::log_squared,
                                     VolumetricFunction::simo_taylor})
    {
      function = f;
      out() << "\n(1) compressible closed form, nu = 0.499"
            << (f == VolumetricFunction::polynomial ?
                  "" :
                  ", volumetric function " + volumetric_function_name(f))
            << " (max relative error)" << std::endl;
      const double  K = bulk_modulus(0.499);
      const Yeoh<3> material(C10, C20, C30, {{2. / K, 0., 0.}}, 1.1e-6, f);
      for (const auto &mode : modes)
        for (const double l : loads(mode.first))
          {
            const double mu = lateral_stretch(mode.first, l, K);
            const double error =
              closed_form_error(material, stretches(mode.first, l, mu), K);
            max_error = std::max(max_error, error);
            out() << mode.second << " stretch " << l << ": error " << sci(error)
                  << std::endl;
          }
      // Simple shear F = I + g e1 x e2: J = 1, I1 = 3 + g^2, and
      // tau = 2 W' dev(b) with b = F F^T; in particular tau_12 = 2 W' g.
      for (const double g : {0.2, 1., 2.})
        {
          Tensor<2, 3> F = unit_symmetric_tensor<3>();
          F[0][1]        = g;
          MaterialResponse<3> response;
          material.evaluate(F, {}, {}, false, response);
          const double W1  = W1_of(3. + g * g);
          const double t12 = 2. * W1 * g;
          const double t11 = 2. * W1 * (1. + g * g - (3. + g * g) / 3.);
          const double t22 = 2. * W1 * (1. - (3. + g * g) / 3.);
          const double error =
            std::max({std::abs(response.kirchhoff_stress[0][1] - t12),
                      std::abs(response.kirchhoff_stress[0][0] - t11),
                      std::abs(response.kirchhoff_stress[1][1] - t22),
                      std::abs(response.kirchhoff_stress[2][2] - t22)}) /
            std::abs(t11);
          max_error = std::max(max_error, error);
          out() << "simple shear g = " << g << ": error " << sci(error)
                << std::endl;
        }
      // Pure dilatation F = a I: tau = J U'(J) I, W = U(J).
      for (const double a : {0.98, 0.995, 1.01})
        {
          MaterialResponse<3> response;
          material.evaluate(a * Tensor<2, 3>(unit_symmetric_tensor<3>()),
                            {},
                            {},
                            false,
                            response);
          const double J     = a * a * a;
          const double p     = pressure_of(J, K);
          double       error = 0.;
          for (unsigned int i = 0; i < 3; ++i)
            for (unsigned int j = 0; j < 3; ++j)
              error = std::max(error,
                               std::abs(response.kirchhoff_stress[i][j] -
                                        (i == j ? p : 0.)) /
                                 std::abs(p));
          const double W_exact = U_of(J, K);
          error                = std::max(error,
                           std::abs(response.strain_energy_density - W_exact) /
                             W_exact);
          max_error            = std::max(max_error, error);
          out() << "dilatation a = " << a << ": error " << sci(error)
                << std::endl;
        }
    }
  check(max_error < 1e-12, "closed forms to round-off (1e-12)");
  out() << "largest relative error < 1e-12: yes" << std::endl;

  out() << "\n(2) nominal stress vs the incompressible formulas" << std::endl;
  out() << "mode, stretch, P_incompressible (MPa), rel. difference at nu = "
           "0.499 and 0.4999, ratio"
        << std::endl;
  // Nominal stress P_1 = tau_1 / l_1 (F diagonal).
  const auto nominal = [](const Mode mode, const double l, const double nu) {
    const double  K = bulk_modulus(nu);
    const Yeoh<3> material(C10, C20, C30, {{2. / K, 0., 0.}}, 1.1e-6);
    // The library's own Newton solver for the free lateral stretch.
    const homogeneous_deformation::Mode library_mode =
      (mode == uniaxial ?
         homogeneous_deformation::Mode::uniaxial_stress :
         (mode == equibiaxial ?
            homogeneous_deformation::Mode::equibiaxial_stress :
            homogeneous_deformation::Mode::pure_shear));
    MaterialResponse<3> response;
    homogeneous_deformation::solve(
      material, library_mode, l,
      homogeneous_deformation::incompressible_lateral_stretch(library_mode, l),
      {}, {}, response);
    return response.kirchhoff_stress[0][0] / l;
  };
  for (const auto &mode : modes)
    for (const double l : loads(mode.first))
      {
        const double P_inc = incompressible_nominal_stress(mode.first, l);
        const double d1 = std::abs(nominal(mode.first, l, 0.499) - P_inc) /
                          std::abs(P_inc);
        const double d2 = std::abs(nominal(mode.first, l, 0.4999) - P_inc) /
                          std::abs(P_inc);
        // G/K(0.499) / G/K(0.4999) = 9.9967: the O(G/K) ratio.
        const double GK_ratio = (bulk_modulus(0.4999) / bulk_modulus(0.499));
        out() << mode.second << ", " << l << ", " << P_inc * 1e3 << ", "
              << sci(d1) << ", " << sci(d2) << ", "
              << std::setprecision(3) << d1 / d2 << std::setprecision(6)
              << std::endl;
        check(std::abs(d1 / d2 / GK_ratio - 1.) < 0.1,
              "difference to the incompressible law is O(G/K)");
      }
  out() << "all differences scale with G/K: yes" << std::endl;
}
