#ifndef rubberdyn_elements_implicit_elements_h
#define rubberdyn_elements_implicit_elements_h

#include <rubberdyn/base/vector.h>

#include <functional>
#include <vector>

namespace rubberdyn
{
  namespace elements
  {
    struct ElementStepResult;

    /** Cell averages of the Gauss-point values, for output. */
    struct CellAverages
    {
      /** All values zero for @p n_active_cells cells. */
      explicit CellAverages(const unsigned int n_active_cells = 0)
        : von_mises(n_active_cells, 0.f)
        , pressure(n_active_cells, 0.f)
        , jacobian(n_active_cells, 0.f)
        , equivalent_plastic_strain(n_active_cells, 0.f)
      {
        for (std::vector<float> &component : cauchy_stress)
          component.assign(n_active_cells, 0.f);
      }

      /** Cauchy stress components xx, yy, zz, xy, xz, yz (GPa). */
      std::vector<float> cauchy_stress[6];
      /** Von Mises stress (GPa). */
      std::vector<float> von_mises;
      /** Pressure, positive in compression (GPa). */
      std::vector<float> pressure;
      /** Jacobian determinant J. */
      std::vector<float> jacobian;
      /** Equivalent plastic strain (-; 0 for laws without plasticity). */
      std::vector<float> equivalent_plastic_strain;
    };

    /**
     * What the quasi-static Newton solver (time_integration::QuasiStaticSolver)
     * needs of an element layer: the residual (internal force at zero
     * velocity) with its stored energy, the consistent tangent element by
     * element, and the history of inelastic laws. Implemented by
     * SolidHexElements (Q1, F-bar or displacement: the explicit engine's
     * force) and MixedUPElements (Q2 with condensed pressure and dilatation,
     * quasi-static only), so that one Newton loop serves both
     * (doc/theory.md, sections 10 and 11).
     */
    class ImplicitElements
    {
    public:
      virtual ~ImplicitElements() = default;

      /**
       * Number of dofs of one element: the size of the index array and the
       * side of the matrix passed to compute_tangents()'s callback (24 for
       * the trilinear hexahedron, 81 for the triquadratic one).
       */
      virtual unsigned int
      n_dofs_per_element() const = 0;

      /** Number of element groups (parts). */
      virtual unsigned int
      n_groups() const = 0;

      /**
       * Cell averages of the Cauchy stress, von Mises stress, pressure, J
       * and the equivalent plastic strain at displacement @p u, one value
       * per active cell in the order of the triangulation's active cell
       * iterator (locally owned cells filled, the others zero): the
       * ParaView fields.
       */
      virtual CellAverages
      cell_averages(const VectorType  &u,
                    const unsigned int n_active_cells) const = 0;

      /**
       * The internal force $f_{int}(u)$ (kN) at displacement @p u (ghosted,
       * mm), added into @p f (ghost entries included: the caller compresses
       * with add), and the stored energy (J) in @p result (overwritten,
       * ElementStepResult: internal_energy, internal_energy_by_group,
       * failure). Element failures are reported in @p result, not thrown.
       * The new history of inelastic laws is kept until accept_history().
       */
      virtual void
      compute_residual(const VectorType  &u,
                       VectorType        &f,
                       ElementStepResult &result) = 0;

      /**
       * The exact tangent $\partial f_{int}/\partial u$ at @p u (ghosted):
       * @p add is called once per locally owned element with its
       * n_dofs_per_element() local dof indices (node a, component i at
       * 3 a + i, indices into the ghosted vectors) and its square matrix,
       * row-major (kN/mm).
       */
      virtual void
      compute_tangents(
        const VectorType &u,
        const std::function<void(const unsigned int *dofs, const double *K)>
          &add) const = 0;

      /**
       * Number of pretension sections cutting the elements (0 if the
       * elements do not take sections). A section s shortens the elements it
       * cuts by its shortening $\delta_s$ (mm): their nodes on the positive
       * side of its plane are seen displaced by $\delta_s n$ (doc/theory.md,
       * section 12), and its force $N_s = \partial \Pi / \partial
       * \delta_s$ is reported in ElementStepResult::section_force.
       */
      virtual unsigned int
      n_sections() const
      {
        return 0;
      }

      /**
       * Set the shortening of every section (mm), used by the following
       * evaluations.
       */
      virtual void
      set_section_shortenings(const std::vector<double> &shortenings);

      /**
       * The coupling of the section shortenings with the dofs, for Newton's
       * method: @p add is called once per locally owned element that a
       * section cuts, with its dof indices (as in compute_tangents()), its
       * section, the columns $K g$ and rows $K^T g$ of the element tangent
       * along the element's unit offset g (the derivative of the element
       * force with respect to the shortening, and of the section force with
       * respect to the dofs; kN/mm), and $g^T K g$ (kN/mm).
       */
      virtual void
      compute_section_couplings(
        const VectorType &u,
        const std::function<void(const unsigned int *dofs,
                                 const unsigned int  section,
                                 const double       *K_g,
                                 const double       *KT_g,
                                 const double        gKg)> &add) const;

      /** Whether a law keeps a history (its tangent is then not symmetric). */
      virtual bool
      has_history() const = 0;

      /** Accept the history of the last compute_residual(). */
      virtual void
      accept_history() = 0;
    };
  } // namespace elements
} // namespace rubberdyn

#endif
