#ifndef rubberdyn_materials_homogeneous_deformation_h
#define rubberdyn_materials_homogeneous_deformation_h

#include <rubberdyn/materials/material_model.h>

#include <string>

namespace rubberdyn
{
  namespace materials
  {
    /**
     * Homogeneous deformations of one material point, as in a material test:
     * the loaded components of $F$ are prescribed and the others are found
     * by Newton's method so that the unloaded faces are free of stress.
     */
    namespace homogeneous_deformation
    {
      /** The deformation modes. */
      enum class Mode
      {
        /**
         * $F = \mathrm{diag}(\lambda, \mu, \mu)$, $\tau_{22} = \tau_{33} = 0$;
         * only $\tau_{22}$ is driven to zero, $\tau_{33}$ follows by the
         * symmetry of an isotropic point without history transverse to the
         * axis (true for every path this mode itself produces).
         */
        uniaxial_stress,
        /** $F = \mathrm{diag}(\lambda, \lambda, \mu)$, $\tau_{33} = 0$. */
        equibiaxial_stress,
        /** $F = \mathrm{diag}(\lambda, 1, \mu)$, $\tau_{33} = 0$ (planar). */
        pure_shear,
        /** $F = I + \gamma\, e_1 \otimes e_2$. */
        simple_shear,
        /** $F = \lambda I$. */
        dilatation
      };

      /** Names as used in parameter files, '|'-separated. */
      std::string
      mode_names();

      /** Mode from its name (one of mode_names()). */
      Mode
      mode_from_name(const std::string &name);

      /**
       * Deformation gradient for @p mode at load @p load (the stretch
       * $\lambda$, or $\gamma$ for simple shear), with the free lateral
       * stretch @p mu (ignored where there is none).
       */
      Tensor<2, 3>
      deformation_gradient(const Mode mode, const double load, const double mu);

      /**
       * The lateral stretch of an incompressible material in @p mode at
       * @p load: a good first guess for solve() (1 where there is none).
       */
      double
      incompressible_lateral_stretch(const Mode mode, const double load);

      /**
       * Solve for the free lateral stretch at load @p load, starting from
       * @p mu, and leave the response at the solution in @p response and the
       * updated history in @p state_new (from @p state_old).
       *
       * Start from a nearby state (the previous load step, or
       * incompressible_lateral_stretch()): the volumetric term of eq. 3.16
       * (the default 'polynomial' VolumetricFunction) stays finite as
       * $J \to 0$, so far from the solution Newton's method can be drawn
       * towards a spurious state of tiny volume.
       *
       * @return The lateral stretch $\mu$.
       * @throws std::runtime_error if Newton's method does not converge in
       *   50 iterations (stress residual 1e-13 (|tau| + G) + 1e-14 K).
       */
      double
      solve(const MaterialModel<3> &       material,
            const Mode                     mode,
            const double                   load,
            const double                   mu,
            const ArrayView<const double> &state_old,
            const ArrayView<double> &      state_new,
            MaterialResponse<3> &          response);
    } // namespace homogeneous_deformation
  }   // namespace materials
} // namespace rubberdyn

#endif
