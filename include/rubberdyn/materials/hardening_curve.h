#ifndef rubberdyn_materials_hardening_curve_h
#define rubberdyn_materials_hardening_curve_h

#include <string>
#include <vector>

namespace rubberdyn
{
  namespace materials
  {
    /**
     * Piecewise-linear isotropic hardening: the uniaxial yield stress $k$ as
     * a function of the equivalent plastic strain $\alpha$, through the
     * points $(0, \sigma_y), (\alpha_1, k_1), \dots, (\alpha_n, k_n)$. Beyond
     * the last point the last segment's slope continues (a single point is
     * perfectly plastic).
     */
    class HardeningCurve
    {
    public:
      /**
       * @param yield_stress Initial yield stress $\sigma_y$ (GPa), > 0.
       * @param plastic_strains $\alpha_1 < \dots < \alpha_n$, all > 0.
       * @param stresses $k_1 \le \dots \le k_n$, the first $\ge \sigma_y$
       *   (GPa): softening is rejected, it makes the local problem
       *   non-unique and the solution mesh-dependent.
       * @param path Parameter path for error messages.
       *
       * @throws InputError if the table is not increasing, or a point or a
       *   slope is not a finite normal number.
       */
      HardeningCurve(const double               yield_stress,
                     const std::vector<double> &plastic_strains,
                     const std::vector<double> &stresses,
                     const std::string &        path);

      /**
       * Parse a table written as "strain:stress, strain:stress, ..." (an
       * empty string gives perfect plasticity).
       */
      static HardeningCurve
      parse(const double       yield_stress,
            const std::string &table,
            const std::string &path);

      /** Yield stress $k(\alpha)$ (GPa). */
      double
      yield_stress(const double alpha) const;

      /**
       * Slope $k'(\alpha)$ (GPa) of the segment that holds $\alpha$ (the
       * right-hand slope at a table point).
       */
      double
      slope(const double alpha) const;

      /**
       * Solve the radial-return equation $q - 3\bar\mu\,\Delta\alpha -
       * k(\alpha_n + \Delta\alpha) = 0$ for $\Delta\alpha \ge 0$, exactly
       * (segment by segment), given the trial von Mises stress $q >
       * k(\alpha_n)$ and the shear modulus $\bar\mu > 0$.
       */
      double
      solve_return(const double q_trial,
                   const double mu_bar,
                   const double alpha_old) const;

      /** The steepest slope of the table (GPa), 0 if perfectly plastic. */
      double
      largest_slope() const;

      /** Describe the curve, e.g. for the log. */
      std::string
      to_string() const;

    private:
      /** Index of the segment holding alpha (segment i starts at point i). */
      unsigned int
      segment(const double alpha) const;

      /** Points, the first (0, yield stress). */
      std::vector<double> alpha_points, k_points;
    };
  } // namespace materials
} // namespace rubberdyn

#endif
