#include <rubberdyn/model/rigid_part_mass.h>

#include <utility>

namespace rubberdyn
{
  namespace model
  {
    RigidPartMass::RigidPartMass(VectorType lumped_mass)
      : lumped_mass(std::move(lumped_mass))
    {}



    std::string
    RigidPartMass::name() const
    {
      return "rigid-part mass";
    }



    ForceContribution::Accumulation
    RigidPartMass::accumulation() const
    {
      return Accumulation::external_owned;
    }



    void
    RigidPartMass::add_forces(const EvaluationPoint &,
                              VectorType &,
                              ContributionResults &)
    {}



    void
    RigidPartMass::add_lumped_mass(VectorType &mass,
                                   VectorType &physical_mass) const
    {
      // Owned entries (the ghosts are added by the owner, and the solver
      // compresses with add).
      for (unsigned int i = 0; i < lumped_mass.locally_owned_size(); ++i)
        {
          mass.local_element(i) += lumped_mass.local_element(i);
          physical_mass.local_element(i) += lumped_mass.local_element(i);
        }
    }
  } // namespace model
} // namespace rubberdyn
