#include <rubberdyn/base/binary_io.h>
#include <rubberdyn/elements/solid_hex_forces.h>

#include <sstream>

namespace rubberdyn
{
  namespace elements
  {
    SolidHexForces::SolidHexForces(SolidHexElements &         elements,
                                   const std::vector<double> &density_scaling)
      : elements(elements)
      , scaling(density_scaling)
    {}



    std::string
    SolidHexForces::name() const
    {
      return "elements";
    }



    model::ForceContribution::Accumulation
    SolidHexForces::accumulation() const
    {
      return Accumulation::internal_ghosted;
    }



    void
    SolidHexForces::add_forces(const model::EvaluationPoint &point,
                               VectorType &                  f,
                               model::ContributionResults &  results)
    {
      // compute_forces() overwrites every member of step_result, which is
      // kept across steps so that its per-group vector is allocated once.
      elements.compute_forces(point.displacement, point.velocity, scaling, f,
                              step_result);
      results.internal_energy += step_result.internal_energy;
      // The element groups are the model's parts, in the same order.
      for (unsigned int g = 0; g < step_result.internal_energy_by_group.size() &&
                               g < results.internal_energy_by_group.size();
           ++g)
        {
          results.internal_energy_by_group[g] +=
            step_result.internal_energy_by_group[g];
          results.bulk_viscosity_power_by_group[g] +=
            step_result.bulk_viscosity_power_by_group[g];
        }
      results.bulk_viscosity_power += step_result.bulk_viscosity_power;
      results.element_time_step =
        std::min(results.element_time_step, step_result.min_time_step);
      results.element_undamped_time_step =
        std::min(results.element_undamped_time_step,
                 step_result.min_undamped_time_step);
      results.element_damping_factor =
        std::min(results.element_damping_factor,
                 step_result.min_damping_factor);
      if (step_result.failure.failed && !results.failure.failed)
        {
          std::ostringstream message;
          message << "element " << step_result.failure.cell_id << " at ("
                  << step_result.failure.position
                  << ") mm failed: " << step_result.failure.message;
          results.failure.failed  = true;
          results.failure.message = message.str();
        }
    }



    bool
    SolidHexForces::in_assembled_step_estimate() const
    {
      // compute_forces() keeps the new history and its step_result until
      // the next call: a probe before the step's own evaluation leaves
      // nothing behind.
      return true;
    }



    void
    SolidHexForces::accept_step()
    {
      elements.accept_history();
    }



    void
    SolidHexForces::add_lumped_mass(VectorType &mass,
                                    VectorType &physical_mass) const
    {
      elements.add_lumped_mass(mass, scaling);
      elements.add_lumped_mass(physical_mass,
                               std::vector<double>(scaling.size(), 1.));
    }



    void
    SolidHexForces::save(std::ostream &out) const
    {
      const std::vector<double> &history = elements.history();
      binary_io::write_doubles(out, history.data(), history.size());
    }



    void
    SolidHexForces::load(std::istream &in)
    {
      std::vector<double> &history = elements.history();
      binary_io::read_doubles(in, history.data(), history.size(),
                              "material history");
    }
  } // namespace elements
} // namespace rubberdyn
