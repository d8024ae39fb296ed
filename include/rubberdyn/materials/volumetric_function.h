#ifndef rubberdyn_materials_volumetric_function_h
#define rubberdyn_materials_volumetric_function_h

#include <string>

namespace rubberdyn
{
  namespace materials
  {
    /**
     * The volumetric strain-energy function U(J) of a decoupled law
     * $W = \bar W(\bar I_1) + U(J)$ (doc/theory.md, "Volumetric
     * functions"). All three have $U(1) = U'(1) = 0$ and $U''(1) = K$, so
     * the small-strain bulk modulus, the wave speed at rest and the stable
     * step do not depend on the choice; they differ at finite volume change.
     */
    enum class VolumetricFunction
    {
      /**
       * The reference study's $U = \sum_{k=1}^3 (1/d_k)(J-1)^{2k}$
       * (Centeno 2009, eq. 3.16), $K = 2/d_1$. Stays finite as $J \to 0$
       * ($U(0) = \sum_k 1/d_k$), so a point can be crushed with finite
       * work: a Newton iteration started far away may find a spurious state
       * of tiny volume.
       */
      polynomial,
      /**
       * $U = \frac K2 (\ln J)^2$, quadratic in the logarithmic volume
       * strain: $U \to \infty$ as $J \to 0$ and as $J \to \infty$; the
       * Kirchhoff pressure $J U' = K \ln J$ and $J^2 U'' = K(1 - \ln J)$,
       * so U is not convex beyond $J = e$ (Doll & Schweizerhof, J. Appl.
       * Mech. 67 (2000) 17-21, compare these functions).
       */
      log_squared,
      /**
       * $U = \frac K4 (J^2 - 1 - 2 \ln J)$ (Simo & Taylor, Comput. Methods
       * Appl. Mech. Eng. 35 (1982) 107-118; Ogden's
       * $\beta = -2$ volumetric function): convex for all $J > 0$,
       * $U \to \infty$ as $J \to 0$ and as $J \to \infty$;
       * $J U' = \frac K2 (J^2 - 1)$, $J^2 U'' = \frac K2 (J^2 + 1)$.
       */
      simo_taylor
    };

    /** Valid 'Volumetric function' entries, '|'-separated. */
    std::string
    volumetric_function_names();

    /** The function of a name in volumetric_function_names(). */
    VolumetricFunction
    volumetric_function_from_name(const std::string &name);

    /** The name of @p function as the parameter file spells it. */
    std::string
    volumetric_function_name(const VolumetricFunction function);

    /**
     * U(J) and the two combinations that enter the Kirchhoff stress and
     * the spatial tangent (doc/theory.md): the Kirchhoff pressure $J U'$
     * and $J^2 U''$. Energies per reference volume (GPa).
     */
    struct VolumetricValues
    {
      double U;
      double J_dU;
      double J2_d2U;
    };

    /**
     * The two logarithmic functions at J > 0 with bulk modulus @p K (GPa),
     * given @p log_J = ln J: the scalar law passes std::log(J), the batched
     * kernel its vectorisable simd_math::natural_log(J), so that both share
     * one formula. Inline and branch-free in the function, which the
     * caller fixes outside its loop.
     */
    template <VolumetricFunction function>
    inline VolumetricValues
    logarithmic_volumetric_values(const double J,
                                  const double log_J,
                                  const double K)
    {
      static_assert(function != VolumetricFunction::polynomial,
                    "the polynomial is evaluated by the callers");
      if constexpr (function == VolumetricFunction::log_squared)
        return {0.5 * K * log_J * log_J, K * log_J, K * (1. - log_J)};
      else
        {
          // J^2 - 1 as (J - 1)(J + 1): J - 1 is exact near 1, so the
          // pressure keeps its relative accuracy as J -> 1 (J * J - 1 would
          // carry an absolute rounding error of 1e-16).
          const double J2_minus_1 = (J - 1.) * (J + 1.);
          return {0.25 * K * (J2_minus_1 - 2. * log_J),
                  0.5 * K * J2_minus_1,
                  0.5 * K * (J * J + 1.)};
        }
    }
  } // namespace materials
} // namespace rubberdyn

#endif
