#ifndef rubberdyn_elements_solid_hex_forces_h
#define rubberdyn_elements_solid_hex_forces_h

#include <rubberdyn/elements/solid_hex_elements.h>
#include <rubberdyn/model/force_contribution.h>

#include <vector>

namespace rubberdyn
{
  namespace elements
  {
    /**
     * The solid elements as a force contribution of the time integrators:
     * internal forces, strain energy per element group, bulk viscosity,
     * stable element step, lumped mass (with the mass-scaling factors it
     * owns) and the material history in checkpoints.
     */
    class SolidHexForces : public model::ForceContribution
    {
    public:
      /**
       * @param elements Initialised elements (kept by reference).
       * @param density_scaling Mass-scaling factor per element (1: none).
       */
      SolidHexForces(SolidHexElements &         elements,
                     const std::vector<double> &density_scaling);

      std::string
      name() const override;

      Accumulation
      accumulation() const override;

      void
      add_forces(const model::EvaluationPoint &point,
                 VectorType &                  f,
                 model::ContributionResults &  results) override;

      /** Yes: the elements' stiffness is the assembled estimate's. */
      bool
      in_assembled_step_estimate() const override;

      void
      accept_step() override;

      void
      add_lumped_mass(VectorType &mass,
                      VectorType &physical_mass) const override;

      void
      save(std::ostream &out) const override;

      void
      load(std::istream &in) override;

      /** The mass-scaling factor of each element. */
      const std::vector<double> &
      density_scaling() const
      {
        return scaling;
      }

    private:
      SolidHexElements &  elements;
      std::vector<double> scaling;
      ElementStepResult   step_result;
    };
  } // namespace elements
} // namespace rubberdyn

#endif
