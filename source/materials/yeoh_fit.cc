#include <deal.II/base/utilities.h>

#include <rubberdyn/base/exceptions.h>
#include <rubberdyn/materials/yeoh_fit.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace rubberdyn
{
  namespace materials
  {
    namespace yeoh_fit
    {
      std::string
      mode_name(const TestMode mode)
      {
        switch (mode)
          {
            case TestMode::uniaxial:
              return "uniaxial";
            case TestMode::equibiaxial:
              return "equibiaxial";
            case TestMode::pure_shear:
              return "pure_shear";
          }
        return "";
      }



      TestMode
      mode_from_name(const std::string &name, const std::string &context)
      {
        for (const TestMode mode : {TestMode::uniaxial,
                                    TestMode::equibiaxial,
                                    TestMode::pure_shear})
          if (name == mode_name(mode))
            return mode;
        throw InputError(context,
                         "unknown test mode '" + name +
                           "'; valid: uniaxial, equibiaxial, pure_shear");
      }



      DataSet
      read_csv(const std::string &filename, const TestMode mode)
      {
        std::ifstream file(filename);
        if (!file)
          throw InputError(filename, "cannot open the data file");

        DataSet data{mode, filename, {}, {}};
        int     stretch_column = -1, stress_column = -1;
        double  unit_to_GPa    = 0.;
        std::string  line;
        unsigned int line_number = 0;
        while (std::getline(file, line))
          {
            ++line_number;
            const std::string trimmed = dealii::Utilities::trim(line);
            if (trimmed.empty() || trimmed[0] == '#')
              continue;
            const std::vector<std::string> fields =
              dealii::Utilities::split_string_list(trimmed, ',');
            const std::string where =
              filename + ":" + std::to_string(line_number);

            if (stretch_column < 0)
              {
                // The header line.
                for (unsigned int c = 0; c < fields.size(); ++c)
                  if (fields[c] == "stretch")
                    stretch_column = c;
                  else if (fields[c].rfind("nominal_stress", 0) == 0)
                    {
                      stress_column = c;
                      const std::vector<std::pair<std::string, double>>
                        units = {{"[Pa]", 1e-9},
                                 {"[kPa]", 1e-6},
                                 {"[MPa]", 1e-3},
                                 {"[GPa]", 1.}};
                      for (const auto &unit : units)
                        if (fields[c].find(unit.first) != std::string::npos)
                          unit_to_GPa = unit.second;
                    }
                if (stretch_column < 0 || stress_column < 0 ||
                    unit_to_GPa == 0.)
                  throw InputError(
                    where,
                    "the header must name the columns 'stretch' and "
                    "'nominal_stress [UNIT]' with UNIT one of Pa, kPa, MPa, "
                    "GPa, but reads '" +
                      trimmed + "'");
                continue;
              }

            if (fields.size() <=
                static_cast<unsigned int>(
                  std::max(stretch_column, stress_column)))
              throw InputError(where, "too few columns in '" + trimmed + "'");
            double values[2];
            const int columns[2] = {stretch_column, stress_column};
            for (unsigned int k = 0; k < 2; ++k)
              {
                char *end = nullptr;
                values[k] = std::strtod(fields[columns[k]].c_str(), &end);
                if (fields[columns[k]].empty() || *end != '\0' ||
                    !std::isfinite(values[k]))
                  throw InputError(where,
                                   "'" + fields[columns[k]] +
                                     "' is not a number");
              }
            if (!(values[0] > 0.))
              throw InputError(where, "stretch must be positive");
            data.stretch.push_back(values[0]);
            data.nominal_stress.push_back(values[1] * unit_to_GPa);
          }
        if (stretch_column < 0)
          throw InputError(filename, "no header line and no data");
        if (data.stretch.empty())
          throw InputError(filename, "no data points");
        return data;
      }



      double
      first_invariant(const TestMode mode, const double l)
      {
        switch (mode)
          {
            case TestMode::uniaxial:
              return l * l + 2. / l;
            case TestMode::equibiaxial:
              return 2. * l * l + std::pow(l, -4);
            case TestMode::pure_shear:
              return l * l + 1. + 1. / (l * l);
          }
        return 0.;
      }



      double
      kinematic_factor(const TestMode mode, const double l)
      {
        const int m = (mode == TestMode::uniaxial ?
                         2 :
                         (mode == TestMode::equibiaxial ? 5 : 3));
        return 2. * (l - std::pow(l, -m));
      }



      double
      nominal_stress(const TestMode               mode,
                     const double                 l,
                     const std::array<double, 3> &C)
      {
        const double x = first_invariant(mode, l) - 3.;
        return kinematic_factor(mode, l) *
               (C[0] + 2. * C[1] * x + 3. * C[2] * x * x);
      }



      Result
      fit(const std::vector<DataSet> &data)
      {
        // Design matrix A (n x 3) and right-hand side b.
        std::vector<std::array<double, 3>> A;
        std::vector<double>                b;
        for (const DataSet &set : data)
          for (unsigned int i = 0; i < set.stretch.size(); ++i)
            {
              const double f = kinematic_factor(set.mode, set.stretch[i]);
              const double x = first_invariant(set.mode, set.stretch[i]) - 3.;
              A.push_back({{f, 2. * f * x, 3. * f * x * x}});
              b.push_back(set.nominal_stress[i]);
            }
        const unsigned int n = A.size();
        if (n < 3)
          throw std::runtime_error(
            "Yeoh fit: at least three data points are needed");

        // Column scaling keeps the QR well balanced (x^2 reaches 1e3).
        std::array<double, 3> scale{{0., 0., 0.}};
        for (const auto &row : A)
          for (unsigned int j = 0; j < 3; ++j)
            scale[j] = std::max(scale[j], std::abs(row[j]));
        for (unsigned int j = 0; j < 3; ++j)
          {
            if (scale[j] == 0.)
              throw std::runtime_error("Yeoh fit: the data determine no "
                                       "constants (all stretches are 1)");
            for (auto &row : A)
              row[j] /= scale[j];
          }

        // Householder QR: apply reflections to A and b.
        for (unsigned int j = 0; j < 3; ++j)
          {
            double norm = 0.;
            for (unsigned int i = j; i < n; ++i)
              norm += A[i][j] * A[i][j];
            norm = std::sqrt(norm);
            if (norm == 0.)
              throw std::runtime_error(
                "Yeoh fit: the data cannot determine three constants");
            const double        alpha = (A[j][j] > 0. ? -norm : norm);
            std::vector<double> v(n, 0.);
            v[j] = A[j][j] - alpha;
            for (unsigned int i = j + 1; i < n; ++i)
              v[i] = A[i][j];
            double v_norm2 = 0.;
            for (unsigned int i = j; i < n; ++i)
              v_norm2 += v[i] * v[i];
            if (v_norm2 == 0.)
              continue;
            for (unsigned int k = j; k < 3; ++k)
              {
                double dot = 0.;
                for (unsigned int i = j; i < n; ++i)
                  dot += v[i] * A[i][k];
                for (unsigned int i = j; i < n; ++i)
                  A[i][k] -= 2. * dot / v_norm2 * v[i];
              }
            double dot = 0.;
            for (unsigned int i = j; i < n; ++i)
              dot += v[i] * b[i];
            for (unsigned int i = j; i < n; ++i)
              b[i] -= 2. * dot / v_norm2 * v[i];
          }
        // Back substitution R c = Q^T b.
        Result result;
        for (int j = 2; j >= 0; --j)
          {
            double sum = b[j];
            for (unsigned int k = j + 1; k < 3; ++k)
              sum -= A[j][k] * result.C[k];
            if (std::abs(A[j][j]) < 1e-14)
              throw std::runtime_error(
                "Yeoh fit: the data cannot determine three constants "
                "(rank-deficient least-squares problem)");
            result.C[j] = sum / A[j][j];
          }
        for (unsigned int j = 0; j < 3; ++j)
          result.C[j] /= scale[j];

        for (const DataSet &set : data)
          {
            ModeError    error{0., 0., 0.};
            unsigned int n_nonzero = 0;
            for (unsigned int i = 0; i < set.stretch.size(); ++i)
              {
                const double difference =
                  nominal_stress(set.mode, set.stretch[i], result.C) -
                  set.nominal_stress[i];
                error.rms_error += difference * difference;
                if (set.nominal_stress[i] != 0.)
                  {
                    const double relative =
                      std::abs(difference / set.nominal_stress[i]);
                    error.mean_relative_error += relative;
                    ++n_nonzero;
                    error.max_relative_error =
                      std::max(error.max_relative_error, relative);
                  }
              }
            error.rms_error = std::sqrt(error.rms_error / set.stretch.size());
            if (n_nonzero > 0)
              error.mean_relative_error /= n_nonzero;
            result.errors.push_back(error);
          }
        return result;
      }
    } // namespace yeoh_fit
  }   // namespace materials
} // namespace rubberdyn
