// Checkpoint and restart: a run continued from a checkpoint is identical,
// to the last bit, to the uninterrupted run. The model is the drop-test
// cylinder (80 cells) of a J2-plastic metal with a low yield stress (so
// the material history matters) between plates with Coulomb friction
// mu = 0.3 (so the contact state matters), hit by a 5 kg impactor at 2
// m/s under gravity. Run A goes to 0.3 ms, writes a checkpoint, and goes
// on to 0.6 ms; run B builds the model anew, loads the checkpoint and runs
// to 0.6 ms. Displacements, velocities, energies and the impactor must
// agree exactly. Also checks that a checkpoint of a different model is
// refused with a message.
#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>

#include <rubberdyn/base/partitioner.h>
#include <rubberdyn/contact/rigid_surface_contact.h>
#include <rubberdyn/elements/solid_hex_elements.h>
#include <rubberdyn/geometry/standing_cylinder.h>
#include <rubberdyn/materials/hardening_curve.h>
#include <rubberdyn/materials/j2_plasticity.h>
#include <rubberdyn/contact/rigid_surface_forces.h>
#include <rubberdyn/elements/solid_hex_forces.h>
#include <rubberdyn/time_integration/explicit_solver.h>

#include <sstream>

#include "../tests.h"

using namespace dealii;
using namespace rubberdyn;
using testing::check;
using testing::out;

namespace
{
  struct Model
  {
    Model(const MPI_Comm comm, const unsigned int refinement)
      : triangulation(comm)
      , fe(FE_Q<3>(1), 3)
      , dof_handler(triangulation)
      , metal(70., 0.33, 2.7e-6,
              materials::HardeningCurve(0.005, {0.1}, {0.01}, "test"))
      , bodies(2)
    {
      geometry::make_standing_cylinder(triangulation, 25., 24., refinement);
      dof_handler.distribute_dofs(fe);
      partitioner = rubberdyn::ghosted_partitioner(dof_handler);
      elements.initialize(dof_handler, partitioner, {{{0}, &metal, elements::Formulation::fbar}},
                          elements::ElementSettings());
      const Tensor<1, 3> up({0., 0., 1.});
      plates.initialize(dof_handler, partitioner, {0, 1, 2},
                        {metal.bulk_modulus()}, 0.1,
                        {{Point<3>(0., 0., 0.), up, 0.3},
                         {Point<3>(0., 0., 24.), -up, 0.3}});
      bodies[1].mass        = 5.;
      bodies[1].free[2]     = true;
      bodies[1].velocity[2] = -2.;
      time_integration::ExplicitSettings settings;
      settings.gravity = -9.81e-3 * up;
      element_forces   = std::make_unique<elements::SolidHexForces>(
        elements, std::vector<double>(elements.n_elements(), 1.));
      plate_forces = std::make_unique<contact::RigidSurfaceForces>(
        plates, std::vector<unsigned int>{0, 1});
      solver = std::make_unique<time_integration::ExplicitSolver>(
        dof_handler,
        std::vector<model::ForceContribution *>{element_forces.get(),
                                                plate_forces.get()},
        bodies, nullptr, partitioner, settings, comm);
    }

    parallel::distributed::Triangulation<3>           triangulation;
    FESystem<3>                                       fe;
    DoFHandler<3>                                     dof_handler;
    std::shared_ptr<Utilities::MPI::Partitioner>      partitioner;
    materials::J2Plasticity<3>                        metal;
    elements::SolidHexElements                        elements;
    contact::RigidSurfaceContact                      plates;
    std::vector<model::RigidBody>                     bodies;
    std::unique_ptr<elements::SolidHexForces>         element_forces;
    std::unique_ptr<contact::RigidSurfaceForces>      plate_forces;
    std::unique_ptr<time_integration::ExplicitSolver> solver;
  };

  double
  largest_difference(const VectorType &a, const VectorType &b)
  {
    double difference = 0.;
    for (unsigned int i = 0; i < a.locally_owned_size(); ++i)
      difference =
        std::max(difference, std::abs(a.local_element(i) - b.local_element(i)));
    return Utilities::MPI::max(difference, MPI_COMM_WORLD);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                   comm = MPI_COMM_WORLD;

  Model a(comm, 1);
  a.solver->run(0.3, []() {});
  std::stringstream checkpoint;
  a.solver->save(checkpoint);
  a.solver->run(0.6, []() {});

  Model b(comm, 1);
  b.solver->load(checkpoint);
  b.solver->run(0.6, []() {});

  const double du = largest_difference(a.solver->displacement(),
                                       b.solver->displacement());
  const double dv =
    largest_difference(a.solver->velocity(), b.solver->velocity());
  const auto & ea = a.solver->energies(), &eb = b.solver->energies();
  const bool   same_energies =
    ea.kinetic == eb.kinetic && ea.internal == eb.internal &&
    ea.external_work == eb.external_work && ea.contact == eb.contact &&
    ea.friction_work == eb.friction_work &&
    ea.bulk_viscosity_work == eb.bulk_viscosity_work;
  const bool same_impactor =
    a.bodies[1].displacement == b.bodies[1].displacement &&
    a.bodies[1].velocity == b.bodies[1].velocity;
  out() << "steps " << a.solver->step() << " and " << b.solver->step()
        << ", time " << std::setprecision(6) << a.solver->time() << " ms"
        << std::endl
        << "material history and friction work present: "
        << (a.elements.history().size() > 0 && ea.friction_work > 0. ? "yes" :
                                                                       "no")
        << std::endl
        << "largest differences: displacement " << du << " mm, velocity "
        << dv << " mm/ms" << std::endl
        << "energies identical: " << (same_energies ? "yes" : "no")
        << ", impactor identical: " << (same_impactor ? "yes" : "no")
        << std::endl;
  check(a.solver->step() == b.solver->step() && du == 0. && dv == 0. &&
          same_energies && same_impactor,
        "restart continues identically");

  // A checkpoint of another model (a finer mesh) is refused.
  Model c(comm, 2);
  checkpoint.seekg(0);
  try
    {
      c.solver->load(checkpoint);
      check(false, "a checkpoint of another mesh must be refused");
    }
  catch (const time_integration::SolverFailure &failure)
    {
      out() << "other mesh: " << failure.what() << std::endl;
    }
}
