// Speed of the wave front that a step in velocity sends down an elastic
// bar: the explicit engine (F-bar hexahedra, lumped mass, central
// differences, bulk viscosity, penalty contact with a moving rigid body)
// against one-dimensional wave theory (K. F. Graff, Wave Motion in Elastic
// Solids, Dover 1991, ch. 2): the front of a velocity step travels at
//   c = sqrt(E / rho)
// in a thin bar. Acceptance: the speed within 2 %.
//
// The end z = 0 of a bar at rest is pushed at v0 by a rigid plane of 1e6 kg
// (a prescribed-velocity step: the bar's 0.11 kg cannot slow it). Poisson's
// ratio 0 keeps the bar uniaxial, so the three-dimensional dilatational
// speed equals c and no lateral inertia disperses the front. The front
// reaches a station when the mean axial velocity of its cross-section
// reaches v0 / 2; the speed is the least-squares slope of the station
// positions over the arrival times, so a constant delay (the penalty
// spring takes about 3 h / (s c) to pass on the pusher's velocity, see
// bar_wall_impact.cc) drops out. In a lumped-mass mesh the middle of a step
// front moves at the long-wave speed while the Gibbs oscillations around it
// spread; bulk viscosity (defaults) damps them symmetrically about it.
// Stations at 0.2 L ... 0.8 L; the run ends at 0.9 L / c, before the
// reflection from the free end comes back to the last station (1.2 L / c).
#include <deal.II/base/mpi.h>

#include <rubberdyn/materials/elastic.h>

#include "../tests.h"
#include "bar.h"

using namespace dealii;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                   comm = MPI_COMM_WORLD;
  const bool root = (Utilities::MPI::this_mpi_process(comm) == 0);

  // Steel-like, nu = 0 (units mm, ms, kg, kN, GPa); strain v0 / c = 1.9e-4.
  const double E = 210., nu = 0., rho = 7.85e-6, v0 = 1.;
  const double c = std::sqrt(E / rho);
  const rubberdyn::materials::Elastic<3> steel(E, nu, rho);

  // 6 x 6 mm, 3 elements across; 400 mm, 200 elements along.
  const double       width = 6., length = 400.;
  const unsigned int n_across = 3, n_along = 200;
  const bar::Bar     model(width, n_across, length, n_along, comm);

  // Penalty scale 1: stiffer walls are unstable at the default time step
  // scale (see bar_wall_impact.cc).
  const std::vector<double> stations = {0.2 * length,
                                        0.35 * length,
                                        0.5 * length,
                                        0.65 * length,
                                        0.8 * length};
  const bar::FrontArrivals  front    = bar::step_load_front(model,
                                                        steel,
                                                        v0,
                                                        1.,
                                                        /*confined=*/false,
                                                        stations,
                                                        0.9 * length / c);

  bool arrived = true;
  for (const double t : front.t)
    arrived = arrived && (t > 0.);
  const double error = std::abs(front.speed - c) / c;
  if (root)
    {
      auto &out = testing::out();
      out << "Bar " << width << " x " << width << " x " << length << " mm, "
          << model.triangulation.n_global_active_cells()
          << " hexahedra; E = " << E << " GPa, nu = " << nu << ", rho = " << rho
          << " kg/mm^3, step v0 = " << v0 << " mm/ms" << std::endl;
      out << std::setprecision(4);
      for (unsigned int s = 0; s < stations.size(); ++s)
        out << "front at z = " << front.z[s] << " mm: t = " << front.t[s]
            << " ms" << std::endl;
      out << "fitted front speed " << front.speed
          << " mm/ms, c = sqrt(E/rho) = " << c << " mm/ms, error " << std::fixed
          << std::setprecision(2) << 100. * error << " %" << std::endl;
      out << "wave speed within 2 %: " << (error < 0.02 ? "PASS" : "FAIL")
          << std::endl;
    }
  testing::check(arrived, "the front reaches every station");
  testing::check(error < 0.02, "wave speed within 2 %");
}
