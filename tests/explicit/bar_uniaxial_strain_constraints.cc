// A velocity step on a bar held in uniaxial strain by symmetry planes: the
// kinematic constraints of the explicit solver (symmetry planes, a
// prescribed velocity, their reactions and their work) against the plane
// dilatational wave of linear elasticity (K. F. Graff, Wave Motion in
// Elastic Solids, Dover 1991, ch. 5, plane waves in unbounded media; ch. 2
// for the one-dimensional impedance relations).
//
// The lateral faces x = 0, x = a, y = 0, y = a are symmetry planes (zero
// normal velocity, free tangential motion), so every cross-section stays
// in place laterally and the material is in uniaxial strain. The end z = 0
// is driven at the constant velocity v0 from t = 0 (a step), the end z = L
// is free. Before the wave comes back from the free end (t < 2 L / c_d):
//  - the front travels at the dilatational speed
//      c_d = sqrt((lambda + 2 mu) / rho);
//  - behind it the axial stress is sigma_zz = -rho c_d v0 (the impedance
//    relation of a velocity step), so the driven end needs the force
//      F = rho c_d A v0;
//  - the lateral stress is sigma_xx = lambda eps_zz = -lambda v0 / c_d, so
//    the reaction of one symmetry plane grows with the loaded length
//    c_d t as |R_x| = lambda v0 a t (slope lambda v0 a);
//  - the driver's work F v0 t is the external work, and kinetic plus
//    internal energy (plus bulk viscosity's dissipation) equal it.
// Acceptance: front speed within 2 % of c_d, the driven end's reaction
// (mean over the middle half of [0, 2 L / c_d], which averages the Gibbs
// oscillations of a lumped-mass mesh) within 3 % of rho c_d A v0, the
// least-squares slope of the symmetry plane's reaction within 3 % of
// lambda v0 a, the external work at the end of the plateau window within
// 3 % of F v0 t, and the relative energy error below 1e-3 from t = L / c_d
// on.
//
// Why not from t = 0: the solver's kinetic energy at t_n takes the mean of
// the two half-step velocities, which exceeds the energy the central
// difference scheme conserves (with v^{n-1/2} . M v^{n+1/2}) by
// (dt^2 / 8) a . M a. At a velocity-step front, where each node layer
// jumps by about v0 in a step, that is about rho A h v0^2 / 8 (h the
// element length), an offset that travels with the front and stays
// constant (measured 1.92e-5 J against 1.91e-5 J). Relative to the work
// rho c_d A v0^2 t it is h / (8 c_d t): 12 % after the first step, 7e-4 at
// t = L / c_d, 3e-4 at the end. (The solver used to count the reaction's
// work half a step ahead of the energies, an offset of F v0 dt / 2 =
// -6.5e-5 J that made the error 1.5e-3 at t = L / c_d; this test caught
// it.) The largest error of the whole run is printed too.
//
// The symmetry planes hold every x and y displacement at zero: the nodes
// on the planes are constrained (exactly 0 checked), the ones between them
// are pushed by mirror images of the same element and stay at 0 to
// rounding (the largest |u_x|, |u_y| over the run must stay below 1e-12 of
// the axial displacement v0 t of the driven end).
//
// Steel with nu = 0.3 (c_d 16 % above the bar speed sqrt(E / rho));
// v0 = 0.6 mm/ms gives the strain v0 / c_d = 1e-4, where the compressible
// neo-Hookean law is linear to that relative amount. Bulk viscosity keeps
// its defaults; it acts only in the front.
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

  // Steel-like (units mm, ms, kg, kN, GPa).
  const double E = 210., nu = 0.3, rho = 7.85e-6, v0 = 0.6;
  const double lambda = E * nu / ((1. + nu) * (1. - 2. * nu));
  const double mu     = E / (2. * (1. + nu));
  const double c_d    = std::sqrt((lambda + 2. * mu) / rho);
  const rubberdyn::materials::Elastic<3> steel(E, nu, rho);

  // 6 x 6 mm, 3 elements across (so that there are nodes between the
  // planes); 300 mm, 200 elements along.
  const double       width = 6., length = 300.;
  const unsigned int n_across = 3, n_along = 200;
  const bar::Bar     model(width, n_across, length, n_along, comm);

  // No contact, no bodies; symmetry planes on the sides, the end z = 0
  // driven at v0.
  bar::ExplicitBar model_solver(
    model, steel, {}, {}, 1., {}, [v0](ti::KinematicConstraints &constraints) {
      constraints.symmetry_plane("symmetry x = 0", bar::boundary::x_min, 0);
      constraints.symmetry_plane("symmetry x = a", bar::boundary::x_max, 0);
      constraints.symmetry_plane("symmetry y = 0", bar::boundary::y_min, 1);
      constraints.symmetry_plane("symmetry y = a", bar::boundary::y_max, 1);
      constraints.prescribe_velocity("driver",
                                     bar::boundary::z_min,
                                     2,
                                     [v0](const double) { return v0; });
    });
  ti::ExplicitSolver &            solver      = *model_solver.solver;
  const ti::KinematicConstraints &constraints = model_solver.constraints;
  const unsigned int              x_plane = 0, driver = 4;

  const std::vector<double> stations = {0.2 * length,
                                        0.35 * length,
                                        0.5 * length,
                                        0.65 * length,
                                        0.8 * length};
  bar::FrontTracker         tracker(model, stations, v0);
  // x and y dofs, split into those on a symmetry plane (constrained) and
  // those between the planes.
  std::vector<unsigned int> on_planes, between_planes;
  {
    std::set<unsigned int> constrained;
    for (const ti::KinematicConstraints::Entry &entry : constraints.entries())
      if (entry.group != driver)
        constrained.insert(entry.dof);
    for (const unsigned int d : {0u, 1u})
      for (const unsigned int i : model.owned_dofs_of_component(d))
        (constrained.count(i) ? on_planes : between_planes).push_back(i);
  }

  // Per step, the same on every rank: reactions and energies are summed
  // over all ranks by the solver.
  const double        T = 2. * length / c_d; // the wave's round trip
  std::vector<double> times, driver_force, plane_force, external_work;
  std::vector<double> energy_error, energy_residual;
  double              max_on_planes = 0., max_between_planes = 0.;
  solver.run(0.95 * T, [&]() {
    tracker.record(solver);
    times.push_back(solver.time());
    driver_force.push_back(solver.reactions()[driver]);
    plane_force.push_back(solver.reactions()[x_plane]);
    external_work.push_back(solver.energies().external_work);
    const ti::EnergyBalance &e = solver.energies();
    energy_error.push_back(e.relative_error());
    energy_residual.push_back(e.kinetic + e.internal + e.contact +
                              e.bulk_viscosity_work - e.initial -
                              e.external_work);
    for (const unsigned int i : on_planes)
      max_on_planes =
        std::max(max_on_planes,
                 std::abs(solver.displacement().local_element(i)));
    for (const unsigned int i : between_planes)
      max_between_planes =
        std::max(max_between_planes,
                 std::abs(solver.displacement().local_element(i)));
  });
  max_on_planes      = Utilities::MPI::max(max_on_planes, comm);
  max_between_planes = Utilities::MPI::max(max_between_planes, comm);
  const bar::FrontArrivals front = tracker.result();

  // Plateau of the driven end's force and external work at its end.
  double       force = 0., work = 0., t_work = 0.;
  unsigned int n_plateau = 0;
  for (unsigned int i = 0; i < times.size(); ++i)
    if (times[i] >= 0.25 * T && times[i] <= 0.75 * T)
      {
        force += driver_force[i];
        ++n_plateau;
        work   = external_work[i];
        t_work = times[i];
      }
  force /= std::max(n_plateau, 1u);
  // Energy error: largest over the run, and over its second half (where
  // the checked bound applies, see the header).
  double       max_error = 0., max_late_error = 0., t_max_error = 0.;
  unsigned int step_max_error = 0;
  for (unsigned int i = 0; i < times.size(); ++i)
    {
      if (energy_error[i] > max_error)
        {
          max_error      = energy_error[i];
          t_max_error    = times[i];
          step_max_error = i;
        }
      if (times[i] >= 0.5 * T)
        max_late_error = std::max(max_late_error, energy_error[i]);
    }
  // Kinetic energy with the mean velocity of the two half steps exceeds
  // the one the scheme conserves by about this much at a velocity-step
  // front (see the header).
  const double h            = length / n_along;
  const double front_excess = rho * model.area() * h * v0 * v0 / 8.;
  // Least-squares slope of the reaction of the plane x = 0 over time,
  // while the loaded length grows (front before the free end).
  double       mean_t = 0., mean_r = 0.;
  unsigned int n_fit = 0;
  for (unsigned int i = 0; i < times.size(); ++i)
    if (times[i] >= 0.1 * T && times[i] <= 0.45 * T)
      {
        mean_t += times[i];
        mean_r += plane_force[i];
        ++n_fit;
      }
  mean_t /= std::max(n_fit, 1u);
  mean_r /= std::max(n_fit, 1u);
  double stt = 0., str = 0.;
  for (unsigned int i = 0; i < times.size(); ++i)
    if (times[i] >= 0.1 * T && times[i] <= 0.45 * T)
      {
        stt += (times[i] - mean_t) * (times[i] - mean_t);
        str += (times[i] - mean_t) * (plane_force[i] - mean_r);
      }
  const double plane_slope = (stt > 0. ? str / stt : 0.);

  bool arrived = true;
  for (const double t : front.t)
    arrived = arrived && (t > 0.);
  const double force_exact = rho * c_d * model.area() * v0;
  const double slope_exact = lambda * v0 * width;
  const double work_exact  = force_exact * v0 * t_work;
  const double speed_error = std::abs(front.speed - c_d) / c_d;
  const double force_error = std::abs(force - force_exact) / force_exact;
  // The plane x = 0 pushes the bar in +x.
  const double slope_error = std::abs(plane_slope - slope_exact) / slope_exact;
  const double work_error  = std::abs(work - work_exact) / work_exact;
  const double lateral_bound = 1e-12 * v0 * times.back();

  if (root)
    {
      auto &out = testing::out();
      out << "Bar " << width << " x " << width << " x " << length << " mm, "
          << model.triangulation.n_global_active_cells()
          << " hexahedra, lateral faces on symmetry planes, end z = 0 driven "
             "at v0 = "
          << v0 << " mm/ms; E = " << E << " GPa, nu = " << nu
          << ", rho = " << rho << " kg/mm^3" << std::endl;
      out << "constraint groups:";
      for (const std::string &name : constraints.group_names())
        out << " '" << name << "'";
      out << std::endl << std::setprecision(4);
      for (unsigned int s = 0; s < stations.size(); ++s)
        out << "front at z = " << front.z[s] << " mm: t = " << front.t[s]
            << " ms" << std::endl;
      out << "fitted front speed " << front.speed
          << " mm/ms, c_d = sqrt((lambda + 2 mu)/rho) = " << c_d
          << " mm/ms, error " << std::fixed << std::setprecision(2)
          << 100. * speed_error << " %" << std::endl;
      out << std::defaultfloat << std::setprecision(4)
          << "driven end reaction (mean over [0.25, 0.75] 2L/c_d): " << force
          << " kN, rho c_d A v0 = " << force_exact << " kN, error "
          << std::fixed << std::setprecision(2) << 100. * force_error << " %"
          << std::endl;
      out << std::defaultfloat << std::setprecision(4)
          << "reaction of the plane x = 0, slope over [0.1, 0.45] 2L/c_d: "
          << plane_slope << " kN/ms, lambda v0 a = " << slope_exact
          << " kN/ms, error " << std::fixed << std::setprecision(2)
          << 100. * slope_error << " %" << std::endl;
      out << std::defaultfloat << std::setprecision(4)
          << "external work at t = " << t_work << " ms: " << work
          << " J, rho c_d A v0^2 t = " << work_exact << " J, error "
          << std::fixed << std::setprecision(2) << 100. * work_error << " %"
          << std::endl;
      out << "relative energy error: largest " << testing::sci(max_error)
          << " (step " << step_max_error << ", t = " << std::defaultfloat
          << t_max_error << " ms), largest for t >= L/c_d "
          << testing::sci(max_late_error) << std::endl;
      out << "energy residual E_kin + E_int + W_bv - E_0 - W_ext at the end "
          << testing::sci(energy_residual.back())
          << " J (rho A h v0^2 / 8 = " << testing::sci(front_excess) << " J)"
          << std::endl;
      out << "largest |u_x|, |u_y| over the run: on the symmetry planes "
          << testing::sci(max_on_planes) << " mm, between them "
          << testing::sci(max_between_planes) << " mm" << std::endl;
    }
  testing::check(arrived, "the front reaches every station");
  testing::check(speed_error < 0.02, "wave speed within 2 %");
  testing::check(force_error < 0.03, "driven end reaction within 3 %");
  testing::check(slope_error < 0.03, "symmetry plane reaction within 3 %");
  testing::check(work_error < 0.03, "external work within 3 %");
  testing::check(max_late_error < 1e-3,
                 "energy error below 1e-3 for t >= L / c_d");
  testing::check(max_on_planes == 0.,
                 "no normal displacement on the symmetry planes");
  testing::check(max_between_planes <= lateral_bound,
                 "no lateral displacement between the planes (symmetry)");
}
