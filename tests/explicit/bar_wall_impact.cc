// A slender elastic bar hits a rigid wall: the whole explicit engine
// (F-bar hexahedra, lumped mass, central differences, penalty contact with
// a held rigid plane, bulk viscosity) against elementary one-dimensional
// wave theory (K. F. Graff, Wave Motion in Elastic Solids, Dover 1991,
// ch. 2, longitudinal waves in thin rods; W. Johnson, Impact Strength of
// Materials, Edward Arnold 1972).
//
// A bar of length L moving at v0 towards a rigid wall starts, on contact,
// a compression wave that brings the material behind it to rest. While the
// wave runs to the free end and back the wall force is
//   F = rho c A v0,   c = sqrt(E / rho)  (bar wave speed),
// and the bar leaves the wall when the reflected unloading wave returns,
// after the contact duration 2 L / c. Acceptance: plateau force within 3 %,
// contact duration within 2 %.
//
// Poisson's ratio 0 makes the three-dimensional dilatational speed
// sqrt((lambda + 2 mu) / rho) equal to the bar speed and keeps the bar
// uniaxial (no lateral inertia, no Pochhammer dispersion). The strain
// v0 / c = 1.9e-4 keeps the compressible neo-Hookean law linear to about
// that relative amount.
//
// Penalty contact: a wall spring of stiffness k in series with the bar
// (impedance Z = rho c A) makes the force rise as
// Z v0 (1 - exp(-t / tau)), tau = Z / k, and delays the separation:
// with the wave returning at T = 2 L / c, tau F' + F = Z v0 - 2 F(t - T)
// gives F = Z v0 [2 (1 + x) e^{-x} - 1], x = (t - T) / tau, which vanishes
// at x = 1.68, so the contact lasts T + 1.68 tau. The contact stiffness
// sums k = s K A_f^2 / V over the end faces, so k = s K A / h and, with
// K = E / 3 for nu = 0, tau = 3 h / (s c). The penalty scale s = 1 gives
// tau = 3 h / c and a delay of 5 h / c, 0.84 % of T on 300 elements along
// the bar (1.00 % measured; 12.6 % predicted and 12.7 % measured for the
// drop-test default s = 0.1 on 200 elements, which is meant for soft
// rubber, not steel on steel).
// A stiffer wall is not usable at the default time step scale 0.9: the
// solver takes the smaller of the element step and the penalty step
// 2 sqrt(m / k) (= 2 (h / c) sqrt(1.5 / s) for a corner node here), but a
// node held by both its element and the penalty spring oscillates faster
// than on either alone (the squared frequencies add). Here s = 2 already
// rings in the first steps, s = 3 dips to a third of the plateau, and from
// s = 4 on the end nodes blow up off the wall; all of them run cleanly at
// the scale 0.6. A rough estimate, 2 / sqrt((2 c / h)^2 + (2 / dt_pen)^2)
// against the step 0.9 h / (1.06 c) taken (bulk viscosity's 1.06), leaves
// 9 % of margin for s = 1, 2 % for s = 2 and none for s = 3. (These
// figures predate two changes: the solver now combines the two,
// 1/dt^2 = 1/dt_e^2 + 1/dt_c^2, and the element step is Flanagan and
// Belytschko's bound, doc/theory.md section 8.3.)
//
// The plateau force is the mean over the middle half of the measured
// contact: that skips the penalty rise and the unloading and averages the
// Gibbs oscillations that trail a front in a lumped-mass mesh.
// Bulk viscosity keeps its defaults (linear 0.06, quadratic 1.5): it only
// acts while the volume changes, i.e. in the fronts, not on the plateau.
//
// Energy (issue 11, "an energy-balance assertion in the bar-on-wall test"):
// nothing but the wall acts, and it is held, so E_kin + E_int + E_contact
// + W_bulk viscosity stays at E_0 = M v0^2 / 2 (conservation of energy).
// Checked at every step: the solver's error |E_kin + E_int + E_contact +
// W_bv + W_friction - E_0 - W_ext| below 1e-3 E_0, and the external work
// zero (the wall does not move) to 1e-12 E_0. After the separation the bar
// carries E_0 - W_bv as kinetic energy and the elastic ringing the wave
// leaves behind: E_kin + E_int + W_bv = E_0 within 1e-3, and W_bv >= 0
// (the viscosity only dissipates).
#include <deal.II/base/mpi.h>

#include <rubberdyn/contact/rigid_surface_contact.h>
#include <rubberdyn/elements/solid_hex_elements.h>
#include <rubberdyn/materials/elastic.h>
#include <rubberdyn/time_integration/explicit_solver.h>

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

  // 6 x 6 mm, 3 elements across; 600 mm, 300 elements along: cubes of
  // h = 2 mm.
  const double       width = 6., length = 600.;
  const unsigned int n_across = 3, n_along = 300;
  bar::Bar           model(width, n_across, length, n_along, comm);

  // The wall z = 0, facing the bar's end face, which touches it at t = 0;
  // its body has mass 0 and nothing free: held.
  const double     penalty_scale = 1.;
  bar::ExplicitBar model_solver(model,
                                steel,
                                {bar::boundary::z_min},
                                {{Point<3>(0., 0., 0.), Tensor<1, 3>({0., 0., 1.})}},
                                penalty_scale);
  ti::ExplicitSolver &solver = *model_solver.solver;
  const auto         &bodies = model_solver.bodies;
  solver.set_initial_velocity(Tensor<1, 3>({0., 0., -v0}));

  // Wall force at every step (the same on every rank: the solver sums the
  // contact force over all ranks).
  std::vector<double> times, forces;
  double largest_error = 0., largest_external = 0., smallest_viscous = 0.;
  solver.run(1.25 * 2. * length / c, [&]() {
    times.push_back(solver.time());
    forces.push_back(-bodies[0].contact_force[2]);
    const ti::EnergyBalance &e = solver.energies();
    largest_error    = std::max(largest_error, e.absolute_error());
    largest_external = std::max(largest_external, std::abs(e.external_work));
    smallest_viscous = std::min(smallest_viscous, e.bulk_viscosity_work);
  });
  const ti::EnergyBalance &final_energy = solver.energies();
  const double             E0           = final_energy.initial;
  const double             mass         = rho * model.area() * length;
  const double             energy_error = largest_error / E0;
  const double             final_balance =
    std::abs(final_energy.kinetic + final_energy.internal +
             final_energy.bulk_viscosity_work - E0) /
    E0;

  // First contact: the last sample without force before the first with
  // force (the gap is zero at t = 0 and closes from then on). Separation:
  // the first sample without force after that.
  unsigned int first = 0;
  while (first < forces.size() && !(forces[first] > 0.))
    ++first;
  unsigned int last = first;
  while (last < forces.size() && forces[last] > 0.)
    ++last;
  unsigned int later_contacts = 0;
  for (unsigned int i = last; i < forces.size(); ++i)
    if (forces[i] > 0.)
      ++later_contacts;
  const bool   separated = (first > 0 && last < forces.size());
  const double t_start   = separated ? times[first - 1] : 0.;
  const double t_end     = separated ? times[last] : 0.;
  const double duration  = t_end - t_start;

  double       plateau   = 0.;
  unsigned int n_plateau = 0;
  for (unsigned int i = first; i < last; ++i)
    if (times[i] >= t_start + 0.25 * duration &&
        times[i] <= t_start + 0.75 * duration)
      {
        plateau += forces[i];
        ++n_plateau;
      }
  plateau /= std::max(n_plateau, 1u);

  const double force_exact    = rho * c * model.area() * v0;
  const double duration_exact = 2. * length / c;
  const double force_error    = std::abs(plateau - force_exact) / force_exact;
  const double duration_error =
    std::abs(duration - duration_exact) / duration_exact;

  if (root)
    {
      auto &out = testing::out();
      out << "Bar " << width << " x " << width << " x " << length << " mm, "
          << model.triangulation.n_global_active_cells()
          << " hexahedra; E = " << E << " GPa, nu = " << nu << ", rho = " << rho
          << " kg/mm^3, v0 = " << v0 << " mm/ms; penalty scale "
          << penalty_scale << std::endl;
      out << std::setprecision(4);
      out << "bar wave speed c = sqrt(E/rho) = " << c << " mm/ms" << std::endl;
      out << "separated from the wall: " << (separated ? "yes" : "no")
          << ", contacts after separation: " << later_contacts << std::endl;
      out << "plateau force (mean over the middle half of the contact): "
          << plateau << " kN, rho c A v0 = " << force_exact << " kN, error "
          << std::fixed << std::setprecision(2) << 100. * force_error << " %"
          << std::endl;
      out << std::defaultfloat << std::setprecision(4)
          << "contact duration: " << duration
          << " ms, 2 L / c = " << duration_exact << " ms, error " << std::fixed
          << std::setprecision(2) << 100. * duration_error << " %" << std::endl;
      out << std::scientific << std::setprecision(1)
          << "E_0 / (M v0^2 / 2) - 1: "
          << E0 / (0.5 * mass * v0 * v0) - 1. << std::endl
          << "largest energy error / E_0: " << energy_error << std::endl
          << "after separation, |E_kin + E_int + W_bv - E_0| / E_0: "
          << final_balance << std::endl
          << "largest |W_ext| / E_0: " << largest_external / E0 << std::endl;
      out << "plateau force within 3 %: "
          << (force_error < 0.03 ? "PASS" : "FAIL") << std::endl;
      out << "contact duration within 2 %: "
          << (duration_error < 0.02 ? "PASS" : "FAIL") << std::endl;
    }
  testing::check(separated && later_contacts == 0,
                 "the bar leaves the wall once and for all");
  testing::check(force_error < 0.03, "plateau force within 3 %");
  testing::check(duration_error < 0.02, "contact duration within 2 %");
  testing::check(std::abs(E0 / (0.5 * mass * v0 * v0) - 1.) < 1e-12,
                 "the initial energy is M v0^2 / 2");
  testing::check(energy_error < 1e-3, "energy error below 1e-3 of E_0");
  testing::check(largest_external < 1e-12 * E0, "a held wall does no work");
  testing::check(smallest_viscous >= 0., "bulk viscosity only dissipates");
  testing::check(final_balance < 1e-3,
                 "after separation E_kin + E_int + W_bv = E_0 within 1e-3");
}
