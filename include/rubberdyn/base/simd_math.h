#ifndef rubberdyn_base_simd_math_h
#define rubberdyn_base_simd_math_h

#include <cstdint>
#include <cstring>

/**
 * On x86-64 with GCC, compile the marked function twice, for AVX2 + FMA
 * (x86-64-v3) and for the baseline, and pick one at load time: the
 * hot loops get 4-wide vectors without building the whole code for a
 * particular CPU.
 */
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#  define RUBBERDYN_VECTOR_CLONES \
    __attribute__((target_clones("arch=x86-64-v3", "default")))
#else
#  define RUBBERDYN_VECTOR_CLONES
#endif

namespace rubberdyn
{
  /**
   * Elementary functions written so that GCC vectorises loops that call
   * them (glibc's scalar cbrt/pow are opaque calls that stop vectorisation;
   * its vector library needs -ffast-math, which we do not use because it
   * removes NaN checks).
   */
  namespace simd_math
  {
    /**
     * $x^{-1/3}$ for normal positive doubles, to about 4 ulp (checked
     * against 1/std::cbrt over x in [1e-6, 1e6] in
     * tests/elements/inverse_cube_root). A float bit-level initial guess
     * (relative error below 4 %, Lomont's "fast inverse root" idea applied
     * to the exponent/3) refined by four Newton steps on $y^{-3} = x$,
     * $y \leftarrow y (4 - x y^3) / 3$, each of which squares the relative
     * error (times 2). Non-positive or non-finite x give garbage, not a
     * trap: callers check J > 0 themselves.
     */
    /** Bits of the initial guess of inverse_cube_root(): magic - bits/3. */
    constexpr std::int32_t inverse_cube_root_magic = 0x54a2fa8c;

    /** Newton steps of inverse_cube_root(). */
    constexpr unsigned int inverse_cube_root_newton_steps = 4;

    inline double
    inverse_cube_root(const double x)
    {
      const float  x_float = static_cast<float>(x);
      std::int32_t bits;
      std::memcpy(&bits, &x_float, sizeof(bits));
      bits = inverse_cube_root_magic - bits / 3;
      float y_float;
      std::memcpy(&y_float, &bits, sizeof(bits));
      double y = y_float;
      for (unsigned int k = 0; k < inverse_cube_root_newton_steps; ++k)
        y = y * (4. - x * (y * y * y)) * (1. / 3.);
      return y;
    }
  } // namespace simd_math
} // namespace rubberdyn

#endif
