#ifndef rubberdyn_base_simd_math_h
#define rubberdyn_base_simd_math_h

#include <cstdint>
#include <cstring>

/**
 * On x86-64 with GCC, compile the marked function three times, for
 * AVX-512 (x86-64-v4: F, BW, CD, DQ, VL), for AVX2 + FMA (x86-64-v3) and
 * for the baseline, and pick one at load time (an ifunc resolver asks
 * the CPU): the hot loops get 8-wide vectors on CPUs that have them
 * without building the whole code for a particular CPU. The clones may
 * differ in the last bits (FMA contraction), never more.
 */
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#  define RUBBERDYN_VECTOR_CLONES                                  \
    __attribute__((                                               \
      target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
/** Whether the CPU picks one of several versions at load time. */
#  define RUBBERDYN_HAVE_VECTOR_CLONES 1
#else
#  define RUBBERDYN_HAVE_VECTOR_CLONES 0
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

    /**
     * The natural logarithm $\ln x$ for normal positive doubles, to about
     * 1 ulp (checked against std::log over x in [1e-6, 1e6] in
     * tests/materials/stress_kernels), in integer and floating-point
     * arithmetic that GCC vectorises. As in musl's log: x = m 2^e with m in
     * [sqrt(1/2), sqrt(2)), found by moving the bits of sqrt(1/2) to the
     * bottom of the exponent range; then
     * $\ln x = e \ln 2 + 2\,\mathrm{artanh}\, s$, $s = (m-1)/(m+1)$,
     * $|s| \le 0.1716$, whose series $2 s \sum_n s^{2n}/(2n+1)$ is cut
     * after $s^{20}$ (the next term is below $10^{-18}$ relative). The
     * exponent becomes a double through the bits of $2^{52} + e$, since
     * AVX2 has no 64-bit integer conversion. Non-positive, subnormal or
     * non-finite x give garbage, not a trap: callers check J > 0
     * themselves.
     */
    inline double
    natural_log(const double x)
    {
      constexpr std::uint64_t sqrt_half_bits = 0x3fe6a09e667f3bcdULL;
      constexpr std::uint64_t one_bits       = 0x3ff0000000000000ULL;
      constexpr std::uint64_t mantissa_mask  = 0x000fffffffffffffULL;
      std::uint64_t           bits;
      std::memcpy(&bits, &x, sizeof(bits));
      bits += one_bits - sqrt_half_bits;
      // The biased exponent, one higher where the mantissa of x is at
      // least sqrt(2), under the bits of 2^52: minus 2^52 + 1023 gives e.
      std::uint64_t exponent_bits = 0x4330000000000000ULL | (bits >> 52);
      double        e;
      std::memcpy(&e, &exponent_bits, sizeof(e));
      e -= 4503599627370496. + 1023.;
      bits = (bits & mantissa_mask) + sqrt_half_bits;
      double m;
      std::memcpy(&m, &bits, sizeof(m));

      const double s = (m - 1.) / (m + 1.);
      const double z = s * s;
      // sum_{n=1}^{10} z^n/(2n+1), by Horner (a fixed trip count: GCC
      // unrolls it).
      constexpr double coefficients[10] = {1. / 3.,
                                           1. / 5.,
                                           1. / 7.,
                                           1. / 9.,
                                           1. / 11.,
                                           1. / 13.,
                                           1. / 15.,
                                           1. / 17.,
                                           1. / 19.,
                                           1. / 21.};
      double           series           = coefficients[9];
      for (int n = 8; n >= 0; --n)
        series = coefficients[n] + z * series;
      series *= z;
      // ln 2 split so that e * ln2_high is exact (|e| < 2^11).
      constexpr double ln2_high = 6.93147180369123816490e-01;
      constexpr double ln2_low  = 1.90821492927058770002e-10;
      return e * ln2_high + (2. * s + (2. * s * series + e * ln2_low));
    }
  } // namespace simd_math
} // namespace rubberdyn

#endif
