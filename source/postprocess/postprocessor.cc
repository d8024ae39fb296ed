#include <rubberdyn/postprocess/postprocessor.h>

#include <stdexcept>

namespace rubberdyn
{
  namespace postprocess
  {
    const time_integration::ExplicitSolver &
    explicit_solver_of(const SimulationView &view, const std::string &plugin)
    {
      const time_integration::ExplicitSolver *solver = view.explicit_solver();
      if (solver == nullptr)
        throw std::logic_error("The postprocessor '" + plugin +
                               "' reads quantities of explicit dynamics "
                               "(velocities, energies, works), which this "
                               "run's scheme does not have");
      return *solver;
    }
  } // namespace postprocess
} // namespace rubberdyn
