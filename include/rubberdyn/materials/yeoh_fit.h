#ifndef rubberdyn_materials_yeoh_fit_h
#define rubberdyn_materials_yeoh_fit_h

#include <array>
#include <string>
#include <vector>

namespace rubberdyn
{
  namespace materials
  {
    /**
     * Least-squares fit of the Yeoh constants $C_{10}, C_{20}, C_{30}$ to
     * homogeneous test data of an incompressible rubber. For the three
     * classical modes the nominal (first Piola-Kirchhoff) stress is
     * @f[
     *   P = 2\left(\lambda - \lambda^{-m}\right)
     *       \left[C_{10} + 2 C_{20} (I_1 - 3) + 3 C_{30} (I_1 - 3)^2\right]
     * @f]
     * with $m = 2$, $I_1 = \lambda^2 + 2/\lambda$ (uniaxial, eq. 4.8 of the
     * reference study), $m = 5$, $I_1 = 2\lambda^2 + \lambda^{-4}$
     * (equibiaxial) and $m = 3$, $I_1 = \lambda^2 + 1 + \lambda^{-2}$ (pure
     * shear). $P$ is linear in the constants, so the fit that minimises
     * $\sum (P_{fit} - P_{data})^2$ over all points of all modes is a
     * linear least-squares problem, solved here by Householder QR.
     */
    namespace yeoh_fit
    {
      /** The test modes. */
      enum class TestMode
      {
        uniaxial,
        equibiaxial,
        pure_shear
      };

      /** Name of a mode ("uniaxial", "equibiaxial", "pure_shear"). */
      std::string
      mode_name(const TestMode mode);

      /** Mode from its name; throws InputError naming @p context. */
      TestMode
      mode_from_name(const std::string &name, const std::string &context);

      /** One test: stretches and nominal stresses (GPa). */
      struct DataSet
      {
        TestMode            mode;
        std::string         source;
        std::vector<double> stretch;
        std::vector<double> nominal_stress;
      };

      /**
       * Read a CSV file with a header line naming the columns `stretch` and
       * `nominal_stress [UNIT]`, UNIT one of Pa, kPa, MPa, GPa; lines starting
       * with '#' are comments. Stresses are converted to GPa.
       *
       * @throws InputError naming the file and line on any problem.
       */
      DataSet
      read_csv(const std::string &filename, const TestMode mode);

      /** $I_1$ of the incompressible mode at stretch $\lambda$. */
      double
      first_invariant(const TestMode mode, const double stretch);

      /** $2(\lambda - \lambda^{-m})$ of the mode. */
      double
      kinematic_factor(const TestMode mode, const double stretch);

      /** Nominal stress of the incompressible Yeoh law (GPa). */
      double
      nominal_stress(const TestMode               mode,
                     const double                 stretch,
                     const std::array<double, 3> &C);

      /** Fit quality for one data set. */
      struct ModeError
      {
        /** Root-mean-square stress error (GPa). */
        double rms_error;
        /** Mean of |P_fit - P_data| / |P_data| over points with P_data != 0 (-). */
        double mean_relative_error;
        /** Largest |P_fit - P_data| / |P_data| (-). */
        double max_relative_error;
      };

      /** The result of a fit. */
      struct Result
      {
        /** C10, C20, C30 (GPa). */
        std::array<double, 3> C;
        /** One entry per data set, in input order. */
        std::vector<ModeError> errors;
      };

      /**
       * Fit to all points of all @p data sets at once.
       *
       * @throws std::runtime_error if the data cannot determine three
       *   constants (fewer than three distinct points).
       */
      Result
      fit(const std::vector<DataSet> &data);
    } // namespace yeoh_fit
  }   // namespace materials
} // namespace rubberdyn

#endif
