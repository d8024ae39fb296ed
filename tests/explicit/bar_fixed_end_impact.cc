// A bar moving at v0 towards its own fixed end: the explicit solver's
// fixed boundary (KinematicConstraints::fix, the initial velocity of the
// constrained dofs overwritten at t = 0, the reaction per direction)
// against elementary one-dimensional wave theory (K. F. Graff, Wave Motion
// in Elastic Solids, Dover 1991, ch. 2, longitudinal waves in thin rods,
// reflection at fixed and free ends).
//
// The bar 0 <= z <= L moves at -v0 (towards z = 0); the end z = 0 is held
// from t = 0 on. A compression wave runs from the fixed end to the free
// end and brings the material behind it to rest, so the fixed end pushes
// with
//   R = rho c A v0,   c = sqrt(E / rho),
// until the wave, reflected at the free end as an unloading wave that
// leaves the bar moving at +v0, returns at t = 2 L / c. Unlike a rigid
// wall, a fixed end does not let go: it now holds the bar back, the
// reaction jumps to -rho c A v0 (tension) and stays there until 4 L / c,
// when the cycle starts again. Acceptance: the compressive plateau (mean
// over the middle half of [0, 2 L / c], which averages the Gibbs
// oscillations trailing a front in a lumped-mass mesh) and the tensile
// one (middle half of [2 L / c, 4 L / c]) within 3 % of rho c A v0, and
// the time the reaction changes sign (linear interpolation between steps)
// within 2 % of 2 L / c.
//
// Energy: the fixed end does no work (its nodes do not move, the external
// work must stay exactly 0); the initial energy is the kinetic energy of
// the free nodes only, 1/2 rho A (L - h / 2) v0^2 with the end layer's
// lumped mass rho A h / 2 at rest (checked to 1e-12: the solver's first
// step applied the constraint's velocity at t = 0 there), and kinetic plus internal energy
// plus bulk viscosity's dissipation stay equal to it: relative error below
// 1e-3 over the whole run. The solver's kinetic energy (mean of the two
// half-step velocities) exceeds the conserved one by about
// rho A h v0^2 / 8 while a velocity-step front runs (see
// bar_uniaxial_strain_constraints.cc), h / (4 L) = 6.3e-4 of the initial
// energy here.
//
// Poisson's ratio 0 keeps the bar uniaxial (the three-dimensional
// dilatational speed equals c; no lateral stress, so the x and y
// reactions stay zero: printed). Strain v0 / c = 1.9e-4, where the
// compressible neo-Hookean law is linear to that relative amount. Bulk
// viscosity keeps its defaults; it acts only in the fronts.
#include <deal.II/base/mpi.h>

#include <rubberdyn/materials/elastic.h>

#include "../tests.h"
#include "bar.h"

using namespace dealii;
namespace ti = rubberdyn::time_integration;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                   comm = MPI_COMM_WORLD;
  const bool root = (Utilities::MPI::this_mpi_process(comm) == 0);

  // Steel-like, nu = 0 (units mm, ms, kg, kN, GPa).
  const double E = 210., nu = 0., rho = 7.85e-6, v0 = 1.;
  const double c = std::sqrt(E / rho);
  const rubberdyn::materials::Elastic<3> steel(E, nu, rho);

  // 6 x 6 mm, 2 elements across; 600 mm, 400 elements along.
  const double       width = 6., length = 600.;
  const unsigned int n_across = 2, n_along = 400;
  const bar::Bar     model(width, n_across, length, n_along, comm);
  const double       h = length / n_along;

  // No contact, no bodies; the end z = 0 fixed.
  bar::ExplicitBar model_solver(
    model, steel, {}, {}, 1., {}, [](ti::KinematicConstraints &constraints) {
      constraints.fix("fixed end", bar::boundary::z_min);
    });
  ti::ExplicitSolver &            solver      = *model_solver.solver;
  const ti::KinematicConstraints &constraints = model_solver.constraints;

  solver.set_initial_velocity(Tensor<1, 3>({0., 0., -v0}));

  // Per step, the same on every rank (the solver sums over the ranks).
  const double        T = 2. * length / c;
  std::vector<double> times, reaction;
  double max_lateral_reaction = 0., max_energy_error = 0., max_abs_work = 0.;
  solver.run(1.95 * T, [&]() {
    times.push_back(solver.time());
    reaction.push_back(solver.reactions()[2]);
    max_lateral_reaction = std::max({max_lateral_reaction,
                                     std::abs(solver.reactions()[0]),
                                     std::abs(solver.reactions()[1])});
    max_energy_error =
      std::max(max_energy_error, solver.energies().relative_error());
    max_abs_work =
      std::max(max_abs_work, std::abs(solver.energies().external_work));
  });

  // Plateaus: means over the middle halves of [0, T] and [T, 2 T].
  double       compression = 0., tension = 0.;
  unsigned int n_compression = 0, n_tension = 0;
  for (unsigned int i = 0; i < times.size(); ++i)
    if (times[i] >= 0.25 * T && times[i] <= 0.75 * T)
      {
        compression += reaction[i];
        ++n_compression;
      }
    else if (times[i] >= 1.25 * T && times[i] <= 1.75 * T)
      {
        tension += reaction[i];
        ++n_tension;
      }
  compression /= std::max(n_compression, 1u);
  tension /= std::max(n_tension, 1u);

  // Sign change: the first step with a negative reaction after it has
  // been positive, interpolated linearly to zero.
  unsigned int first = 0;
  while (first < reaction.size() && !(reaction[first] > 0.))
    ++first;
  unsigned int change = first;
  while (change < reaction.size() && reaction[change] >= 0.)
    ++change;
  const bool   changed = (first < reaction.size() && change < reaction.size());
  const double t_change =
    changed ? times[change - 1] + (times[change] - times[change - 1]) *
                                    reaction[change - 1] /
                                    (reaction[change - 1] - reaction[change]) :
              0.;

  const double force_exact = rho * c * model.area() * v0;
  const double initial_exact =
    0.5 * rho * model.area() * (length - 0.5 * h) * v0 * v0;
  const double compression_error =
    std::abs(compression - force_exact) / force_exact;
  const double tension_error = std::abs(-tension - force_exact) / force_exact;
  const double change_error  = std::abs(t_change - T) / T;
  const double initial_error =
    std::abs(solver.energies().initial - initial_exact) / initial_exact;

  if (root)
    {
      auto &out = testing::out();
      out << "Bar " << width << " x " << width << " x " << length << " mm, "
          << model.triangulation.n_global_active_cells()
          << " hexahedra, end z = 0 fixed; E = " << E << " GPa, nu = " << nu
          << ", rho = " << rho << " kg/mm^3, initial velocity -" << v0
          << " mm/ms" << std::endl;
      out << "constraint groups:";
      for (const std::string &name : constraints.group_names())
        out << " '" << name << "'";
      out << std::endl << std::setprecision(4);
      out << "bar wave speed c = sqrt(E/rho) = " << c
          << " mm/ms, rho c A v0 = " << force_exact << " kN, 2 L / c = " << T
          << " ms" << std::endl;
      out << "compressive plateau (mean over [0.25, 0.75] 2L/c): "
          << compression << " kN, error " << std::fixed << std::setprecision(2)
          << 100. * compression_error << " %" << std::endl;
      out << std::defaultfloat << std::setprecision(4)
          << "tensile plateau (mean over [1.25, 1.75] 2L/c): " << tension
          << " kN, error " << std::fixed << std::setprecision(2)
          << 100. * tension_error << " %" << std::endl;
      out << std::defaultfloat << std::setprecision(4) << std::setprecision(5)
          << "reaction changes sign at t = " << t_change << " ms, error "
          << std::fixed << std::setprecision(3) << 100. * change_error << " %"
          << std::endl;
      out << "largest |x|, |y| reaction: " << testing::sci(max_lateral_reaction)
          << " kN" << std::endl;
      out << "initial energy " << std::defaultfloat << std::setprecision(6)
          << solver.energies().initial
          << " J, 1/2 rho A (L - h/2) v0^2 = " << initial_exact << " J"
          << std::endl;
      out << "largest |external work| " << testing::sci(max_abs_work)
          << " J, largest relative energy error "
          << testing::sci(max_energy_error) << std::endl;
    }
  testing::check(n_compression > 0 && compression_error < 0.03,
                 "compressive reaction within 3 %");
  testing::check(n_tension > 0 && tension_error < 0.03,
                 "tensile reaction within 3 %");
  testing::check(changed && change_error < 0.02,
                 "sign change within 2 % of 2 L / c");
  testing::check(initial_error < 1e-12,
                 "initial energy without the fixed nodes");
  testing::check(max_abs_work == 0., "the fixed end does no work");
  testing::check(max_energy_error < 1e-3, "energy error below 1e-3");
}
