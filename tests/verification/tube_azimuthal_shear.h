// The exact torque-rotation curve of a bonded incompressible Yeoh tube in
// azimuthal (circular) shear: a reference solution for the tests of the
// solvers, derived in doc/theory.md, section "Exact solution: azimuthal shear
// of a bonded tube".
//
// It lives in tests/ and not in the library: it is a proof, not physics the
// solvers use, and keeping it out of include/rubberdyn/ keeps it from ever
// being confused with (or fed by) the code it checks. It is header-only and
// needs nothing but the standard library, so that any test (a .cc in any
// tests/<system>/ folder, or a benchmark) includes it with
// #include "../verification/tube_azimuthal_shear.h".
#ifndef rubberdyn_tests_verification_tube_azimuthal_shear_h
#define rubberdyn_tests_verification_tube_azimuthal_shear_h

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace verification
{
  /**
   * Azimuthal shear of a bonded tube of incompressible isotropic material
   * with a strain energy W(I1) (Rivlin's universal deformation; Ogden,
   * Non-Linear Elastic Deformations (1984), chapter 5): the inner surface
   * r = a is held, the outer surface r = b is turned by the angle
   * @f$\varphi_b@f$ about the axis, nothing moves axially. The material
   * points move on circles, @f$r = R,\ \theta = \Theta + \psi(R),\ z = Z@f$,
   * with the local shear @f$\gamma(r) = r\psi'(r)@f$ and
   * @f$I_1 = 3 + \gamma^2@f$. The shear stress is the simple-shear one,
   * @f[ \tau(\gamma) = \sigma_{r\theta} = 2 W_1(3 + \gamma^2)\,\gamma, @f]
   * and the balance of moments about the axis of the part of the tube
   * inside any radius r makes the torque
   * @f[ M = 2\pi r^2 L\, \tau(\gamma(r)) @f]
   * the same at every r. So for a torque M, @f$\gamma(r)@f$ solves
   * @f$\tau(\gamma) = M / (2\pi r^2 L)@f$ at each r, and the outer surface
   * has turned by
   * @f[ \varphi_b(M) = \int_a^b \frac{\gamma(r)}{r}\,dr. @f]
   *
   * The material is Yeoh's,
   * @f$W_1 = C_{10} + 2C_{20}(I_1 - 3) + 3C_{30}(I_1 - 3)^2@f$. The
   * equation for @f$\gamma@f$ has one root as long as @f$\tau@f$ increases,
   * @f$\tau'(\gamma) = 2(C_{10} + 6C_{20}\gamma^2 + 15C_{30}\gamma^4) > 0@f$:
   * for all @f$\gamma@f$ if @f$C_{10} > 0@f$, @f$C_{30} \ge 0@f$ and either
   * @f$C_{20} \ge 0@f$ or @f$3C_{20}^2 < 5C_{10}C_{30}@f$; otherwise up to
   * largest_monotone_shear(), beyond which the tube has no unique state and
   * the functions here throw.
   *
   * Units: any consistent set; in rubberdyn's, lengths in mm, the constants
   * in GPa, the torque in kN mm (J), angles in rad.
   *
   * Numerics: @f$\gamma(r)@f$ by Newton's method safeguarded by bisection
   * on a bracket; the integral by composite 10-point Gauss-Legendre
   * quadrature in @f$\ln r@f$ (the integrand @f$\gamma@f$ is analytic in
   * @f$\ln r@f$: 16 panels are exact to rounding for b/a = 2, where 64
   * panels change @f$\varphi_b@f$ by less than 1e-15, and 3 points instead
   * of 10 change it by only 2e-13; for much thicker tubes raise n_panels);
   * @f$M(\varphi_b)@f$ by the same safeguarded Newton method on
   * @f$\varphi_b(M)@f$, whose derivative
   * @f$d\varphi_b/dM = \int_a^b [2\pi r^3 L\,\tau'(\gamma(r))]^{-1}\,dr@f$
   * comes from the same quadrature.
   */
  class TubeAzimuthalShear
  {
  public:
    /** A state of the tube. */
    struct State
    {
      /** Torque about the axis (kN mm). */
      double moment;
      /** Rotation of the outer surface (rad). */
      double rotation;
      /** Shear at the inner radius, the largest in the tube. */
      double inner_shear;
      /** Shear at the outer radius. */
      double outer_shear;
    };

    /**
     * The tube a <= r <= b (mm) of length L (mm) and the Yeoh constants
     * (GPa). Throws std::invalid_argument unless 0 < a < b, L > 0 and
     * C10 > 0.
     */
    TubeAzimuthalShear(const double inner_radius,
                       const double outer_radius,
                       const double length,
                       const double c10,
                       const double c20,
                       const double c30)
      : a(inner_radius)
      , b(outer_radius)
      , length(length)
      , c10(c10)
      , c20(c20)
      , c30(c30)
      , gamma_monotone(compute_largest_monotone_shear())
    {
      if (!(a > 0. && b > a && length > 0. && c10 > 0.))
        throw std::invalid_argument(
          "TubeAzimuthalShear: needs 0 < a < b, L > 0 and C10 > 0");
      // The Gauss-Legendre rule on [-1, 1]: each node by Newton's method
      // on the Legendre polynomial from the Chebyshev estimate.
      for (unsigned int i = 0; i < n_points; ++i)
        {
          double x          = std::cos(M_PI * (i + 0.75) / (n_points + 0.5));
          double derivative = 0.;
          for (unsigned int iteration = 0; iteration < 100; ++iteration)
            {
              double p0 = 1., p1 = x;
              for (unsigned int k = 2; k <= n_points; ++k)
                {
                  const double p2 =
                    ((2. * k - 1.) * x * p1 - (k - 1.) * p0) / k;
                  p0 = p1;
                  p1 = p2;
                }
              derivative      = n_points * (x * p1 - p0) / (x * x - 1.);
              const double dx = p1 / derivative;
              x -= dx;
              if (std::abs(dx) < 1e-16)
                break;
            }
          points[i]  = x;
          weights[i] = 2. / ((1. - x * x) * derivative * derivative);
        }
    }

    /** @f$W_1 = \partial W/\partial I_1@f$ at @f$I_1 = 3 + \gamma^2@f$ (GPa).
     */
    double
    w1(const double gamma) const
    {
      const double x = gamma * gamma;
      return c10 + 2. * c20 * x + 3. * c30 * x * x;
    }

    /** @f$\tau(\gamma) = 2W_1\gamma@f$ (GPa), the simple-shear stress. */
    double
    shear_stress(const double gamma) const
    {
      return 2. * w1(gamma) * gamma;
    }

    /**
     * @f$\tau'(\gamma) = 2(C_{10} + 6C_{20}\gamma^2 + 15C_{30}\gamma^4)@f$
     * (GPa), the tangent shear modulus.
     */
    double
    shear_stress_slope(const double gamma) const
    {
      const double x = gamma * gamma;
      return 2. * (c10 + 6. * c20 * x + 15. * c30 * x * x);
    }

    /**
     * The shear up to which @f$\tau(\gamma)@f$ increases: the smallest
     * positive root of @f$C_{10} + 6C_{20}x + 15C_{30}x^2@f$ in
     * @f$x = \gamma^2@f$, or infinity if it has none (see the class
     * documentation for the condition on the constants).
     */
    double
    largest_monotone_shear() const
    {
      return gamma_monotone;
    }

    /**
     * The shear @f$\gamma(r)@f$ at the radius @p r (mm) under the torque
     * @p moment (kN mm, >= 0): the root of
     * @f$\tau(\gamma) = M/(2\pi r^2 L)@f$ in
     * [0, largest_monotone_shear()). Throws std::domain_error if the stress
     * is beyond the largest the material can carry monotonically.
     */
    double
    shear_at(const double moment, const double r) const
    {
      const double target = moment / (2. * M_PI * r * r * length);
      if (!(target >= 0.))
        throw std::invalid_argument("TubeAzimuthalShear: negative torque");
      if (target == 0.)
        return 0.;
      // A bracket [low, high] with tau(low) <= target <= tau(high).
      double low = 0., high;
      if (std::isfinite(gamma_monotone))
        {
          high = gamma_monotone;
          if (!(target < shear_stress(high)))
            throw std::domain_error(
              "TubeAzimuthalShear: the shear stress " + std::to_string(target) +
              " exceeds the largest the Yeoh law carries monotonically, " +
              std::to_string(shear_stress(high)) +
              " at gamma = " + std::to_string(high));
        }
      else
        {
          high = std::max(1., target / c10);
          while (shear_stress(high) < target)
            high *= 2.;
        }
      // Newton from the small-strain estimate, bisection whenever a step
      // leaves the bracket; the bracket shrinks on every iteration.
      double gamma = std::min(target / (2. * c10), 0.5 * (low + high));
      for (unsigned int iteration = 0; iteration < 200; ++iteration)
        {
          const double residual = shear_stress(gamma) - target;
          if (residual == 0.)
            return gamma;
          (residual < 0. ? low : high) = gamma;
          double next = gamma - residual / shear_stress_slope(gamma);
          if (!(next > low && next < high))
            next = 0.5 * (low + high);
          if (std::abs(next - gamma) <= 4. * eps * gamma ||
              high - low <= 4. * eps * high)
            return next;
          gamma = next;
        }
      throw std::runtime_error("TubeAzimuthalShear: no convergence for gamma");
    }

    /**
     * The rotation @f$\varphi_b(M) = \int_a^b \gamma(r)/r\,dr@f$ (rad) of
     * the outer surface under the torque @p moment (kN mm).
     */
    double
    rotation(const double moment) const
    {
      // The quadrature samples only interior radii: solve at r = a first,
      // where the stress is largest, so that a torque beyond what the
      // material carries is refused rather than integrated.
      shear_at(moment, a);
      return integrate_over_log_radius(
        [&](const double r) { return shear_at(moment, r); });
    }

    /**
     * @f$d\varphi_b/dM = \int_a^b [2\pi r^3 L\,\tau'(\gamma(r))]^{-1}\,dr@f$
     * (rad per kN mm): @f$\partial\gamma/\partial M = 1/(2\pi r^2 L\tau')@f$
     * from the equation for @f$\gamma@f$.
     */
    double
    rotation_derivative(const double moment) const
    {
      return integrate_over_log_radius([&](const double r) {
        return 1. / (2. * M_PI * r * r * length *
                     shear_stress_slope(shear_at(moment, r)));
      });
    }

    /** The state under the torque @p moment (kN mm). */
    State
    at_moment(const double moment) const
    {
      return {moment,
              rotation(moment),
              shear_at(moment, a),
              shear_at(moment, b)};
    }

    /**
     * The state with the shear @p inner_shear at the inner radius: the
     * torque @f$M = 2\pi a^2 L\tau(\gamma_a)@f$, no inversion needed.
     */
    State
    at_inner_shear(const double inner_shear) const
    {
      return at_moment(2. * M_PI * a * a * length * shear_stress(inner_shear));
    }

    /**
     * The state at the rotation @p rotation_b (rad, >= 0) of the outer
     * surface: the torque @f$M(\varphi_b)@f$ by inverting
     * @f$\varphi_b(M)@f$ (increasing in M), Newton's method safeguarded by
     * bisection, to a relative 1e-14 in M.
     */
    State
    at_rotation(const double rotation_b) const
    {
      if (!(rotation_b >= 0.))
        throw std::invalid_argument("TubeAzimuthalShear: negative rotation");
      if (rotation_b == 0.)
        return {0., 0., 0., 0.};
      // The bracket: [0, the torque that takes gamma(a) to the end of the
      // monotone range], or doubled from the small-strain estimate.
      double low = 0., high;
      if (std::isfinite(gamma_monotone))
        {
          // Just below the end, where the shear is still solvable.
          high = 2. * M_PI * a * a * length * shear_stress(gamma_monotone) *
                 (1. - 1e-12);
          if (!(rotation(high) > rotation_b))
            throw std::domain_error(
              "TubeAzimuthalShear: the rotation " + std::to_string(rotation_b) +
              " needs a shear beyond the monotone range of the Yeoh law");
        }
      else
        {
          high = small_strain_stiffness() * rotation_b;
          while (rotation(high) < rotation_b)
            high *= 2.;
        }
      double moment =
        std::min(small_strain_stiffness() * rotation_b, 0.5 * (low + high));
      for (unsigned int iteration = 0; iteration < 200; ++iteration)
        {
          const double residual = rotation(moment) - rotation_b;
          if (residual == 0.)
            return at_moment(moment);
          (residual < 0. ? low : high) = moment;
          double next = moment - residual / rotation_derivative(moment);
          if (!(next > low && next < high))
            next = 0.5 * (low + high);
          if (std::abs(next - moment) <= 1e-14 * moment ||
              high - low <= 1e-14 * high)
            return at_moment(next);
          moment = next;
        }
      throw std::runtime_error("TubeAzimuthalShear: no convergence for M");
    }

    /** The torque @f$M(\varphi_b)@f$ (kN mm) at the rotation (rad). */
    double
    moment(const double rotation_b) const
    {
      return at_rotation(rotation_b).moment;
    }

    /**
     * The small-strain torsional stiffness
     * @f$M/\varphi_b = 4\pi G L a^2 b^2/(b^2 - a^2)@f$ (kN mm/rad) with
     * @f$G = 2C_{10}@f$, the limit of @f$M(\varphi_b)/\varphi_b@f$ as
     * @f$\varphi_b \to 0@f$.
     */
    double
    small_strain_stiffness() const
    {
      return 4. * M_PI * 2. * c10 * length * a * a * b * b / (b * b - a * a);
    }

    /**
     * @f$\sigma_{rr}(r) - \sigma_{rr}(a) = \int_a^r 2W_1\gamma^2/s\,ds@f$
     * (GPa) under the torque @p moment: the radial balance
     * @f$d\sigma_{rr}/dr = (\sigma_{\theta\theta} - \sigma_{rr})/r@f$ with
     * @f$\sigma_{\theta\theta} - \sigma_{rr} = 2W_1\gamma^2@f$ (the
     * Poynting effect). The constant @f$\sigma_{rr}(a)@f$ is not fixed by
     * the incompressible problem with the displacement prescribed on the
     * whole boundary normal; see doc/theory.md.
     */
    double
    radial_stress_rise(const double moment, const double r) const
    {
      if (r <= a)
        return 0.;
      const TubeAzimuthalShear part(a, r, length, c10, c20, c30);
      return part.integrate_over_log_radius([&](const double s) {
        const double gamma = shear_at(moment, s);
        return 2. * w1(gamma) * gamma * gamma;
      });
    }

    /**
     * The axial force (kN, negative: compressive) that the two ends must
     * carry to keep the tube at its length when the displacement is
     * prescribed on the whole boundary normal (inner and outer surfaces
     * bonded, ends held axially and free in their plane), in the limit of
     * a nearly incompressible material:
     * @f[ N = -\frac{4\pi}{3}\int_a^b W_1\gamma^2\, r\,dr . @f]
     * The incompressible problem leaves a constant pressure free; a
     * compressible law with bulk modulus K fixes it by
     * @f$\int_V (J - 1)\,dV = 0@f$ (the boundary keeps the volume), which
     * makes the mean stress @f$\sigma_m \approx K(J - 1)@f$ average to zero,
     * up to a relative O(G/K). With
     * @f$\sigma_m = \sigma_{rr} + \tfrac23 W_1\gamma^2@f$ and
     * @f$\sigma_{zz} = \sigma_{rr}@f$ this gives N (doc/theory.md).
     */
    double
    end_force(const double moment) const
    {
      shear_at(moment, a);
      return -4. * M_PI / 3. * integrate_over_log_radius([&](const double r) {
        const double gamma = shear_at(moment, r);
        return w1(gamma) * gamma * gamma * r * r;
      });
    }

  private:
    static constexpr unsigned int n_points = 10;
    static constexpr unsigned int n_panels = 16;
    static constexpr double       eps = std::numeric_limits<double>::epsilon();

    const double                 a, b, length, c10, c20, c30;
    const double                 gamma_monotone;
    std::array<double, n_points> points, weights;

    /** @f$\int_a^b f(r)/r\,dr = \int_{\ln a}^{\ln b} f(e^s)\,ds@f$. */
    template <typename Function>
    double
    integrate_over_log_radius(const Function &f) const
    {
      const double s0 = std::log(a), h = (std::log(b) - s0) / n_panels;
      double       sum = 0.;
      for (unsigned int panel = 0; panel < n_panels; ++panel)
        for (unsigned int i = 0; i < n_points; ++i)
          sum +=
            weights[i] * f(std::exp(s0 + h * (panel + 0.5 * (1. + points[i]))));
      return 0.5 * h * sum;
    }

    double
    compute_largest_monotone_shear() const
    {
      // Positive roots of q(x) = 15 C30 x^2 + 6 C20 x + C10, q(0) > 0.
      const double infinity = std::numeric_limits<double>::infinity();
      if (c30 == 0.)
        return c20 >= 0. ? infinity : std::sqrt(-c10 / (6. * c20));
      const double discriminant = 36. * c20 * c20 - 60. * c10 * c30;
      if (discriminant < 0.)
        return infinity; // only possible for C30 > 0: q > 0 everywhere
      // The root (-6 C20 - sqrt(disc)) / (30 C30) is the smaller positive
      // one if C30 > 0 and C20 < 0, and the only positive one if C30 < 0.
      const double root = (-6. * c20 - std::sqrt(discriminant)) / (30. * c30);
      if (c30 > 0. && c20 >= 0.)
        return infinity; // both roots negative
      return std::sqrt(root);
    }
  };
} // namespace verification

#endif
