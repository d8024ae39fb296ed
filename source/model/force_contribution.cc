#include <rubberdyn/model/force_contribution.h>

#include <algorithm>

namespace rubberdyn
{
  namespace model
  {
    void
    ContributionResults::reset(const unsigned int n_groups,
                               const unsigned int n_bodies)
    {
      internal_energy = 0.;
      internal_energy_by_group.assign(n_groups, 0.);
      contact_energy       = 0.;
      bulk_viscosity_power = 0.;
      bulk_viscosity_power_by_group.assign(n_groups, 0.);
      friction_dissipation = 0.;
      external_work        = 0.;
      element_time_step    = std::numeric_limits<double>::max();
      element_undamped_time_step = std::numeric_limits<double>::max();
      element_damping_factor     = 1.;
      contact_time_step    = std::numeric_limits<double>::max();
      force_on_body.assign(n_bodies, Tensor<1, 3>());
      moment_on_body.assign(n_bodies, Tensor<1, 3>());
      failure = EvaluationFailure();
    }
  } // namespace model
} // namespace rubberdyn
