// A term missing from the energy balance shows (issue 11, energy
// accounting: "a deliberately removed term (a test hook that drops the
// viscous force from the balance) is detected").
//
// A soft elastic bar (E = 0.01 GPa, nu = 0.3, 1.1e-6 kg/mm^3; bar wave
// speed 95 mm/ms; 10 x 10 x 100 mm, 2 x 2 x 40 F-bar hexahedra) hits a held
// rigid wall at 20 mm/ms: a strain of about 0.2 behind the front, a shock
// for the bulk viscosity (default coefficients). Run twice to 1 ms, the
// same trajectory:
//   - as it is: the largest error against the energy through the
//     deformable parts (EnergyBalance::deformable_relative_error()) is the
//     discretisation's;
//   - with the elements wrapped by a test decorator that withholds the
//     reported bulk-viscosity power (the force still acts): the signed
//     balance (present minus supplied energy) at the end must fall by
//     exactly the viscous work W of the first run (to 1e-9 W: the balance
//     sees every joule of the missing term), and the largest error must
//     grow to at least 3 times the first run's: the missing term stands
//     out above the discretisation error. (W is 7e-4 of the impact energy
//     here: below the 1 % warning, so the comparison, not the warning, is
//     the check.)
// The hook lives in this test only (ViscousWorkDropped): production code
// has no switch to lose a term.
#include <deal.II/base/mpi.h>

#include <rubberdyn/materials/elastic.h>

#include <array>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <memory>

#include "../tests.h"
#include "bar.h"

using namespace dealii;
using namespace rubberdyn;
using testing::check;
using testing::out;
using testing::sci;

namespace
{
  /** The elements, with their bulk-viscosity power withheld. */
  class ViscousWorkDropped : public model::ForceContribution
  {
  public:
    explicit ViscousWorkDropped(model::ForceContribution &inner)
      : inner(inner)
    {}

    std::string
    name() const override
    {
      return inner.name() + " (viscous work dropped)";
    }

    Accumulation
    accumulation() const override
    {
      return inner.accumulation();
    }

    void
    add_forces(const model::EvaluationPoint &point,
               VectorType &                  f,
               model::ContributionResults &  results) override
    {
      const double before = results.bulk_viscosity_power;
      inner.add_forces(point, f, results);
      results.bulk_viscosity_power = before;
    }

    void
    accept_step() override
    {
      inner.accept_step();
    }

    void
    add_lumped_mass(VectorType &mass, VectorType &physical_mass) const override
    {
      inner.add_lumped_mass(mass, physical_mass);
    }

  private:
    model::ForceContribution &inner;
  };

  struct Outcome
  {
    double largest_error, viscous_work, impact_energy, signed_error;
  };

  Outcome
  impact(const bool drop_viscous_work)
  {
    const materials::Elastic<3> law(0.01, 0.3, 1.1e-6);
    const bar::Bar bar(10., 2, 100., 40, MPI_COMM_WORLD);
    contact::RigidSurface wall;
    wall.normal = Tensor<1, 3>({0., 0., 1.});
    bar::ExplicitBar parts(bar, law, {bar::boundary::z_min}, {wall}, 0.1);
    ViscousWorkDropped dropping(*parts.element_forces);
    time_integration::ExplicitSolver solver(
      bar.dof_handler,
      {drop_viscous_work ?
         static_cast<model::ForceContribution *>(&dropping) :
         static_cast<model::ForceContribution *>(parts.element_forces.get()),
       parts.contact_forces.get()},
      parts.bodies,
      &parts.constraints,
      bar.partitioner,
      time_integration::ExplicitSettings(),
      bar.comm);
    const double v0 = 20.;
    solver.set_initial_velocity(Tensor<1, 3>({0., 0., -v0}));
    double largest = 0.;
    solver.run(1., [&]() {
      largest =
        std::max(largest, solver.energies().deformable_relative_error());
    });
    const time_integration::EnergyBalance &e = solver.energies();
    return {largest,
            e.bulk_viscosity_work,
            e.initial,
            e.kinetic + e.internal + e.contact + e.bulk_viscosity_work +
              e.friction_work - e.initial - e.external_work};
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const Outcome kept    = impact(false);
  const Outcome dropped = impact(true);
  const double W = kept.viscous_work;
  const double drop_error =
    std::abs((dropped.signed_error - kept.signed_error) + W);
  out() << "Soft bar on a wall at 20 mm/ms to 1 ms:" << std::endl
        << "  the viscous work is booked in the first run and not in the "
           "second: "
        << (W > 0. && dropped.viscous_work == 0. ? "yes" : "no") << std::endl
        << "  the balance falls by exactly the viscous work, to 1e-9 of it: "
        << (drop_error < 1e-9 * W ? "yes" : "no") << std::endl
        << "  the largest error against the deformable energy grows at least "
           "3 times: "
        << (dropped.largest_error > 3. * kept.largest_error ? "yes" : "no")
        << std::endl;
  std::cout << "viscous work " << sci(W / kept.impact_energy)
            << " of the impact energy; largest error " << sci(kept.largest_error)
            << " kept, " << sci(dropped.largest_error) << " dropped"
            << std::endl;
  check(W > 0. && dropped.viscous_work == 0., "the hook withholds the work");
  check(drop_error < 1e-9 * W, "the balance sees the missing work");
  check(dropped.largest_error > 3. * kept.largest_error,
        "the missing term stands out");
}
