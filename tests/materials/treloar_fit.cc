// The Yeoh fit to Treloar's (1944) data, recomputed independently.
//
// The library fits C10, C20, C30 by Householder QR on column-scaled data.
// Here the same least-squares problem is solved a second way: the normal
// equations (A^T A) c = A^T b, assembled from the closed-form incompressible
// nominal stresses written out below (not the library's functions) and
// solved by Cramer's rule in long double. Both must agree to 1e-7 relative
// (the normal equations square the condition number, ~1e5 after scaling,
// so 1e-16 * 1e10 ~ 1e-6 in double; long double gives 1e-19 * 1e10).
// Then the optimality condition: the gradient of the sum of squared
// residuals, A^T (A c - b), vanishes relative to |A^T b|.
#include <rubberdyn/materials/yeoh_fit.h>

#include <array>
#include <vector>

#include "../tests.h"

using namespace rubberdyn::materials::yeoh_fit;
using testing::check;
using testing::out;
using testing::sci;

// Incompressible nominal stress = f(l) (C10 + 2 C20 x + 3 C30 x^2).
std::array<long double, 3>
row(const TestMode mode, const long double l)
{
  long double f = 0, I1 = 0;
  if (mode == TestMode::uniaxial)
    {
      f  = 2 * (l - 1 / (l * l));
      I1 = l * l + 2 / l;
    }
  else if (mode == TestMode::equibiaxial)
    {
      f  = 2 * (l - 1 / (l * l * l * l * l));
      I1 = 2 * l * l + 1 / (l * l * l * l);
    }
  else
    {
      f  = 2 * (l - 1 / (l * l * l));
      I1 = l * l + 1 + 1 / (l * l);
    }
  const long double x = I1 - 3;
  return {{f, 2 * f * x, 3 * f * x * x}};
}

long double
det3(const std::array<std::array<long double, 3>, 3> &M)
{
  return M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) -
         M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0]) +
         M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0]);
}

int
main()
{
  const std::string data_dir = std::string(SOURCE_DIR) + "/../../data/treloar/";
  const std::vector<DataSet> data = {
    read_csv(data_dir + "uniaxial.csv", TestMode::uniaxial),
    read_csv(data_dir + "equibiaxial.csv", TestMode::equibiaxial),
    read_csv(data_dir + "pure_shear.csv", TestMode::pure_shear)};
  const Result result = fit(data);

  // Normal equations.
  std::array<std::array<long double, 3>, 3> N{};
  std::array<long double, 3>                rhs{};
  for (const DataSet &set : data)
    for (unsigned int i = 0; i < set.stretch.size(); ++i)
      {
        const auto a = row(set.mode, set.stretch[i]);
        for (unsigned int j = 0; j < 3; ++j)
          {
            rhs[j] += a[j] * set.nominal_stress[i];
            for (unsigned int k = 0; k < 3; ++k)
              N[j][k] += a[j] * a[k];
          }
      }
  const long double          D = det3(N);
  std::array<long double, 3> C_independent;
  for (unsigned int j = 0; j < 3; ++j)
    {
      auto M = N;
      for (unsigned int k = 0; k < 3; ++k)
        M[k][j] = rhs[k];
      C_independent[j] = det3(M) / D;
    }

  out() << std::setprecision(5);
  const char *names[3] = {"C10", "C20", "C30"};
  double      max_difference = 0.;
  for (unsigned int j = 0; j < 3; ++j)
    {
      const double difference =
        std::abs(result.C[j] - double(C_independent[j])) /
        std::abs(double(C_independent[j]));
      max_difference = std::max(max_difference, difference);
      out() << names[j] << " = " << result.C[j] * 1e3
            << " MPa (independent: " << double(C_independent[j]) * 1e3
            << " MPa, relative difference " << sci(difference) << ")"
            << std::endl;
    }
  check(max_difference < 1e-7, "QR and normal equations agree to 1e-7");

  // Gradient of the sum of squares at the library's constants.
  std::array<long double, 3> gradient{};
  for (const DataSet &set : data)
    for (unsigned int i = 0; i < set.stretch.size(); ++i)
      {
        const auto  a = row(set.mode, set.stretch[i]);
        long double r = -set.nominal_stress[i];
        for (unsigned int k = 0; k < 3; ++k)
          r += a[k] * result.C[k];
        for (unsigned int j = 0; j < 3; ++j)
          gradient[j] += a[j] * r;
      }
  double relative_gradient = 0.;
  for (unsigned int j = 0; j < 3; ++j)
    relative_gradient = std::max(
      relative_gradient, double(std::abs(gradient[j]) / std::abs(rhs[j])));
  out() << "gradient of the squared residual at the fit, relative: "
        << sci(relative_gradient) << std::endl;
  check(relative_gradient < 1e-9, "the fit is a stationary point");

  const char *mode_names[3] = {"uniaxial", "equibiaxial", "pure shear"};
  for (unsigned int k = 0; k < 3; ++k)
    out() << mode_names[k] << ": " << data[k].stretch.size()
          << " points, rms error " << result.errors[k].rms_error * 1e3
          << " MPa, mean relative error "
          << 100. * result.errors[k].mean_relative_error << " %"
          << std::endl;
}
