#ifndef rubberdyn_simulation_explicit_view_h
#define rubberdyn_simulation_explicit_view_h

#include <rubberdyn/postprocess/postprocessor.h>

namespace rubberdyn
{
  namespace simulation
  {
    /**
     * What the postprocessors of an explicit run see
     * (postprocess::SimulationView) over its time_integration::ExplicitSolver
     * and elements::SolidHexElements: the state at the solver's current
     * time, and the solver itself for the explicit-only quantities.
     */
    class ExplicitView : public postprocess::SimulationView
    {
    public:
      /** Hold references to the run's parts; they must outlive the view. */
      ExplicitView(const model::Model                     &model,
                   const time_integration::ExplicitSolver &solver,
                   const elements::SolidHexElements       &elements,
                   const std::vector<model::RigidBody>    &bodies);

      const model::Model &
      model() const override;

      double
      time() const override;

      const VectorType &
      displacement() const override;

      const std::vector<double> &
      reactions() const override;

      const std::vector<dealii::Tensor<1, 3>> &
      reaction_moments() const override;

      /** time_integration::EnergyBalance::internal at the current time. */
      double
      internal_energy() const override;

      const std::vector<double> &
      internal_energy_by_group() const override;

      /**
       * elements::SolidHexElements::section_forces() at the current
       * displacement (without bulk viscosity), summed over the ranks.
       */
      std::vector<double>
      section_forces() const override;

      const std::vector<double> &
      section_shortenings() const override;

      /**
       * The rigid surfaces' own bodies in their order, then the rigid
       * parts' (simulation::ExplicitSimulation::rigid_bodies()).
       */
      const std::vector<model::RigidBody> &
      bodies() const override;

      const elements::ImplicitElements &
      elements() const override;

      const time_integration::ExplicitSolver *
      explicit_solver() const override;

    private:
      const model::Model                     &the_model;
      const time_integration::ExplicitSolver &solver;
      const elements::SolidHexElements       &hexes;
      const std::vector<model::RigidBody>    &the_bodies;
    };
  } // namespace simulation
} // namespace rubberdyn

#endif
