#ifndef rubberdyn_elements_solid_hex_elements_h
#define rubberdyn_elements_solid_hex_elements_h

#include <deal.II/base/partitioner.h>
#include <deal.II/base/point.h>
#include <rubberdyn/base/vector.h>

#include <rubberdyn/materials/material_model.h>
#include <rubberdyn/materials/stress_kernel.h>

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


    namespace internal
    {
      constexpr unsigned int n_nodes = 8;
      constexpr unsigned int n_q     = 8;
      /**
       * Elements evaluated together, one per SIMD lane: the hot loops run
       * over lanes innermost, so that GCC turns them into vector
       * instructions (4 doubles with AVX2).
       */
      constexpr unsigned int lanes = 4;

      /**
       * Shape functions on the reference cell $[0,1]^3$ (the same for every
       * element): values $N_a$ at the 2x2x2 Gauss points [q][a] and
       * gradients $\partial N_a / \partial \xi_k$ at the centre [a][k].
       * (Gradients at the Gauss points are applied by sum factorisation.)
       */
      struct ReferenceShapes
      {
        double values[n_q][n_nodes];
        double centre[n_nodes][3];
      };

      /**
       * Geometry of `lanes` elements of one law in structure-of-arrays
       * layout, the last index being the lane. Unused lanes of the last block
       * of a law repeat its first element and are never scattered.
       */
      struct HexBlock
      {
        /** Local indices into the ghosted vectors, [node][component]. */
        unsigned int dofs[n_nodes][3][lanes];
        /**
         * Inverse reference Jacobians $\partial\xi_k/\partial X_c$ at the
         * Gauss points [q][k][c] and at the centre [k][c].
         */
        double inverse_jacobian[n_q][3][3][lanes];
        double inverse_jacobian_centre[3][3][lanes];
        /** Gauss weights times reference Jacobians (mm^3). */
        double JxW[n_q][lanes];
        /** Reference nodal coordinates (mm). */
        double X[n_nodes][3][lanes];
        /** Index of each lane's element in the element numbering. */
        unsigned int element[lanes];
        /** Number of lanes in use. */
        unsigned int n_active;
        /** Index of the law. */
        unsigned int law;
        /**
         * History of Gauss point q of lane l starts at history_offset + (q
         * lanes + l) n_state.
         */
        unsigned int history_offset;
      };
    } // namespace internal



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
      /**
       * F-bar only: stiffness of the volumetric stabilisation relative to the
       * law's small-strain bulk modulus, beta in kappa = beta K (-); 0: none.
       * It resists Gauss-point volume changes at a fixed centre volume,
       * which F-bar otherwise leaves to the shear stiffness alone.
       */
      double fbar_stabilization = 0.;
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
     * Written as $f_a = \sum_q B_q \hat\nabla N_a(\xi_q) + S\,g^0_a$ with
     * $B_q = w_q(\bar\tau - \tfrac13\mathrm{tr}\bar\tau\,I)F^{-T}
     * (\partial\xi/\partial X)^T_q$ and $S = \sum_q w_q \tfrac13
     * \mathrm{tr}\bar\tau$, so only the reference-cell gradients
     * $\hat\nabla N_a$ (the same for every element) and the inverse
     * reference Jacobians are stored; no FEValues is touched per step.
     * Elements are evaluated four at a time (internal::HexBlock), and the
     * law through its batched materials::StressKernel.
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

      /**
       * Number of locally owned elements. Elements are numbered law by law
       * (the numbering of density_scaling and reference_time_steps()).
       */
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
       * Mass (kg) of this rank's elements of each law (in the order of the
       * laws' material ids), with the densities scaled by
       * @p density_scaling; the caller sums over ranks. The difference with
       * and without scaling is the added mass of mass scaling per part.
       */
      std::vector<double>
      mass_by_law(const std::vector<double> &density_scaling) const;

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
      static constexpr unsigned int n_nodes = internal::n_nodes;
      static constexpr unsigned int n_q     = internal::n_q;
      static constexpr unsigned int lanes   = internal::lanes;

      /** Per element, what the hot loop does not need. */
      struct ElementInfo
      {
        /** Block and lane of the element in `blocks`. */
        unsigned int block, lane;
        /** Index of the cell in the active cell iterator order. */
        unsigned int active_cell_index;
        /** Cell id and reference centre, for failure reports. */
        std::string cell_id;
        Point<3>    centre;
      };

      internal::ReferenceShapes              reference;
      std::vector<internal::HexBlock>         blocks;
      std::vector<ElementInfo>                elements;
      std::vector<const materials::MaterialModel<3> *>       laws;
      std::vector<std::unique_ptr<materials::StressKernel>> kernels;
      ElementSettings                         settings;
      std::vector<double>                     history_old, history_new;
    };
  } // namespace elements
} // namespace rubberdyn

#endif
