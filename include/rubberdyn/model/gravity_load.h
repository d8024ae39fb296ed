#ifndef rubberdyn_model_gravity_load_h
#define rubberdyn_model_gravity_load_h

#include <deal.II/base/tensor.h>

#include <rubberdyn/base/vector.h>
#include <rubberdyn/model/force_contribution.h>

#include <string>
#include <vector>

namespace rubberdyn
{
  namespace model
  {
    class Model;

    /**
     * Gravity on a quasi-static load path, as a force contribution: the
     * weight of every node, its lumped mass (setup::part_masses(), summed
     * over the parts: the explicit engine's nodal mass without mass
     * scaling) times `Model/Gravity` (kN), a dead load that grows linearly
     * with the pseudo-time to its full value at @p full_at (the end of the
     * load path) and stays there:
     * $f = \min(t / t_{full}, 1)\, m\, g$.
     * A rigid part's nodes carry its weight (to its support, or to its
     * equilibrium). At the end of a preload the weight is the one the
     * explicit run applies from its start, so the handed-over state is in
     * equilibrium under it.
     */
    class GravityLoad : public ForceContribution
    {
    public:
      /**
       * @param model The gravity, and the dofs.
       * @param masses setup::part_masses() of @p model.
       * @param full_at Pseudo-time at which the full weight acts (> 0).
       */
      GravityLoad(const Model                   &model,
                  const std::vector<VectorType> &masses,
                  const double                   full_at);

      std::string
      name() const override
      {
        return "gravity";
      }

      Accumulation
      accumulation() const override
      {
        return Accumulation::external_owned;
      }

      void
      add_forces(const EvaluationPoint &point,
                 VectorType            &f,
                 ContributionResults   &results) override;

      /** A dead load: no tangent (the default adds none). */
      bool
      supports_implicit() const override
      {
        return true;
      }

      /** The full weight of all nodes (kN), summed over the ranks. */
      Tensor<1, 3>
      total_weight() const
      {
        return total;
      }

    private:
      /** m g at the owned dofs (kN). */
      VectorType   weight;
      double       full_at;
      Tensor<1, 3> total;
    };
  } // namespace model
} // namespace rubberdyn

#endif
