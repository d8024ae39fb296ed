#include <deal.II/base/utilities.h>

#include <rubberdyn/base/exceptions.h>
#include <rubberdyn/base/parameter_tools.h>
#include <rubberdyn/materials/hardening_curve.h>

#include <algorithm>
#include <sstream>

namespace rubberdyn
{
  namespace materials
  {
    using parameter_tools::format_number;

    HardeningCurve::HardeningCurve(const double               yield_stress,
                                   const std::vector<double> &plastic_strains,
                                   const std::vector<double> &stresses,
                                   const std::string &        path)
    {
      parameter_tools::require_positive(yield_stress, path + "/Yield stress");
      if (plastic_strains.size() != stresses.size())
        throw InputError(path + "/Hardening curve",
                         "needs as many stresses as plastic strains");
      alpha_points.push_back(0.);
      k_points.push_back(yield_stress);
      for (unsigned int i = 0; i < plastic_strains.size(); ++i)
        {
          if (!(plastic_strains[i] > alpha_points.back()))
            throw InputError(
              path + "/Hardening curve",
              "plastic strains must be positive and strictly increasing, "
              "but point " +
                std::to_string(i + 1) + " has plastic strain " +
                format_number(plastic_strains[i]) + " after " +
                format_number(alpha_points.back()));
          if (!(stresses[i] >= k_points.back()))
            throw InputError(
              path + "/Hardening curve",
              "stresses must not decrease (no softening), starting from "
              "the yield stress, but point " +
                std::to_string(i + 1) + " has stress " +
                format_number(stresses[i]) + " GPa after " +
                format_number(k_points.back()) + " GPa");
          for (const double value : {plastic_strains[i], stresses[i]})
            if (!parameter_tools::is_usable_number(value))
              throw InputError(path + "/Hardening curve",
                               "point " + std::to_string(i + 1) + " holds " +
                                 format_number(value) +
                                 ", which is not a finite normal number");
          alpha_points.push_back(plastic_strains[i]);
          k_points.push_back(stresses[i]);
          // Close points give a steep slope: it must stay finite.
          parameter_tools::require_usable((k_points.back() - k_points[i]) /
                                            (alpha_points.back() -
                                             alpha_points[i]),
                                          path + "/Hardening curve",
                                          "the slope between points " +
                                            std::to_string(i) + " and " +
                                            std::to_string(i + 1),
                                          "GPa",
                                          parameter_tools::Sign::non_negative);
        }
    }



    HardeningCurve
    HardeningCurve::parse(const double       yield_stress,
                          const std::string &table,
                          const std::string &path)
    {
      std::vector<double> strains, stresses;
      for (const std::string &pair :
           dealii::Utilities::split_string_list(table, ','))
        {
          const std::vector<std::string> parts =
            dealii::Utilities::split_string_list(pair, ':');
          char *end_1 = nullptr, *end_2 = nullptr;
          if (parts.size() == 2)
            {
              strains.push_back(std::strtod(parts[0].c_str(), &end_1));
              stresses.push_back(std::strtod(parts[1].c_str(), &end_2));
            }
          if (parts.size() != 2 || parts[0].empty() || parts[1].empty() ||
              *end_1 != '\0' || *end_2 != '\0')
            throw InputError(path + "/Hardening curve",
                             "cannot read '" + pair +
                               "': write each point as plastic strain:stress "
                               "(GPa), points separated by commas");
        }
      return HardeningCurve(yield_stress, strains, stresses, path);
    }



    unsigned int
    HardeningCurve::segment(const double alpha) const
    {
      unsigned int i = 0;
      while (i + 1 < alpha_points.size() && alpha >= alpha_points[i + 1])
        ++i;
      return i;
    }



    double
    HardeningCurve::slope(const double alpha) const
    {
      if (alpha_points.size() == 1)
        return 0.;
      // Past the table the last segment continues.
      const unsigned int i = std::min<unsigned int>(segment(alpha),
                                                    alpha_points.size() - 2);
      return (k_points[i + 1] - k_points[i]) /
             (alpha_points[i + 1] - alpha_points[i]);
    }



    double
    HardeningCurve::yield_stress(const double alpha) const
    {
      const unsigned int i = segment(alpha);
      return k_points[i] + slope(alpha) * (alpha - alpha_points[i]);
    }



    double
    HardeningCurve::solve_return(const double q_trial,
                                 const double mu_bar,
                                 const double alpha_old) const
    {
      // The residual is strictly decreasing in the increment (k' >= 0), so
      // walking the segments from alpha_old finds the single root.
      for (unsigned int i = segment(alpha_old);; ++i)
        {
          const bool   last = (i + 1 >= alpha_points.size());
          const double H =
            last ? slope(alpha_points[i]) :
                   (k_points[i + 1] - k_points[i]) /
                     (alpha_points[i + 1] - alpha_points[i]);
          const double delta_alpha =
            (q_trial - k_points[i] - H * (alpha_old - alpha_points[i])) /
            (3. * mu_bar + H);
          if (last || alpha_old + delta_alpha <= alpha_points[i + 1])
            return std::max(delta_alpha, 0.);
        }
    }



    double
    HardeningCurve::largest_slope() const
    {
      double H = 0.;
      for (unsigned int i = 0; i + 1 < alpha_points.size(); ++i)
        H = std::max(H,
                     (k_points[i + 1] - k_points[i]) /
                       (alpha_points[i + 1] - alpha_points[i]));
      return H;
    }



    std::string
    HardeningCurve::to_string() const
    {
      std::ostringstream s;
      for (unsigned int i = 0; i < alpha_points.size(); ++i)
        s << (i ? ", " : "") << format_number(alpha_points[i]) << ":"
          << format_number(k_points[i]);
      return s.str();
    }
  } // namespace materials
} // namespace rubberdyn
