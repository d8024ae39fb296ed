#include <deal.II/base/mpi.h>

#include <rubberdyn/elements/solid_hex_elements.h>
#include <rubberdyn/model/model.h>
#include <rubberdyn/simulation/explicit_view.h>
#include <rubberdyn/time_integration/explicit_solver.h>

namespace rubberdyn
{
  namespace simulation
  {
    ExplicitView::ExplicitView(const model::Model                     &model,
                               const time_integration::ExplicitSolver &solver,
                               const elements::SolidHexElements &elements,
                               const std::vector<model::RigidBody> &bodies)
      : the_model(model)
      , solver(solver)
      , hexes(elements)
      , the_bodies(bodies)
    {}



    const model::Model &
    ExplicitView::model() const
    {
      return the_model;
    }



    double
    ExplicitView::time() const
    {
      return solver.time();
    }



    const VectorType &
    ExplicitView::displacement() const
    {
      return solver.displacement();
    }



    const std::vector<double> &
    ExplicitView::reactions() const
    {
      return solver.reactions();
    }



    const std::vector<dealii::Tensor<1, 3>> &
    ExplicitView::reaction_moments() const
    {
      return solver.reaction_moments();
    }



    double
    ExplicitView::internal_energy() const
    {
      return solver.energies().internal;
    }



    const std::vector<double> &
    ExplicitView::internal_energy_by_group() const
    {
      return solver.internal_energy_by_group();
    }



    std::vector<double>
    ExplicitView::section_forces() const
    {
      // (The solver keeps no section forces: the elements compute them
      // from the displacement when a row asks.)
      std::vector<double> force = hexes.section_forces(solver.displacement());
      dealii::Utilities::MPI::sum(dealii::ArrayView<const double>(force),
                                  the_model.comm,
                                  dealii::ArrayView<double>(force));
      return force;
    }



    const std::vector<double> &
    ExplicitView::section_shortenings() const
    {
      return hexes.section_shortenings();
    }



    const std::vector<model::RigidBody> &
    ExplicitView::bodies() const
    {
      return the_bodies;
    }



    const elements::ImplicitElements &
    ExplicitView::elements() const
    {
      return hexes;
    }



    const time_integration::ExplicitSolver *
    ExplicitView::explicit_solver() const
    {
      return &solver;
    }
  } // namespace simulation
} // namespace rubberdyn
