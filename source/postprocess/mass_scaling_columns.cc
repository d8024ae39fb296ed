#include <rubberdyn/postprocess/mass_scaling_columns.h>
#include <rubberdyn/postprocess/run_summary.h>

#include <ostream>

namespace rubberdyn
{
  namespace postprocess
  {
    MassScalingColumns::MassScalingColumns(
      const time_integration::SelectiveMassScaling  &scaling,
      std::vector<std::string>                       part_names,
      std::vector<time_integration::PartMassScaling> parts)
      : scaling(scaling)
      , part_names(std::move(part_names))
      , parts(std::move(parts))
    {}



    std::string
    MassScalingColumns::name() const
    {
      return "selective mass scaling";
    }



    std::vector<std::string>
    MassScalingColumns::history_columns() const
    {
      return {"mass_scaling_iterations"};
    }



    void
    MassScalingColumns::history_values(const SimulationView &,
                                       std::vector<double> &values)
    {
      values.push_back(scaling.last_iterations());
    }



    void
    MassScalingColumns::summary(const SimulationView &,
                                std::vector<SummaryEntry> &entries)
    {
      std::string by_part = "{";
      for (unsigned int p = 0; p < parts.size(); ++p)
        {
          const time_integration::PartMassScaling &part = parts[p];
          if (part.target_time_step <= 0.)
            continue;
          by_part += std::string(by_part.size() > 1 ? ", " : "") +
                     json_string(part_names[p]) +
                     ": {\"target_time_step\": " +
                     json_number(part.target_time_step) +
                     ", \"elements\": " + std::to_string(part.n_elements) +
                     ", \"scaled_elements\": " + std::to_string(part.n_scaled) +
                     ", \"next_to_rigid_part\": " +
                     std::to_string(part.n_next_to_rigid) +
                     ", \"added_mass\": " + json_number(part.added_mass) +
                     ", \"mass\": " + json_number(part.mass) + "}";
        }
      const double solves = double(scaling.n_solves());
      entries.emplace_back(
        "selective_mass_scaling",
        "{\"parts\": " + by_part + "}, \"solves\": " +
          std::to_string(scaling.n_solves()) + ", \"mean_iterations\": " +
          json_number(solves > 0. ? scaling.total_iterations() / solves : 0.) +
          ", \"largest_iterations\": " +
          std::to_string(scaling.largest_iterations()) + "}");
    }



    void
    MassScalingColumns::final_log(std::ostream &log) const
    {
      const double solves = double(scaling.n_solves());
      log << "Selective mass scaling: " << scaling.n_solves()
          << " solves, mean "
          << (solves > 0. ? scaling.total_iterations() / solves : 0.)
          << " iterations, largest " << scaling.largest_iterations()
          << std::endl;
    }
  } // namespace postprocess
} // namespace rubberdyn
