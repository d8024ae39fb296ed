#ifndef rubberdyn_materials_yeoh_stress_kernel_h
#define rubberdyn_materials_yeoh_stress_kernel_h

#include <rubberdyn/materials/stress_kernel.h>
#include <rubberdyn/materials/volumetric_function.h>

#include <array>

namespace rubberdyn
{
  namespace materials
  {
    /**
     * Batched Yeoh law (no history) for the explicit elements: the same
     * formulas as Yeoh::evaluate() without the tangent, written as one loop
     * over points with scalar arithmetic only, which GCC vectorises (8 points
     * per instruction with AVX-512, 4 with AVX2). $J^{-2/3}$ comes from
     * simd_math::inverse_cube_root instead of std::pow, and $\ln J$ (for
     * the logarithmic volumetric functions) from simd_math::natural_log
     * instead of std::log. The loop is compiled once per volumetric
     * function, so the choice costs no branch per point.
     */
    class YeohStressKernel : public StressKernel
    {
    public:
      /**
       * @param C Coefficients C10, C20, C30 (GPa).
       * @param inverse_d 1/d_k of the volumetric term (GPa).
       * @param density Reference density (kg/mm^3).
       * @param volumetric_function Which U(J); the logarithmic ones use
       *   K = 2 inverse_d[0] only.
       */
      YeohStressKernel(const std::array<double, 3> &C,
                       const std::array<double, 3> &inverse_d,
                       const double                 density,
                       const VolumetricFunction     volumetric_function =
                         VolumetricFunction::polynomial);

      unsigned int
      evaluate(const unsigned int n,
               const double *     F,
               const double *     state_old,
               double *           state_new,
               double *           tau,
               double *           energy,
               double *           wave_speed) const override;

    private:
      std::array<double, 3> C;
      std::array<double, 3> inverse_d;
      double                density;
      VolumetricFunction    volumetric_function;
    };
  } // namespace materials
} // namespace rubberdyn

#endif
