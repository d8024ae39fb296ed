#ifndef rubberdyn_materials_material_model_h
#define rubberdyn_materials_material_model_h

#include <deal.II/base/array_view.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <rubberdyn/base/parameter_tools.h>

#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

namespace rubberdyn
{
  /**
   * Constitutive laws: from the deformation gradient (and, for
   * history-dependent laws, the state at the start of the step) to the
   * Kirchhoff stress, the consistent spatial tangent, the strain-energy
   * density and the dilatational wave speed.
   *
   * Units are those of the whole code: mm, ms, kg, kN, GPa; energy density
   * in GPa = kN mm / mm^3 = J/mm^3 (J = joule here), wave speed in mm/ms.
   */
  namespace materials
  {
    using namespace dealii;

    /**
     * What a material law returns at one material point.
     */
    template <int dim>
    struct MaterialResponse
    {
      /**
       * Kirchhoff stress $\tau = J \sigma$ (GPa).
       */
      SymmetricTensor<2, dim> kirchhoff_stress;

      /**
       * Consistent spatial tangent $\mathfrak{c} = J \mathbb{c}$ (GPa): the
       * push-forward of $2\,\partial S/\partial C$, or for inelastic laws the
       * algorithmic tangent of the stress update. It is defined by the
       * directional derivative of the Kirchhoff stress for a perturbation
       * $\delta F$ of the deformation gradient, with $l = \delta F F^{-1}$:
       * @f[
       *   \delta\tau = \mathfrak{c} : \mathrm{sym}(l) + l\,\tau + \tau\,l^T .
       * @f]
       * It has the minor symmetries; the algorithmic tangent of J2
       * plasticity lacks the major one. Filled only when requested.
       */
      SymmetricTensor<4, dim> spatial_tangent;

      /**
       * Stored (elastic) strain-energy density per unit reference volume
       * (GPa = J/mm^3).
       */
      double strain_energy_density = 0.;

      /**
       * Current dilatational (P-) wave speed $c$ (mm/ms) that the explicit
       * solver's stable time step uses, $\Delta t \le l / c$.
       */
      double dilatational_wave_speed = 0.;
    };


    /**
     * A constant that a law computes from its input (a modulus, a wave
     * speed, a slope), with the entries it comes from, so that a value that
     * overflows or underflows is refused with a message naming them (see
     * check_derived_constants()).
     */
    struct DerivedConstant
    {
      /** The quantity and how it is derived, e.g. "the shear modulus G =
       * 2 C10". */
      std::string what;
      /** Its value. */
      double value;
      /** Its unit, e.g. "GPa" (empty if dimensionless). */
      std::string unit;
      /**
       * The entries of the law's subsection it is computed from, the one
       * most likely at fault first (e.g. {"Young's modulus", "Poisson's
       * ratio"}).
       */
      std::vector<std::string> entries;
      /** The sign it must have. */
      parameter_tools::Sign sign = parameter_tools::Sign::positive;
    };


    /**
     * Interface of every constitutive law. A law is constructed once per
     * part from its parameter subsection and is then shared, read-only, by
     * all of that part's material points; per-point history lives outside
     * the law, in arrays of `n_state_variables()` doubles per point, so
     * the solver owns all state (and can checkpoint or hand it over).
     *
     * All laws work in three dimensions internally. For `dim == 2` the
     * deformation is plane strain ($F_{33} = 1$), and the returned stress
     * and tangent are the in-plane components.
     */
    class StressKernel;

    template <int dim>
    class MaterialModel
    {
    public:
      virtual ~MaterialModel() = default;

      /** The law's name, as registered. */
      virtual std::string
      name() const = 0;

      /** Mass density in the reference configuration (kg/mm^3). */
      virtual double
      density() const = 0;

      /**
       * Number of history variables stored per material point (0 for
       * hyperelastic laws).
       */
      virtual unsigned int
      n_state_variables() const;

      /**
       * Write the history of an undeformed, virgin material point.
       */
      virtual void
      initialize_state(const ArrayView<double> &state) const;

      /**
       * The equivalent plastic strain $\alpha$ (-) held in the history
       * @p state of a point (size n_state_variables()), for the ParaView
       * field `equivalent_plastic_strain`; 0 for a law without plasticity
       * (the default).
       */
      virtual double
      equivalent_plastic_strain(const ArrayView<const double> &state) const;

      /**
       * Evaluate the law at deformation gradient @p F.
       *
       * @param F Deformation gradient at the end of the step.
       * @param state_old History at the start of the step (size
       *   n_state_variables()); not changed.
       * @param state_new History at the end of the step, written.
       * @param compute_tangent Whether to fill the spatial tangent (the
       *   explicit solver does not need it).
       * @param response Result.
       *
       * @throws InvertedMaterialError if $\det F \le 0$.
       */
      virtual void
      evaluate(const Tensor<2, dim> &         F,
               const ArrayView<const double> &state_old,
               const ArrayView<double> &      state_new,
               const bool                     compute_tangent,
               MaterialResponse<dim> &        response) const = 0;

      /**
       * Dilatational wave speed of the undeformed material, $\sqrt{(K +
       * \tfrac43 G)/\rho}$ (mm/ms).
       */
      virtual double
      reference_wave_speed() const = 0;

      /**
       * Small-strain shear modulus $G$ (GPa).
       */
      virtual double
      shear_modulus() const = 0;

      /**
       * Small-strain bulk modulus $K$ (GPa).
       */
      virtual double
      bulk_modulus() const = 0;

      /**
       * Every constant the law computes from its input and uses: at least
       * the density, G, K and the reference wave speed, and whatever else
       * the law derives (coefficients, inverse compliances, hardening
       * slopes), each with the entries it comes from.
       * registry::create() refuses a law whose constants are not all
       * finite, normal and of their sign (check_derived_constants()).
       */
      virtual std::vector<DerivedConstant>
      derived_constants() const = 0;

      /**
       * Write the resolved constants (what the law actually uses, after
       * conversions from the user's input) to @p out, one per line.
       */
      virtual void
      print_constants(std::ostream &out) const = 0;

      /**
       * A batched 3D kernel of this law for the explicit elements (see
       * StressKernel), or nullptr if the law has none and is to be
       * evaluated point by point. It must give the same results as
       * evaluate() to rounding (tests/materials/stress_kernels).
       */
      virtual std::unique_ptr<StressKernel>
      create_stress_kernel() const;
    };


    /**
     * Throw an InputError unless every one of @p law's derived_constants()
     * is a finite, normal number of its sign. The error names the first
     * entry the offending constant comes from, under @p path (the law's
     * subsection, e.g. "Materials/Rubber"), and mentions the others.
     */
    template <int dim>
    void
    check_derived_constants(const MaterialModel<dim> &law,
                            const std::string        &path);


    /**
     * Helpers shared by the laws: they work in 3D and are wrapped for
     * plane strain.
     */
    namespace internal
    {
      /**
       * Embed a `dim`-dimensional deformation gradient in 3D (plane strain:
       * $F_{33} = 1$, no out-of-plane shear).
       */
      template <int dim>
      Tensor<2, 3>
      embed_in_3d(const Tensor<2, dim> &F);

      /**
       * The in-plane part of a 3D response.
       */
      template <int dim>
      void
      restrict_from_3d(const MaterialResponse<3> &response_3d,
                       const bool                 with_tangent,
                       MaterialResponse<dim> &    response);

      /**
       * $\delta\tau = \mathfrak{c} : \mathrm{sym}(l) + l\tau + \tau l^T$ with
       * $l = \delta F F^{-1}$: the change of Kirchhoff stress predicted by a
       * response for a perturbation @p dF of @p F. Used by Newton solvers on
       * homogeneous deformations and by the tangent tests.
       */
      template <int dim>
      Tensor<2, dim>
      kirchhoff_stress_derivative(const MaterialResponse<dim> &response,
                                  const Tensor<2, dim> &       F,
                                  const Tensor<2, dim> &       dF);
    } // namespace internal
  }   // namespace materials
} // namespace rubberdyn

#endif
