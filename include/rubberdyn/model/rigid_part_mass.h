#ifndef rubberdyn_model_rigid_part_mass_h
#define rubberdyn_model_rigid_part_mass_h

#include <rubberdyn/base/vector.h>
#include <rubberdyn/model/force_contribution.h>

#include <string>

namespace rubberdyn
{
  namespace model
  {
    /**
     * The lumped mass of the rigid parts' cells (their elements compute
     * nothing, so they give no mass of their own): the row sums rho N_a of
     * simulation::setup::part_masses(). It adds no force: a rigid part's
     * forces are its body's (time_integration::ExplicitSolver).
     */
    class RigidPartMass : public ForceContribution
    {
    public:
      /** @param lumped_mass The rigid parts' nodal masses (kg), ghosted. */
      explicit RigidPartMass(VectorType lumped_mass);

      std::string
      name() const override;

      Accumulation
      accumulation() const override;

      /** Nothing: a rigid part's forces are its body's. */
      void
      add_forces(const EvaluationPoint &,
                 VectorType &,
                 ContributionResults &) override;

      void
      add_lumped_mass(VectorType &mass,
                      VectorType &physical_mass) const override;

    private:
      VectorType lumped_mass;
    };
  } // namespace model
} // namespace rubberdyn

#endif
