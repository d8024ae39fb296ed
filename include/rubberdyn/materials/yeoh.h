#ifndef rubberdyn_materials_yeoh_h
#define rubberdyn_materials_yeoh_h

#include <rubberdyn/materials/material_model.h>
#include <rubberdyn/materials/volumetric_function.h>

#include <array>

namespace dealii
{
  class ParameterHandler;
}

namespace rubberdyn
{
  namespace materials
  {
    /**
     * Compressible Yeoh rubber with the isochoric/volumetric split of the
     * reference study (Centeno 2009, eq. 3.16):
     * @f[
     *   W = \sum_{i=1}^{3} C_{i0} (\bar I_1 - 3)^i
     *     + \sum_{k=1}^{3} \frac{1}{d_k} (J - 1)^{2k},
     *   \qquad \bar I_1 = J^{-2/3} I_1 .
     * @f]
     * The volumetric term U(J) can be replaced by $\frac K2 (\ln J)^2$ or
     * $\frac K4 (J^2 - 1 - 2\ln J)$ with the same $K = 2/d_1$
     * (VolumetricFunction; 'Volumetric function' in the parameter file):
     * the study's polynomial stays finite as $J \to 0$, they do not.
     * The Kirchhoff stress is (push-forward of eq. 3.17)
     * @f[
     *   \tau = J U'(J)\, I + 2 W'\, \mathrm{dev}\,\bar b,
     *   \qquad W' = \sum_i i\, C_{i0} (\bar I_1 - 3)^{i-1},
     * @f]
     * and the consistent spatial tangent is derived in doc/theory.md:
     * @f[
     *   \mathfrak{c} = \tfrac43 W' \bar I_1\, \mathbb{P}
     *     - \tfrac23 (\tau_{iso} \otimes I + I \otimes \tau_{iso})
     *     + 4 W''\, \mathrm{dev}\bar b \otimes \mathrm{dev}\bar b
     *     + (J U' + J^2 U'') I \otimes I - 2 J U'\, \mathbb{I}.
     * @f]
     *
     * The constants come from the coefficients themselves, from an initial
     * shear modulus through eq. 3.11 ($C_{10} = G/2$, $C_{20} = -G/20$,
     * $C_{30} = G/200$), or from a Shore A hardness through Gent's relation
     * (A. N. Gent, Trans. Inst. Rubber Ind. 34 (1958) 46-57):
     * $E\,[\mathrm{MPa}] = 0.0981 (56 + 7.62336 S) / (0.137505 (254 - 2.54
     * S))$, $G = E/3$, then eq. 3.11. The volumetric term comes from the $d_k$,
     * or from a bulk modulus $K$ ($d_1 = 2/K$, $d_2 = d_3 = \infty$), or from
     * Poisson's ratio, $K = 2G(1+\nu)/(3(1-2\nu))$ with $G = 2C_{10}$.
     * Neo-Hooke is the special case $C_{20} = C_{30} = 0$.
     */
    template <int dim>
    class Yeoh : public MaterialModel<dim>
    {
    public:
      /**
       * Read the constants from the current subsection of @p prm, whose full
       * path is @p path (for error messages).
       *
       * @throws InputError on invalid constants.
       */
      Yeoh(const ParameterHandler &prm, const std::string &path);

      /**
       * Construct from the constants directly (GPa, 1/GPa, kg/mm^3). An
       * entry of @p d equal to zero omits that volumetric term; d[0] must be
       * positive. With a logarithmic @p volumetric_function, K = 2/d[0] and
       * d[1], d[2] must be zero.
       */
      Yeoh(const double                 C10,
           const double                 C20,
           const double                 C30,
           const std::array<double, 3> &d,
           const double                 density,
           const VolumetricFunction     volumetric_function =
             VolumetricFunction::polynomial);

      /** Declare the Yeoh entries in the current subsection. */
      static void
      declare_parameters(ParameterHandler &prm);

      /**
       * Gent's (1958) Young's modulus (GPa) for a Shore A hardness.
       */
      static double
      youngs_modulus_from_shore_a(const double hardness);

      std::string
      name() const override;

      double
      density() const override;

      void
      evaluate(const Tensor<2, dim> &         F,
               const ArrayView<const double> &state_old,
               const ArrayView<double> &      state_new,
               const bool                     compute_tangent,
               MaterialResponse<dim> &        response) const override;

      double
      reference_wave_speed() const override;

      double
      shear_modulus() const override;

      double
      bulk_modulus() const override;

      /**
       * The density, C10, 2 C20 and 6 C30 (the largest multiples in the
       * stress and the tangent), G, K, 1/d2, 1/d3 (zero with a logarithmic
       * volumetric function) and the reference wave
       * speed, each with the entries it comes from ('C10', 'Initial shear
       * modulus' or 'Shore A hardness'; 'D1', 'Bulk modulus' or 'Poisson's
       * ratio').
       */
      std::vector<DerivedConstant>
      derived_constants() const override;

      void
      print_constants(std::ostream &out) const override;

      /** A YeohStressKernel with this law's constants. */
      std::unique_ptr<StressKernel>
      create_stress_kernel() const override;

    private:
      /** The 3D evaluation that both dimensions use. */
      void
      evaluate_3d(const Tensor<2, 3> &F,
                  const bool          compute_tangent,
                  MaterialResponse<3> &response) const;

      double C10, C20, C30;

      /**
       * 1/d_k, zero where a term is omitted; K/2 = 1/d_1 for every
       * volumetric function.
       */
      std::array<double, 3> inverse_d;

      double rho;

      /** Which U(J): the study's polynomial or a logarithmic one. */
      VolumetricFunction volumetric_function = VolumetricFunction::polynomial;

      /**
       * The entries C10 (and C20, C30) and the bulk modulus come from, for
       * error messages: 'C10', 'Initial shear modulus' or 'Shore A
       * hardness'; 'D1', 'Bulk modulus' or 'Poisson's ratio'.
       */
      std::string shear_entry = "C10", bulk_entry = "D1";
    };
  } // namespace materials
} // namespace rubberdyn

#endif
