#ifndef rubberdyn_simulation_selective_mass_scaling_setup_h
#define rubberdyn_simulation_selective_mass_scaling_setup_h

#include <rubberdyn/parameters/time_integration_parameters.h>
#include <rubberdyn/time_integration/selective_mass_scaling.h>

#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

namespace rubberdyn
{
  namespace elements
  {
    class SolidHexElements;
  }
  namespace model
  {
    class Model;
  }
  namespace simulation
  {
    using time_integration::PartMassScaling;

    /** Selective mass scaling of a model, ready for the explicit solver. */
    struct SelectiveMassScalingSetup
    {
      /** The operator (nullptr: no element is scaled). */
      std::unique_ptr<time_integration::SelectiveMassScaling> scaling;
      /** Factor on each element's stable step (empty: none scaled). */
      std::vector<double> time_step_factors;
      /** Per part, in the model's order. */
      std::vector<PartMassScaling> parts;

      SelectiveMassScalingSetup();
      SelectiveMassScalingSetup(SelectiveMassScalingSetup &&) noexcept;
      ~SelectiveMassScalingSetup();
    };

    namespace setup
    {
      /**
       * Selective mass scaling of @p model's deformable parts: each part's
       * target step (`Parts/<name>/Selective mass scaling time step`, else
       * `Time integration/Selective mass scaling time step`). An element
       * whose stable step (times the Time step scale factor) is below its
       * part's target gets the added mass beta_e = s max_a m_a - min_a
       * m_a, s = (target / step)^2, m_a its nodes' lumped masses: its
       * highest frequency falls at least by sqrt(s) (doc/theory.md,
       * "Selective mass scaling"), and its stable step is multiplied by
       * sqrt((beta_e + min m_a) / max m_a) = sqrt(s). Elements with a
       * rigid part's node are not scaled (counted). Collective.
       *
       * @throws InputError when conventional and selective mass scaling
       *   are both asked for.
       */
      SelectiveMassScalingSetup
      selective_mass_scaling(
        const model::Model                &model,
        const parameters::TimeIntegration &time_integration,
        const elements::SolidHexElements  &elements);

      /** The log's lines on selective mass scaling (rank 0 writes). */
      void
      log_selective_mass_scaling(const model::Model                  &model,
                                 const std::vector<PartMassScaling> &parts,
                                 std::ostream                        &log);
    } // namespace setup
  }   // namespace simulation
} // namespace rubberdyn

#endif
