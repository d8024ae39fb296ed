// The mortar segment integrals (contact::integrate_mortar_segment()) against
// closed forms, on a slave facet in the plane z = 0 (outward normal +z)
// and master facets facing it (outward normal -z):
//  1. Matching facets, the unit square: D = M = the bilinear quadrilateral's
//     consistent mass matrix, A/9 on the diagonal, A/18 along an edge,
//     A/36 across (e.g. Hughes, The Finite Element Method, 2000, sect. 7.3).
//  2. A master square shifted to [0.5, 1.5] x [0.25, 1.25], 0.1 above: the
//     overlap [0.5, 1] x [0.25, 1] has area 0.375, and the slave rows of D
//     sum to int N_a over it, products of int (1 - x), int x over [0.5, 1]
//     (0.125, 0.375) and int (1 - y), int y over [0.25, 1] (0.28125,
//     0.46875). The rows of M sum to the same (the master's shape functions
//     sum to 1): momentum is exchanged exactly. The weighted gap vector
//     sum_b D_ab x_b - sum_k M_ak x_k is int N_a (x - x_master) = -0.1
//     int N_a in z, i.e. a gap of 0.1 at every node.
//  3. A master diamond (the square turned by 45 degrees about its centre,
//     corners at the slave's edge midpoints): overlap area 0.5, and by
//     symmetry int N_a = 0.125 for every slave corner.
//  4. A trapezoidal slave facet, the matching master: D's sum is its
//     area, 0.75 (the rule is exact for the inverse bilinear map of a
//     trapezoid only approximately: bound 1e-12 on the sum, which is exact
//     whatever the map).
//  5. A master that faces the same way as the slave, and one beside it
//     (no overlap): no segment.
//  6. MasterFacetBounds (the explicit pair's first tests): against 20 000
//     pseudo-random master facets about a warped slave facet (tilted,
//     twisted, of all sizes and orientations, many overlapping it, many
//     just apart), MortarSlaveFacet::integrate() and clearly_open() with
//     the bounds decide and integrate exactly as without them (the bounds
//     may only reject earlier what the box test rejects; every bit of D,
//     M and the slope is compared). Both outcomes are exercised.
// Bound 1e-13 (the rule integrates these quartic products exactly; the
// inverse maps converge to 1e-14 of the facet's size).
#include <rubberdyn/contact/mortar_segment.h>

#include <cmath>

#include "../tests.h"

using namespace dealii;
using namespace rubberdyn;
using testing::check;
using testing::out;
using testing::sci;

namespace
{
  contact::FacetCorners
  square(const double x0,
         const double y0,
         const double size,
         const double z,
         const bool   facing_down)
  {
    contact::FacetCorners c = {{Point<3>(x0, y0, z),
                                Point<3>(x0 + size, y0, z),
                                Point<3>(x0 + size, y0 + size, z),
                                Point<3>(x0, y0 + size, z)}};
    if (facing_down)
      std::swap(c[1], c[3]);
    return c;
  }

  double
  row_sum(const double (&A)[4][4], const unsigned int a)
  {
    return A[a][0] + A[a][1] + A[a][2] + A[a][3];
  }
} // namespace



int
main()
{
  out() << std::setprecision(10);
  contact::MortarSegment      s;
  const contact::FacetCorners slave = square(0., 0., 1., 0., false);

  // 1. Matching facets.
  {
    const contact::FacetCorners master = square(0., 0., 1., 0., true);
    check(contact::integrate_mortar_segment(slave, master, s),
          "matching facets overlap");
    double error = 0.;
    for (unsigned int a = 0; a < 4; ++a)
      for (unsigned int b = 0; b < 4; ++b)
        {
          const unsigned int distance = (a + 4 - b) % 4;
          const double       exact    = distance == 0 ? 1. / 9. :
                                        distance == 2 ? 1. / 36. :
                                                        1. / 18.;
          error = std::max(error, std::abs(s.D[a][b] - exact));
          // The master's corner k sits at the slave's corner (4 - k) % 4.
          error = std::max(error, std::abs(s.M[a][(4 - b) % 4] - exact));
        }
    out() << "1. matching: area " << s.area << ", D[0][0] " << s.D[0][0]
          << ", D[0][1] " << s.D[0][1] << ", D[0][2] " << s.D[0][2]
          << ", largest error " << sci(error) << std::endl;
    check(error < 1e-13, "matching facets: D and M are the mass matrix");
  }

  // 2. Shifted master, 0.1 above.
  {
    const contact::FacetCorners master = square(0.5, 0.25, 1., 0.1, true);
    check(contact::integrate_mortar_segment(slave, master, s),
          "shifted facets overlap");
    const double       int_x[2] = {0.125, 0.375};     // 1 - x, x over [0.5, 1]
    const double       int_y[2] = {0.28125, 0.46875}; // 1 - y, y over [0.25, 1]
    const unsigned int ix[4] = {0, 1, 1, 0}, iy[4] = {0, 0, 1, 1};
    double             error = std::abs(s.area - 0.375);
    for (unsigned int a = 0; a < 4; ++a)
      {
        const double exact = int_x[ix[a]] * int_y[iy[a]];
        error              = std::max(error, std::abs(row_sum(s.D, a) - exact));
        error              = std::max(error, std::abs(row_sum(s.M, a) - exact));
        Tensor<1, 3> weighted;
        for (unsigned int b = 0; b < 4; ++b)
          weighted += s.D[a][b] * slave[b] - s.M[a][b] * master[b];
        error = std::max(error, std::abs(weighted[2] + 0.1 * exact));
        out() << "2. shifted: node " << a << ": int N_a " << row_sum(s.D, a)
              << " (exact " << exact << "), mean gap "
              << -weighted[2] / row_sum(s.D, a) << std::endl;
      }
    out() << "2. shifted: area " << s.area << ", largest error " << sci(error)
          << std::endl;
    check(error < 1e-13, "shifted facets: overlap integrals");
  }

  // 3. Diamond.
  {
    contact::FacetCorners master = {{Point<3>(0.5, 0., 0.),
                                     Point<3>(0., 0.5, 0.),
                                     Point<3>(0.5, 1., 0.),
                                     Point<3>(1., 0.5, 0.)}};
    check(contact::integrate_mortar_segment(slave, master, s),
          "diamond overlaps");
    double error = std::abs(s.area - 0.5);
    for (unsigned int a = 0; a < 4; ++a)
      {
        error = std::max(error, std::abs(row_sum(s.D, a) - 0.125));
        error = std::max(error, std::abs(row_sum(s.M, a) - 0.125));
      }
    out() << "3. diamond: area " << s.area << ", largest error " << sci(error)
          << std::endl;
    check(error < 1e-13, "diamond: overlap integrals");
  }

  // 4. Trapezoid.
  {
    const contact::FacetCorners trapezoid = {{Point<3>(0., 0., 0.),
                                              Point<3>(1., 0., 0.),
                                              Point<3>(0.75, 1., 0.),
                                              Point<3>(0.25, 1., 0.)}};
    contact::FacetCorners       master    = trapezoid;
    std::swap(master[1], master[3]);
    check(contact::integrate_mortar_segment(trapezoid, master, s),
          "trapezoids overlap");
    double sum_D = 0., sum_M = 0.;
    for (unsigned int a = 0; a < 4; ++a)
      {
        sum_D += row_sum(s.D, a);
        sum_M += row_sum(s.M, a);
      }
    out() << "4. trapezoid: area " << s.area << ", sum D " << sum_D
          << ", sum M " << sum_M << std::endl;
    check(std::abs(sum_D - 0.75) < 1e-12 && std::abs(sum_M - 0.75) < 1e-12,
          "trapezoid: D and M sum to the area");
  }

  // 5. No segment.
  {
    const bool same_way =
      contact::integrate_mortar_segment(slave,
                                        square(0., 0., 1., 0.1, false),
                                        s);
    const bool beside =
      contact::integrate_mortar_segment(slave,
                                        square(1.5, 0., 1., 0., true),
                                        s);
    out() << "5. same way: " << same_way << ", beside: " << beside << std::endl;
    check(!same_way && !beside, "no segment");
  }

  // 6. The bounds decide as the tests without them.
  {
    // A linear congruential generator (Knuth's MMIX constants): the same
    // facets on every machine.
    unsigned long long state   = 12345;
    const auto         uniform = [&state](const double a, const double b) {
      state = 6364136223846793005ULL * state + 1442695040888963407ULL;
      return a + (b - a) * double(state >> 11) / double(1ULL << 53);
    };
    const contact::FacetCorners     warped = {{Point<3>(0., 0., 0.),
                                               Point<3>(1.1, 0.05, 0.02),
                                               Point<3>(1.0, 0.9, -0.03),
                                               Point<3>(-0.05, 1.0, 0.01)}};
    const contact::MortarSlaveFacet facet(warped);
    unsigned int overlapping = 0, apart = 0, differing = 0, open = 0;
    for (unsigned int trial = 0; trial < 20000; ++trial)
      {
        // A quadrilateral about a random centre, corners at random radii
        // and angles in order, clockwise seen from +z (facing down), its
        // plane tilted and its corners' heights scattered.
        const double   size = uniform(0.05, 2.);
        const Point<3> centre(uniform(-1.5, 2.5),
                              uniform(-1.5, 2.5),
                              uniform(-0.3, 0.3));
        const double   turn   = uniform(0., 6.283185307179586);
        const double   tilt_x = uniform(-0.5, 0.5), tilt_y = uniform(-0.5, 0.5);
        contact::FacetCorners master;
        for (unsigned int k = 0; k < 4; ++k)
          {
            const double angle =
              turn - k * 1.5707963267948966 + uniform(-0.4, 0.4);
            const double r  = size * uniform(0.4, 0.8);
            const double dx = r * std::cos(angle), dy = r * std::sin(angle);
            master[k] =
              centre +
              Tensor<1, 3>(
                {dx, dy, tilt_x * dx + tilt_y * dy + uniform(-0.02, 0.02)});
          }
        // One in eight faces the slave's way.
        if (trial % 8 == 7)
          std::swap(master[1], master[3]);
        const contact::MasterFacetBounds bounds =
          contact::master_facet_bounds(master);
        contact::MortarSegment without, with;
        const bool             found = facet.integrate(master, without);
        const bool             found_with_bounds =
          facet.integrate(master, with, 4, &bounds);
        overlapping += found;
        bool same = found == found_with_bounds;
        if (found && found_with_bounds)
          {
            for (unsigned int a = 0; a < 4; ++a)
              for (unsigned int b = 0; b < 4; ++b)
                same = same && without.D[a][b] == with.D[a][b] &&
                       without.M[a][b] == with.M[a][b];
            for (unsigned int d = 0; d < 3; ++d)
              same = same && without.slope[d] == with.slope[d];
            same = same && without.area == with.area;
          }
        const bool is_open = facet.clearly_open(master, 1e-3);
        same = same && is_open == facet.clearly_open(master, 1e-3, &bounds);
        open += is_open;
        differing += !same;
        apart += !found;
      }
    out() << "6. bounds: " << overlapping << " of 20000 overlap, " << open
          << " clearly open, " << differing << " decided differently"
          << std::endl;
    check(differing == 0, "the bounds decide and integrate as without");
    check(overlapping > 2000 && apart > 2000, "both outcomes are exercised");
  }
  return 0;
}
