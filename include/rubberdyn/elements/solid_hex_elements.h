#ifndef rubberdyn_elements_solid_hex_elements_h
#define rubberdyn_elements_solid_hex_elements_h

#include <deal.II/base/partitioner.h>
#include <deal.II/base/point.h>
#include <rubberdyn/base/vector.h>

#include <rubberdyn/materials/material_model.h>

#include <limits>
#include <map>
#include <memory>
#include <vector>

namespace dealii
{
  template <int dim, int spacedim>
  class DoFHandler;
}

namespace rubberdyn
{
  /**
   * Element kernels: internal forces, lumped mass and stable time step of
   * the solid elements, independent of any time integrator.
   */
  namespace elements
  {
    using namespace dealii;


    /** Where and why an element failed. */
    struct ElementFailure
    {
      /** Whether any element failed in this evaluation. */
      bool failed = false;
      /** The cell, as level.index. */
      std::string cell_id;
      /** Its centre in the reference configuration (mm). */
      Point<3> position;
      /** The material law's message. */
      std::string message;
    };

    /** What one evaluation of all elements returns besides the forces. */
    struct ElementStepResult
    {
      /** Stored strain energy (J = kN mm). */
      double internal_energy = 0.;
      /** Power dissipated by bulk viscosity (kN mm / ms). */
      double bulk_viscosity_power = 0.;
      /** Smallest stable element time step (ms). */
      double min_time_step = std::numeric_limits<double>::max();
      /** Set if an element inverted. */
      ElementFailure failure;
    };

    /** Formulation of the solid element. */
    enum class Formulation
    {
      /** Plain displacement element, 2x2x2 Gauss points (locks). */
      displacement,
      /** F-bar: volumetric part of F taken at the element centre. */
      fbar
    };

    /** Parameters of the element layer. */
    struct ElementSettings
    {
      Formulation formulation = Formulation::fbar;
      /** Linear bulk viscosity coefficient (LS-DYNA Q2, default 0.06). */
      double bulk_viscosity_linear = 0.06;
      /** Quadratic bulk viscosity coefficient (LS-DYNA Q1, default 1.5). */
      double bulk_viscosity_quadratic = 1.5;
    };

    /**
     * Trilinear hexahedra (Q1, 2x2x2 Gauss points) in a total Lagrangian
     * formulation with optional F-bar (de Souza Neto et al., IJSS 33 (1996)
     * 3277-3296): at each Gauss point $\bar F = (J_0/J)^{1/3} F$ with $J_0$
     * the Jacobian at the element centre, and the internal force of node a
     * is the exact derivative of the stored energy,
     * @f[
     *   f_a = \sum_q w_q \left[\bar\tau\, g_a + \tfrac13 \mathrm{tr}\bar\tau
     *          \,(g^0_a - g_a)\right],\quad g_a = F^{-T}\nabla_X N_a,\;
     *   g^0_a = F_0^{-T}\nabla_X N_a(\xi_0).
     * @f]
     * Reference shape gradients, quadrature weights and local dof indices
     * are computed once, so a force evaluation touches no FEValues.
     *
     * Bulk viscosity (LS-DYNA style): in compression a pressure
     * $q = \rho\,l\,(C_q\,l\,\dot\varepsilon_v^2 - C_l\,c\,\dot\varepsilon_v)$
     * is added at every Gauss point; its work is reported. The stable step
     * of an element is $\Delta t_e = l / (Q + \sqrt{Q^2 + c^2})$, $Q = C_l c
     * + C_q l |\dot\varepsilon_v|$ in compression, $l$ = volume / largest
     * face area (current configuration), $c$ the largest current
     * dilatational wave speed of its Gauss points.
     */
    class SolidHexElements
    {
    public:
      /**
       * Precompute element data for the locally owned cells of
       * @p dof_handler (FESystem of three FE_Q(1)).
       *
       * @param material_by_id Law of each material id present in the mesh.
       */
      void
      initialize(const DoFHandler<3, 3> &                         dof_handler,
                 const std::shared_ptr<const Utilities::MPI::Partitioner>
                   &                                               partitioner,
                 const std::map<types::material_id,
                                const materials::MaterialModel<3> *>
                   &                    material_by_id,
                 const ElementSettings &settings);

      /** Number of locally owned elements. */
      unsigned int
      n_elements() const;

      /**
       * Add the row-summed (lumped) mass of every element, scaled by
       * @p density_scaling[e] (1 without mass scaling), to @p mass (ghost
       * entries included: the caller compresses with add).
       */
      void
      add_lumped_mass(VectorType &mass, const std::vector<double> &density_scaling) const;

      /**
       * Stable time step of each element in the reference configuration,
       * without bulk viscosity (for mass scaling).
       */
      std::vector<double>
      reference_time_steps() const;

      /**
       * Internal forces at displacement @p u (ghosted), with bulk viscosity
       * from velocity @p v (ghosted), added into @p f (ghost entries
       * included), and the new history. Elements that invert are reported
       * in the result, not thrown.
       *
       * @param density_scaling Mass-scaling factor per element (wave speed
       *   divided by its square root).
       */
      void
      compute_forces(const VectorType &         u,
                     const VectorType &         v,
                     const std::vector<double> &density_scaling,
                     VectorType &               f,
                     ElementStepResult &        result);

      /** Accept the history computed by the last compute_forces(). */
      void
      accept_history();

      /** Cell averages of the Gauss-point values, for output. */
      struct CellAverages
      {
        /** Cauchy stress components xx, yy, zz, xy, xz, yz (GPa). */
        std::vector<float> cauchy_stress[6];
        /** Von Mises stress (GPa). */
        std::vector<float> von_mises;
        /** Pressure, positive in compression (GPa). */
        std::vector<float> pressure;
        /** Jacobian determinant J. */
        std::vector<float> jacobian;
      };

      /**
       * Cell averages at displacement @p u, one value per active cell in the
       * order of the triangulation's active cell iterator (locally owned
       * cells filled, the others zero).
       */
      CellAverages
      cell_averages(const VectorType &u, const unsigned int n_active_cells) const;

      /** The history of all Gauss points, for checkpoints. */
      std::vector<double> &
      history();

    private:
      static constexpr unsigned int n_nodes = 8;
      static constexpr unsigned int n_q     = 8;

      struct ElementData
      {
        /** Local indices into the ghosted vectors, [node][component]. */
        unsigned int dofs[n_nodes][3];
        /** Reference gradients at the Gauss points, [q][node][direction]. */
        double grad[n_q][n_nodes][3];
        /** Reference gradients at the centre. */
        double grad_centre[n_nodes][3];
        /** Gauss weights times reference Jacobians (mm^3). */
        double JxW[n_q];
        /** Reference nodal coordinates (mm), for the stable step. */
        double X[n_nodes][3];
        /** Index of the law in `laws`. */
        unsigned int law;
        /** Offset of its first Gauss point's history in `history_*`. */
        unsigned int history_offset;
        /** Index of the cell in the active cell iterator order. */
        unsigned int active_cell_index;
        /** Cell id and reference centre, for failure reports. */
        std::string cell_id;
        Point<3>    centre;
      };

      std::vector<ElementData>                       elements;
      std::vector<const materials::MaterialModel<3> *> laws;
      ElementSettings                                settings;
      std::vector<double>                            history_old, history_new;
    };
  } // namespace elements
} // namespace rubberdyn

#endif
