#ifndef rubberdyn_elements_mixed_up_elements_h
#define rubberdyn_elements_mixed_up_elements_h

#include <deal.II/base/partitioner.h>
#include <deal.II/base/point.h>

#include <rubberdyn/base/vector.h>
#include <rubberdyn/elements/implicit_elements.h>
#include <rubberdyn/elements/solid_hex_elements.h>

#include <array>
#include <functional>
#include <string>
#include <vector>

namespace dealii
{
  template <int dim, int spacedim>
  class DoFHandler;
}

namespace rubberdyn
{
  namespace elements
  {
    /**
     * The mixed u-p hexahedron of the quasi-static solver: triquadratic
     * displacement (Q2, 27 nodes, 3x3x3 Gauss points) with a pressure
     * $\tilde p$ and a dilatation $\tilde J$ that are discontinuous linear
     * polynomials of the reference position X on each cell (P1, four
     * coefficients each), both condensed cell by cell: the three-field
     * Hu-Washizu element of step-44 (Q2-DGP1-DGP1; Simo, Taylor and Pister,
     * CMAME 51 (1985) 177-208), with the law evaluated at the modified
     * deformation gradient
     * @f[
     *   \tilde F = (\tilde J/J)^{1/3} F ,
     * @f]
     * whose isochoric part is that of F and whose determinant is
     * $\tilde J$. For a law $W = \Psi_{iso}(\bar F) + U(J)$ (Yeoh) the
     * functional $\int W(\tilde F) + \tilde p (J - \tilde J)\,dV$ is
     * step-44's. Because $\tilde p$ and $\tilde J$ live in the same space,
     * the stationarity in $\tilde p$ makes $\tilde J$ the cell-wise
     * $L^2$ projection $\Pi J$ of J, the stationarity in $\tilde J$ makes
     * $\tilde p = \Pi(\tfrac13\operatorname{tr}\tilde\tau / \tilde J)$, and
     * the condensed element is the gradient of the reduced energy
     * $E(u) = \sum_q w_q W(\tilde F_q)$, $\tilde J = \Pi J(u)$:
     * @f[
     *   f_a = \sum_q w_q \left[\tilde\tau - \tilde p_\tau I + J \tilde p\, I
     *     \right] g_a ,\qquad g_a = F^{-T}\nabla_X N_a,
     *   \quad \tilde p_\tau = \tfrac13 \operatorname{tr}\tilde\tau ,
     * @f]
     * with $\tilde\tau = \tau(\tilde F)$; its tangent is the exact
     * derivative, symmetric for a hyperelastic law (doc/theory.md,
     * section 11). Pressure and dilatation never appear as global dofs.
     *
     * Quasi-static only (no lumped mass, no stable step); hyperelastic laws
     * only (a law with history is refused in initialize()).
     */
    class MixedUPElements : public ImplicitElements
    {
    public:
      /** Displacement nodes per element (Q2). */
      static constexpr unsigned int n_nodes = 27;
      /** Gauss points per element (3x3x3). */
      static constexpr unsigned int n_q = 27;
      /** Coefficients of the P1 pressure and dilatation per element. */
      static constexpr unsigned int n_p = 4;

      /**
       * Precompute the geometry of the locally owned cells of
       * @p dof_handler (FESystem of three FE_Q(2)) whose material id is in
       * one of @p groups; the groups' formulation must be
       * Formulation::mixed_up.
       *
       * @throw std::invalid_argument if the finite element is not
       *   FE_Q(2)^3, a group has no law, a different formulation or a law
       *   with history, or a material id is in two groups.
       */
      void
      initialize(
        const DoFHandler<3, 3>                                   &dof_handler,
        const std::shared_ptr<const Utilities::MPI::Partitioner> &partitioner,
        const std::vector<ElementGroup>                          &groups);

      unsigned int
      n_dofs_per_element() const override
      {
        return 3 * n_nodes;
      }

      unsigned int
      n_groups() const override
      {
        return group_laws.size();
      }

      /** Number of locally owned elements. */
      unsigned int
      n_elements() const
      {
        return elements.size();
      }

      /**
       * The condensed internal force (kN) at @p u (ghosted, mm) added into
       * @p f, the stored energy $\sum_q w_q W(\tilde F_q)$ (J); an element
       * fails if $J \le 0$ or $\tilde J \le 0$ at a Gauss point
       * (FailureKind::inverted_gauss_point) or the law cannot evaluate
       * $\tilde F$.
       */
      void
      compute_residual(const VectorType  &u,
                       VectorType        &f,
                       ElementStepResult &result) override;

      /**
       * The exact tangent of compute_residual()'s force: 81 x 81 per
       * element, rows and columns 3 a + i (doc/theory.md, section 11.3).
       *
       * @throw materials::InvertedMaterialError if the law cannot evaluate
       *   an element (call compute_residual() first: it reports failures).
       */
      void
      compute_tangents(
        const VectorType &u,
        const std::function<void(const unsigned int *dofs, const double *K)>
          &add) const override;

      /** Always false: laws with history are refused. */
      bool
      has_history() const override
      {
        return false;
      }

      /** Nothing to accept (no history). */
      void
      accept_history() override
      {}

      /**
       * The condensed fields of locally owned element @p e at @p u: the
       * dilatation $\tilde J$ and the Cauchy pressure $\tilde p$ (GPa,
       * positive in tension) at its Gauss points, for tests and output.
       */
      void
      condensed_fields(const VectorType        &u,
                       const unsigned int       e,
                       std::array<double, n_q> &dilatation,
                       std::array<double, n_q> &pressure) const;

      /**
       * Cell averages over the Gauss points (weighted by the reference
       * volume) of the Cauchy stress $\sigma = (\tau - p_\tau 1 + J \tilde
       * p\, 1)/J$ of the three-field element, its von Mises stress and
       * pressure, and of J.
       */
      CellAverages
      cell_averages(const VectorType  &u,
                    const unsigned int n_active_cells) const override;

    private:
      /** What one element keeps (reference configuration). */
      struct Element
      {
        /** Local dof indices, node a component i at 3 a + i. */
        unsigned int dofs[3 * n_nodes];
        /** grad_X N_a at Gauss point q, [q][a][c] (1/mm). */
        double grad[n_q][n_nodes][3];
        /** Gauss weight times reference Jacobian (mm^3). */
        double JxW[n_q];
        /** P1 basis 1, (X - X_c)/h at the Gauss points, [q][k]. */
        double phi[n_q][n_p];
        /** Inverse of the P1 mass matrix sum_q w_q phi_k phi_l (1/mm^3). */
        double mass_inverse[n_p][n_p];
        /** Index of its group. */
        unsigned int group;
        /** Cell id and reference centre, for failure reports. */
        std::string cell_id;
        /** The cell's active cell index (output). */
        unsigned int active_cell_index;
        Point<3>    centre;
      };

      /**
       * The kinematics of one element at @p u: F, J, g_a at the Gauss points,
       * tilde J, and the law at tilde F (with its tangent if
       * @p with_tangent). Returns false (with @p message) if it fails.
       */
      struct State;
      bool
      evaluate(const Element &element,
               const double  *u_local,
               const bool     with_tangent,
               State         &state,
               std::string   &message) const;

      std::vector<Element>                             elements;
      std::vector<const materials::MaterialModel<3> *> group_laws;
    };
  } // namespace elements
} // namespace rubberdyn

#endif
