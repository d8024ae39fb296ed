#ifndef rubberdyn_materials_stress_kernel_h
#define rubberdyn_materials_stress_kernel_h

#include <rubberdyn/materials/material_model.h>

#include <memory>

namespace rubberdyn
{
  namespace materials
  {
    /**
     * Batched evaluation of a law's Kirchhoff stress, stored energy and
     * wave speed for the explicit element kernels: many points per call, in
     * structure-of-arrays layout, no tangent, no exceptions. A law that has
     * a hand-written kernel (loops that the compiler vectorises) returns it
     * from MaterialModel::create_stress_kernel(); every other law is
     * evaluated point by point through PointwiseStressKernel. Always 3D.
     *
     * Layout, with a fixed stride N = batch_size (a compile-time stride is
     * what lets GCC vectorise the loops): component (r, c) of F of point i
     * at `F[(3 r + c) N + i]`; Kirchhoff stress components xx, yy, zz, xy,
     * xz, yz (k = 0..5) at `tau[k N + i]`; energy and wave speed at `[i]`;
     * history of point i at `state_old + i n_state` (n_state = the law's
     * n_state_variables()).
     */
    class StressKernel
    {
    public:
      /** Points per batch: the 8 Gauss points of 8 hexahedra. */
      static constexpr unsigned int batch_size = 64;

      virtual ~StressKernel() = default;

      /**
       * Evaluate the first @p n <= batch_size points. @p energy receives the stored energy per
       * reference volume (GPa), @p wave_speed the current dilatational wave
       * speed (mm/ms), both as MaterialModel::evaluate() defines them.
       *
       * @return n if every point was evaluated, otherwise the index of the
       *   first point at which the law failed (det F <= 0 or not finite);
       *   the outputs of the other points are then unspecified. Entries
       *   of points n..batch_size-1 may be overwritten.
       */
      virtual unsigned int
      evaluate(const unsigned int n,
               const double *     F,
               const double *     state_old,
               double *           state_new,
               double *           tau,
               double *           energy,
               double *           wave_speed) const = 0;
    };



    /**
     * The fallback kernel: MaterialModel<3>::evaluate() point by point,
     * with an InvertedMaterialError turned into the returned index.
     */
    class PointwiseStressKernel : public StressKernel
    {
    public:
      /** Wrap @p law, which must outlive the kernel. */
      explicit PointwiseStressKernel(const MaterialModel<3> &law);

      unsigned int
      evaluate(const unsigned int n,
               const double *     F,
               const double *     state_old,
               double *           state_new,
               double *           tau,
               double *           energy,
               double *           wave_speed) const override;

    private:
      const MaterialModel<3> &law;
    };



    /**
     * The law's batched kernel if it has one, else a PointwiseStressKernel
     * around it.
     */
    std::unique_ptr<StressKernel>
    create_stress_kernel(const MaterialModel<3> &law);
  } // namespace materials
} // namespace rubberdyn

#endif
