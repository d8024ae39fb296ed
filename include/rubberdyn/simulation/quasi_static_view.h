#ifndef rubberdyn_simulation_quasi_static_view_h
#define rubberdyn_simulation_quasi_static_view_h

#include <rubberdyn/postprocess/postprocessor.h>

namespace rubberdyn
{
  namespace time_integration
  {
    class QuasiStaticSolver;
  }

  namespace simulation
  {
    /**
     * What the postprocessors of a quasi-static run see
     * (postprocess::SimulationView) over its time_integration::
     * QuasiStaticSolver: the last converged state of the load path. It has
     * no explicit solver (explicit_solver() is nullptr): no velocities,
     * kinetic energy or works.
     */
    class QuasiStaticView : public postprocess::SimulationView
    {
    public:
      /** Hold references to the run's parts; they must outlive the view. */
      QuasiStaticView(const model::Model                        &model,
                      const time_integration::QuasiStaticSolver &solver,
                      const elements::ImplicitElements          &elements);

      const model::Model &
      model() const override;

      /** The pseudo-time of the last converged state. */
      double
      time() const override;

      const VectorType &
      displacement() const override;

      const std::vector<double> &
      reactions() const override;

      const std::vector<dealii::Tensor<1, 3>> &
      reaction_moments() const override;

      double
      internal_energy() const override;

      const std::vector<double> &
      internal_energy_by_group() const override;

      /** The solver's, of the last converged state (already summed). */
      std::vector<double>
      section_forces() const override;

      const std::vector<double> &
      section_shortenings() const override;

      /**
       * The solver's bodies: the rigid surfaces' own, and one standing
       * still for each rigid part that carries a surface, in the order of
       * the surfaces.
       */
      const std::vector<model::RigidBody> &
      bodies() const override;

      const elements::ImplicitElements &
      elements() const override;

    private:
      const model::Model                        &the_model;
      const time_integration::QuasiStaticSolver &solver;
      const elements::ImplicitElements          &the_elements;
    };
  } // namespace simulation
} // namespace rubberdyn

#endif
