// tube_exact_torque PHI...: the exact torque M(phi) (kN mm) of the bonded
// tube of doc/verification/reference_solutions.md §3 (a = 10, b = 20, L = 10 mm, the reference
// study's Yeoh constants C10 = 0.00055, C20 = -5e-5, C30 = 1.5e-5 GPa) at
// each rotation phi (rad) of the outer surface, and the axial force N (kN)
// the ends carry at K/G -> infinity, one "phi M gamma_a N" line
// each, from verification::TubeAzimuthalShear (tube_azimuthal_shear.h,
// tested on its own by tube_azimuthal_shear.cc). A tool for the script
// tests that read a solver's torque column, not a test itself.
#include <cstdio>
#include <cstdlib>

#include "tube_azimuthal_shear.h"

int
main(int argc, char **argv)
{
  const verification::TubeAzimuthalShear tube(10.,
                                              20.,
                                              10.,
                                              0.00055,
                                              -5e-5,
                                              1.5e-5);
  for (int i = 1; i < argc; ++i)
    {
      const double phi = std::strtod(argv[i], nullptr);
      if (phi == 0.)
        {
          std::printf("0 0 0 0\n");
          continue;
        }
      const auto state = tube.at_rotation(phi);
      std::printf("%.12g %.12g %.12g %.12g\n",
                  phi,
                  state.moment,
                  state.inner_shear,
                  tube.end_force(state.moment));
    }
}
