#include <rubberdyn/simulation/quasi_static_view.h>
#include <rubberdyn/time_integration/quasi_static_solver.h>

namespace rubberdyn
{
  namespace simulation
  {
    QuasiStaticView::QuasiStaticView(
      const model::Model                        &model,
      const time_integration::QuasiStaticSolver &solver,
      const elements::ImplicitElements          &elements)
      : the_model(model)
      , solver(solver)
      , the_elements(elements)
    {}



    const model::Model &
    QuasiStaticView::model() const
    {
      return the_model;
    }



    double
    QuasiStaticView::time() const
    {
      return solver.time();
    }



    const VectorType &
    QuasiStaticView::displacement() const
    {
      return solver.displacement();
    }



    const std::vector<double> &
    QuasiStaticView::reactions() const
    {
      return solver.reactions();
    }



    const std::vector<dealii::Tensor<1, 3>> &
    QuasiStaticView::reaction_moments() const
    {
      return solver.reaction_moments();
    }



    double
    QuasiStaticView::internal_energy() const
    {
      return solver.internal_energy();
    }



    const std::vector<double> &
    QuasiStaticView::internal_energy_by_group() const
    {
      return solver.internal_energy_by_group();
    }



    std::vector<double>
    QuasiStaticView::section_forces() const
    {
      return solver.section_forces();
    }



    const std::vector<double> &
    QuasiStaticView::section_shortenings() const
    {
      return solver.section_shortenings();
    }



    const std::vector<model::RigidBody> &
    QuasiStaticView::bodies() const
    {
      return solver.bodies();
    }



    const elements::ImplicitElements &
    QuasiStaticView::elements() const
    {
      return the_elements;
    }
  } // namespace simulation
} // namespace rubberdyn
