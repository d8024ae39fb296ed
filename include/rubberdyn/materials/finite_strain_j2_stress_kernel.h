#ifndef rubberdyn_materials_finite_strain_j2_stress_kernel_h
#define rubberdyn_materials_finite_strain_j2_stress_kernel_h

#include <rubberdyn/materials/finite_strain_j2.h>
#include <rubberdyn/materials/hardening_curve.h>
#include <rubberdyn/materials/stress_kernel.h>

#include <optional>

namespace rubberdyn
{
  namespace materials
  {
    /**
     * Batched finite-strain J2 update (finite_strain_j2::update() without
     * the tangent) for the explicit elements: the `Elastic` law (no
     * hardening, no history) and `J2 plasticity`. The metals of a bushing
     * are most of its cells, and the point-by-point kernel costs about five
     * times the Yeoh kernel per cell (doc/bushing.md).
     *
     * Three passes over the batch:
     *  1. the elastic trial state $\bar b_e^{tr} = \bar F \bar C_p^{-1}
     *     \bar F^T$, its deviator's norm and $\bar\mu$, in one loop that GCC
     *     vectorises;
     *  2. the yield check and, at yielding points only, the exact
     *     piecewise-linear return (HardeningCurve::solve_return()), point by
     *     point: in an explicit step few points yield, and a trial von
     *     Mises stress below the initial yield stress skips the curve
     *     lookup altogether (the curve never falls below it);
     *  3. stress, stored energy, wave speed and the new history, vectorised
     *     again. An elastic step keeps $\bar C_p^{-1}$ as it was (the
     *     point-by-point update recomputes it as $\bar F^{-1} \bar b_e
     *     \bar F^{-T}$, equal up to round-off).
     *
     * $J^{-1/3}$ comes from simd_math::inverse_cube_root and $\ln J$ from
     * simd_math::natural_log, as in YeohStressKernel; the results agree
     * with MaterialModel::evaluate() to round-off
     * (tests/materials/stress_kernels).
     */
    class FiniteStrainJ2StressKernel : public StressKernel
    {
    public:
      /**
       * @param moduli G, K (GPa) and the density (kg/mm^3).
       * @param hardening The yield curve of `J2 plasticity` (copied; the
       *   history then has finite_strain_j2::n_state_variables entries a
       *   point), or nullptr for the `Elastic` law (no history).
       */
      FiniteStrainJ2StressKernel(const finite_strain_j2::ElasticModuli &moduli,
                                 const HardeningCurve *hardening);

      unsigned int
      evaluate(const unsigned int n,
               const double *     F,
               const double *     state_old,
               double *           state_new,
               double *           tau,
               double *           energy,
               double *           wave_speed) const override;

    private:
      finite_strain_j2::ElasticModuli moduli;
      std::optional<HardeningCurve>   hardening;
    };
  } // namespace materials
} // namespace rubberdyn

#endif
