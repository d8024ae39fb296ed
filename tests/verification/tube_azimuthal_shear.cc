// verification::TubeAzimuthalShear (tests/verification/tube_azimuthal_shear.h),
// the exact torque-rotation curve of a bonded incompressible Yeoh tube in
// azimuthal shear (doc/theory.md, "Exact solution: azimuthal shear of a
// bonded tube"), against what it must reduce to:
//
// 1. Neo-Hooke (C20 = C30 = 0): gamma(r) = M / (4 pi C10 r^2 L) and the
//    closed form phi_b = M / (8 pi C10 L) (1/a^2 - 1/b^2), both ways
//    (phi(M) and M(phi)), and the radial stress rise
//    sigma_rr(r) - sigma_rr(a) = C10 k^2 / 2 (1/a^4 - 1/r^4),
//    k = M / (4 pi C10 L), and the ends' axial force
//    N = -(2 pi / 3) C10 k^2 (1/a^2 - 1/b^2). Tolerance 1e-12 relative: the
//    quadrature of the analytic integrand and the root solves are exact to
//    rounding (1e-15).
// 2. The small-strain limit M / phi -> 4 pi G L a^2 b^2 / (b^2 - a^2),
//    G = 2 C10 (Timoshenko's torsion of a hollow cylinder; the reference
//    notes, validation-benchmarks.md section 7): to 1e-10 relative at
//    phi = 1e-6 rad, and the deviation shrinks as phi^2 (the next term of
//    the series in gamma^2), checked by the ratio 100 +- 1 between phi = 1e-3
//    and 1e-4.
// 3. Yeoh (the reference study's constants) against an independent
//    computation written here: the substitution r -> gamma
//    (tau = M / (2 pi r^2 L), dr / r = -d tau / (2 tau)) turns the integral
//    into phi_b = (gamma_a - gamma_b) / 2 + int_{gamma_b}^{gamma_a}
//    gamma^2 W1'(I1) / W1(I1) d gamma, with gamma_a, gamma_b found by pure
//    bisection and the integral by adaptive Simpson quadrature: another
//    formula, another root finder, another quadrature. Tolerance 1e-9
//    relative (both are exact to about 1e-14).
// 4. The tabulated values of /work/shared/references/validation-benchmarks.md
//    section 7 (Yeoh C10 = 0.18303, C20 = -1.418e-3, C30 = 3.935e-5 MPa,
//    a = 10, b = 25, L = 50 mm; torque in N mm), computed there by another
//    program: to their printed six decimals (half a unit: 5e-7 rad).
// 5. The monotone range: with C30 = 0 and C20 < 0 the shear stress peaks at
//    gamma* = sqrt(-C10 / (6 C20)); with 3 C20^2 > 5 C10 C30 at the smaller
//    root of C10 + 6 C20 x + 15 C30 x^2; beyond it the solution refuses.
// Then the curve M(phi) of the tube the quasi-static solver's test uses
// (a = 10, b = 20, L = 10 mm, the study's C10 = 0.00055, C20 = -5e-5,
// C30 = 1.5e-5 GPa) up to gamma(a) = 2, printed for doc/verification/reference_solutions.md.
#include "tube_azimuthal_shear.h"

#include <functional>
#include <sstream>

#include "../tests.h"

using testing::check;
using testing::out;
using testing::sci;
using verification::TubeAzimuthalShear;

namespace
{
  std::string
  fixed(const double value, const int digits)
  {
    std::ostringstream s;
    s << std::fixed << std::setprecision(digits) << value;
    return s.str();
  }

  std::string
  g6(const double value)
  {
    std::ostringstream s;
    s << std::setprecision(6) << value;
    return s.str();
  }

  double
  relative(const double value, const double reference)
  {
    return std::abs(value - reference) / std::abs(reference);
  }

  /** The Yeoh constants, for the independent computation. */
  struct Yeoh
  {
    double c10, c20, c30;
    double
    w1(const double gamma) const
    {
      const double x = gamma * gamma;
      return c10 + 2. * c20 * x + 3. * c30 * x * x;
    }
    /** dW1/dI1. */
    double
    w11(const double gamma) const
    {
      return 2. * c20 + 6. * c30 * gamma * gamma;
    }
    double
    tau(const double gamma) const
    {
      return 2. * w1(gamma) * gamma;
    }
  };

  /** tau(gamma) = target by bisection on [0, 64] (tau increasing). */
  double
  bisect_shear(const Yeoh &yeoh, const double target)
  {
    double low = 0., high = 64.;
    check(yeoh.tau(high) > target, "bisection bracket");
    while (high - low > 1e-17 * high)
      {
        const double middle = 0.5 * (low + high);
        if (middle <= low || middle >= high)
          break;
        (yeoh.tau(middle) < target ? low : high) = middle;
      }
    return 0.5 * (low + high);
  }

  /** Adaptive Simpson quadrature of f on [x0, x1] to @p tolerance. */
  double
  simpson(const std::function<double(double)> &f,
          const double                         x0,
          const double                         x1,
          const double                         f0,
          const double                         fm,
          const double                         f1,
          const double                         whole,
          const double                         tolerance,
          const unsigned int                   depth)
  {
    const double xm = 0.5 * (x0 + x1);
    const double fl = f(0.5 * (x0 + xm)), fr = f(0.5 * (xm + x1));
    const double left  = (xm - x0) / 6. * (f0 + 4. * fl + fm);
    const double right = (x1 - xm) / 6. * (fm + 4. * fr + f1);
    const double error = left + right - whole;
    if (depth == 0 || std::abs(error) <= 15. * tolerance)
      return left + right + error / 15.;
    return simpson(f, x0, xm, f0, fl, fm, left, 0.5 * tolerance, depth - 1) +
           simpson(f, xm, x1, fm, fr, f1, right, 0.5 * tolerance, depth - 1);
  }

  /**
   * phi_b(M) = (gamma_a - gamma_b) / 2 + int gamma^2 W1' / W1 d gamma,
   * the independent computation of item 3.
   */
  double
  independent_rotation(const Yeoh  &yeoh,
                       const double a,
                       const double b,
                       const double length,
                       const double moment)
  {
    const double gamma_a =
      bisect_shear(yeoh, moment / (2. * M_PI * a * a * length));
    const double gamma_b =
      bisect_shear(yeoh, moment / (2. * M_PI * b * b * length));
    const auto f = [&](const double g) {
      return g * g * yeoh.w11(g) / yeoh.w1(g);
    };
    const double fm = f(0.5 * (gamma_a + gamma_b));
    const double whole =
      (gamma_a - gamma_b) / 6. * (f(gamma_b) + 4. * fm + f(gamma_a));
    return 0.5 * (gamma_a - gamma_b) + simpson(f,
                                               gamma_b,
                                               gamma_a,
                                               f(gamma_b),
                                               fm,
                                               f(gamma_a),
                                               whole,
                                               1e-16,
                                               40);
  }
} // namespace

int
main()
{
  // The solver's tube: the reference study's Yeoh constants (GPa).
  const double a = 10., b = 20., length = 10.;
  const double c10 = 0.00055, c20 = -5e-5, c30 = 1.5e-5;

  // 1. Neo-Hooke closed forms.
  {
    const TubeAzimuthalShear tube(a, b, length, c10, 0., 0.);
    double                   largest = 0.;
    for (const double moment : {1e-6, 1e-3, 0.5, 3., 20.})
      {
        const double closed =
          moment / (8. * M_PI * c10 * length) * (1. / (a * a) - 1. / (b * b));
        largest = std::max(largest, relative(tube.rotation(moment), closed));
        // Inverse: M(phi) at the closed-form rotation.
        const auto state = tube.at_rotation(closed);
        largest          = std::max(largest, relative(state.moment, moment));
        const double k   = moment / (4. * M_PI * c10 * length);
        largest = std::max(largest, relative(state.inner_shear, k / (a * a)));
        largest = std::max(largest, relative(state.outer_shear, k / (b * b)));
        const double rise =
          0.5 * c10 * k * k * (1. / std::pow(a, 4) - 1. / std::pow(15., 4));
        largest =
          std::max(largest,
                   relative(tube.radial_stress_rise(moment, 15.), rise));
        const double force =
          -2. * M_PI / 3. * c10 * k * k * (1. / (a * a) - 1. / (b * b));
        largest = std::max(largest, relative(tube.end_force(moment), force));
      }
    out() << "neo-Hooke: phi_b(M), M(phi_b), gamma(a), gamma(b) and "
             "sigma_rr(15) - sigma_rr(a), N against the closed forms at "
             "M = 1e-6 ... 20 kN mm: largest relative error "
          << (largest < 1e-12 ? "< 1e-12" : sci(largest)) << std::endl;
    check(largest < 1e-12,
          "neo-Hooke closed form, relative error " + sci(largest));
  }

  // 2. Small-strain limit.
  {
    const TubeAzimuthalShear tube(a, b, length, c10, c20, c30);
    const double             stiffness = tube.small_strain_stiffness();
    out() << "small-strain stiffness 4 pi G L a^2 b^2 / (b^2 - a^2) = "
          << g6(stiffness) << " kN mm/rad" << std::endl;
    const auto deviation = [&](const double phi) {
      return tube.moment(phi) / phi / stiffness - 1.;
    };
    const double at_micro = std::abs(deviation(1e-6));
    out() << "  M / (K phi) - 1 at phi = 1e-6 rad: "
          << (at_micro < 1e-10 ? "|.| < 1e-10" : sci(at_micro)) << std::endl;
    check(at_micro < 1e-10,
          "small-strain limit at phi = 1e-6: " + sci(at_micro));
    const double d3 = deviation(1e-3), d4 = deviation(1e-4);
    out() << "  at phi = 1e-3: " << sci(d3) << ", at 1e-4: " << sci(d4)
          << ", ratio " << fixed(d3 / d4, 2) << " (phi^2: 100)" << std::endl;
    check(std::abs(d3 / d4 - 100.) < 1.,
          "the deviation from the small-strain "
          "limit is of order phi^2");
  }

  // 3. Yeoh against the independent computation.
  {
    const Yeoh               yeoh{c10, c20, c30};
    const TubeAzimuthalShear tube(a, b, length, c10, c20, c30);
    double                   largest = 0., largest_inverse = 0.;
    for (const double gamma_a : {0.01, 0.3, 1., 2., 3.5})
      {
        const double moment = 2. * M_PI * a * a * length * yeoh.tau(gamma_a);
        const double phi    = tube.rotation(moment);
        largest =
          std::max(largest,
                   relative(phi,
                            independent_rotation(yeoh, a, b, length, moment)));
        const auto state = tube.at_rotation(phi);
        largest_inverse  = std::max({largest_inverse,
                                     relative(state.moment, moment),
                                     relative(state.inner_shear, gamma_a)});
      }
    out() << "Yeoh, gamma(a) = 0.01 ... 3.5: phi_b(M) against the "
             "independent gamma-integral (bisection, adaptive Simpson): "
             "largest relative difference "
          << (largest < 1e-9 ? "< 1e-9" : sci(largest)) << std::endl;
    check(largest < 1e-9,
          "Yeoh against the independent computation: " + sci(largest));
    out() << "  M(phi_b(M)) and gamma(a) back: largest relative error "
          << (largest_inverse < 1e-12 ? "< 1e-12" : sci(largest_inverse))
          << std::endl;
    check(largest_inverse < 1e-12,
          "the inversion M(phi): " + sci(largest_inverse));
  }

  // 4. The tabulated values of the reference notes (MPa, N mm).
  {
    const TubeAzimuthalShear tube(10., 25., 50., 0.18303, -1.418e-3, 3.935e-5);
    out() << "reference notes' table (a = 10, b = 25, L = 50, bold Yeoh set):"
          << std::endl;
    const std::vector<std::pair<double, double>> table = {{1000., 0.036523},
                                                          {10000., 0.366908},
                                                          {20000., 0.743926},
                                                          {40000., 1.547246}};
    for (const auto &[torque, phi] : table)
      {
        const double computed = tube.rotation(torque);
        out() << "  T = " << torque << " N mm: phi = " << fixed(computed, 6)
              << " rad (table " << fixed(phi, 6) << ")" << std::endl;
        check(std::abs(computed - phi) <= 5e-7 * (1. + 1e-9),
              "the reference table at T = " + std::to_string(torque));
      }
  }

  // 5. The monotone range.
  {
    out() << "monotone range of tau(gamma) = 2 W1 gamma:" << std::endl;
    const TubeAzimuthalShear study(a, b, length, c10, c20, c30);
    out() << "  study constants: 3 C20^2 = " << g6(3. * c20 * c20)
          << " < 5 C10 C30 = " << g6(5. * c10 * c30)
          << ", monotone for all gamma: "
          << (std::isinf(study.largest_monotone_shear()) ? "yes" : "no")
          << std::endl;
    check(std::isinf(study.largest_monotone_shear()),
          "the study's Yeoh is monotone");

    for (const double c30_here : {0., 1e-6})
      {
        const TubeAzimuthalShear tube(a, b, length, c10, c20, c30_here);
        const double             peak = tube.largest_monotone_shear();
        const double             expected =
          c30_here == 0. ?
                        std::sqrt(-c10 / (6. * c20)) :
                        std::sqrt(
              (-6. * c20 - std::sqrt(36. * c20 * c20 - 60. * c10 * c30_here)) /
              (30. * c30_here));
        out() << "  C30 = " << c30_here
              << ": tau peaks at gamma* = " << fixed(peak, 6)
              << ", tau'(gamma*) / (2 C10) = "
              << sci(tube.shear_stress_slope(peak) / (2. * c10)) << std::endl;
        check(relative(peak, expected) < 1e-14, "gamma* closed form");
        check(std::abs(tube.shear_stress_slope(peak)) < 1e-12 * c10,
              "tau' vanishes at gamma*");
        check(tube.shear_stress_slope(0.999 * peak) > 0.,
              "tau' > 0 below gamma*");
        // A torque whose stress at r = a exceeds the peak is refused.
        const double too_large =
          2. * M_PI * a * a * length * tube.shear_stress(peak) * 1.001;
        bool refused = false;
        try
          {
            tube.rotation(too_large);
          }
        catch (const std::domain_error &)
          {
            refused = true;
          }
        out() << "    a torque 0.1 % beyond the peak at r = a: "
              << (refused ? "refused" : "accepted") << std::endl;
        check(refused, "a stress beyond the peak is refused");
      }
  }

  // The curve of the solver's test.
  {
    const TubeAzimuthalShear tube(a, b, length, c10, c20, c30);
    out() << std::endl
          << "Tube a = 10, b = 20, L = 10 mm, C10 = 0.00055, C20 = -5e-5, "
             "C30 = 1.5e-5 GPa (small-strain stiffness "
          << g6(tube.small_strain_stiffness()) << " kN mm/rad)" << std::endl
          << "gamma(a)  gamma(b)  phi_b (rad)  M (kN mm)  M / (K phi_b)  N (kN)"
          << std::endl;
    for (unsigned int i = 1; i <= 8; ++i)
      {
        const auto s = tube.at_inner_shear(0.25 * i);
        out() << fixed(s.inner_shear, 2) << "      " << fixed(s.outer_shear, 6)
              << "  " << fixed(s.rotation, 6) << "     " << fixed(s.moment, 6)
              << "   "
              << fixed(s.moment / (tube.small_strain_stiffness() * s.rotation),
                       6)
              << "       " << fixed(tube.end_force(s.moment), 6) << std::endl;
      }
    const double phi_end = tube.at_inner_shear(2.).rotation;
    out() << "phi_b (rad)  M (kN mm)  gamma(a)" << std::endl;
    for (unsigned int i = 1; 0.05 * i <= phi_end; ++i)
      {
        const auto s = tube.at_rotation(0.05 * i);
        out() << fixed(0.05 * i, 2) << "         " << fixed(s.moment, 6)
              << "   " << fixed(s.inner_shear, 6) << std::endl;
      }
  }
}
