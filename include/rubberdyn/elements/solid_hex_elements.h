#ifndef rubberdyn_elements_solid_hex_elements_h
#define rubberdyn_elements_solid_hex_elements_h

#include <deal.II/base/partitioner.h>
#include <deal.II/base/point.h>

#include <rubberdyn/base/vector.h>
#include <rubberdyn/elements/implicit_elements.h>
#include <rubberdyn/materials/material_model.h>
#include <rubberdyn/materials/stress_kernel.h>
#include <rubberdyn/model/element_formulation.h>

#include <array>
#include <functional>
#include <limits>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <array>
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
       * instructions (one AVX-512 instruction on 8 doubles; two AVX2 or
       * four SSE2 instructions in the other clones, RUBBERDYN_VECTOR_CLONES).
       */
      constexpr unsigned int lanes = 8;

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
       * Geometry of `lanes` elements of one group in structure-of-arrays
       * layout, the last index being the lane. Unused lanes of the last block
       * of a group repeat its first element, only so that their arithmetic
       * stays finite: the kernel evaluates the law at F = I there and never
       * reports, sums or scatters them.
       */
      struct HexBlock
      {
        // What the explicit kernel reads, first and together (it streams
        // the blocks from memory every step).

        /** Local indices into the ghosted vectors, [node][component]. */
        unsigned int dofs[n_nodes][3][lanes];
        /** Reference nodal coordinates (mm). */
        double X[n_nodes][3][lanes];
        /**
         * Element volume over node a's share of the lumped mass,
         * $V / \int N_a\,dV$ (reference configuration; 8 for a
         * parallelepiped), [a]: the weights of the stable-step length
         * (doc/theory.md section 8.3).
         */
        double inverse_mass_fraction[n_nodes][lanes];
        /** Index of each lane's element in the element numbering. */
        unsigned int element[lanes];
        /** Number of lanes in use. */
        unsigned int n_active;
        /** Index of the element group (all lanes of a block share it). */
        unsigned int group;
        /**
         * History of Gauss point q of lane l starts at history_offset + (q
         * lanes + l) n_state.
         */
        unsigned int history_offset;

        // The reference geometry at the Gauss points, for the tangent and
        // output code; the explicit kernel recomputes it from X
        // (hex_lanes.h, reference_jacobians()).

        /**
         * Inverse reference Jacobians $\partial\xi_k/\partial X_c$ at the
         * Gauss points [q][k][c] and at the centre [k][c].
         */
        double inverse_jacobian[n_q][3][3][lanes];
        double inverse_jacobian_centre[3][3][lanes];
        /** Gauss weights times reference Jacobians (mm^3). */
        double JxW[n_q][lanes];
      };
    } // namespace internal



    /** Why an element failed. */
    enum class FailureKind
    {
      none,
      /** det F <= 0 (or not finite) at the element centre. */
      inverted_centre,
      /** det F <= 0 (or not finite) at a Gauss point. */
      inverted_gauss_point,
      /** The material law could not evaluate F (det F <= 0, not finite). */
      law_failed,
      /**
       * F-bar only: a Gauss point's volume ratio J_q / J_0 fell below
       * ElementSettings::fbar_collapse_ratio (the hull instability of
       * doc/theory.md section 8.1).
       */
      fbar_collapse
    };

    /** Where and why an element failed. */
    struct ElementFailure
    {
      /** Whether any element failed in this evaluation. */
      bool failed = false;
      /** Why (FailureKind::none if nothing failed). */
      FailureKind kind = FailureKind::none;
      /** The cell, as level.index. */
      std::string cell_id;
      /** Its centre in the reference configuration (mm). */
      Point<3> position;
      /**
       * What happened, in one line for the user; for a collapse it names
       * the entry to change.
       */
      std::string message;
    };

    /**
     * What one evaluation of all elements returns besides the forces.
     * SolidHexElements::compute_forces() overwrites every member; keep one
     * object across steps so that internal_energy_by_group is allocated
     * once.
     */
    struct ElementStepResult
    {
      /** Stored strain energy of this rank's elements (J = kN mm). */
      double internal_energy = 0.;
      /**
       * The same per element group, in the order of the groups given to
       * SolidHexElements::initialize() (J); its sum is internal_energy up
       * to round-off.
       */
      std::vector<double> internal_energy_by_group;
      /**
       * Power of the bulk-viscosity forces actually applied,
       * $\sum_a f^{visc}_a \cdot v_a$ with the velocities the forces were
       * computed with (kN mm / ms = J/ms); it is the rate of work the
       * viscous forces take out of the system.
       */
      double bulk_viscosity_power = 0.;
      /**
       * The same per element group (kN mm / ms), ordered like
       * internal_energy_by_group; its sum is bulk_viscosity_power up to
       * round-off.
       */
      std::vector<double> bulk_viscosity_power_by_group;
      /** Smallest stable element time step (ms). */
      double min_time_step = std::numeric_limits<double>::max();
      /** The same without the bulk viscosity's Q (ms). */
      double min_undamped_time_step = std::numeric_limits<double>::max();
      /**
       * Smallest ratio of an element's step with bulk viscosity to the one
       * without, $\sqrt{1+\xi^2}-\xi$ with $\xi = Q/c$ (-; 1 without
       * compression).
       */
      double min_damping_factor = 1.;
      /**
       * Smallest Gauss-point volume ratio $J_q/J_0$ of the F-bar elements
       * (1 if there are none): the margin to
       * ElementSettings::fbar_collapse_ratio.
       */
      double min_volume_ratio = 1.;
      /** Set if an element failed (the first one in element order). */
      ElementFailure failure;
      /**
       * Force across each pretension section from this rank's elements
       * (kN, positive in tension; the caller sums over the ranks):
       * $N_s = \sum_e g_e \cdot f_e$ over the elements it cuts, the
       * derivative of the stored energy with respect to the section's
       * shortening (ImplicitElements::n_sections()).
       */
      std::vector<double> section_force;
    };

    /**
     * The plane of a pretension section and the element group (part) it
     * cuts (SolidHexElements::cut_sections()).
     */
    struct SectionPlane
    {
      /** A point of the plane (mm). */
      Point<3> point;
      /** Its unit normal; the nodes on its side are the offset ones. */
      Tensor<1, 3> normal;
      /** The element group whose elements it cuts. */
      unsigned int group = 0;
    };

    /**
     * What one rank's elements give a cross section
     * (SolidHexElements::section_resultants()); the caller sums over the
     * ranks.
     */
    struct SectionResultant
    {
      /**
       * Sum of the internal forces of the cut elements at their nodes on
       * the normal's side of the plane (kN): the resultant of the traction
       * sigma n on the plane.
       */
      Tensor<1, 3> force;
      /** Sum of x times those forces, x the nodes' current positions (kN mm). */
      Tensor<1, 3> moment_about_origin;
      /** Sum of the cut elements' current centres (mm). */
      Tensor<1, 3> centre_sum;
      /** Number of cut elements. */
      unsigned int n_cut = 0;
    };

    /* The element formulation is chosen per part in the Model
       (model/element_formulation.h). */
    using model::Formulation;

    /**
     * One part of a model as the element layer sees it: the cells whose
     * material id is in @p material_ids get elements of @p formulation
     * evaluated with @p law.
     */
    struct ElementGroup
    {
      /**
       * The group of @p material_ids with @p law and @p formulation; for
       * F-bar, the beta of its volumetric stabilisation
       * @p fbar_stabilization (-, final: the caller has resolved a part's
       * own value against a model-wide one) and the advice a hull
       * collapse's message ends with (@p collapse_advice, composed by the
       * caller, who knows the input entries; empty: none).
       */
      ElementGroup(std::set<types::material_id>       material_ids,
                   const materials::MaterialModel<3> *law,
                   Formulation                        formulation,
                   double                             fbar_stabilization = 0.,
                   std::string                        collapse_advice = "")
        : material_ids(std::move(material_ids))
        , law(law)
        , formulation(formulation)
        , fbar_stabilization(fbar_stabilization)
        , collapse_advice(std::move(collapse_advice))
      {}

      std::set<types::material_id>       material_ids;
      const materials::MaterialModel<3> *law;
      Formulation                        formulation;
      /**
       * F-bar only: stiffness of the volumetric stabilisation relative to
       * the law's small-strain bulk modulus, beta in kappa = beta K (-); 0:
       * none. It resists Gauss-point volume changes at a fixed centre
       * volume, which F-bar otherwise leaves to the shear stiffness alone.
       */
      double fbar_stabilization;
      /**
       * What the user should change after an F-bar hull collapse of this
       * group, e.g. "set Parts/rubber/F-bar stabilization to 0.03 or
       * more"; appended to the failure's message.
       */
      std::string collapse_advice;
    };

    /** Parameters of the element layer, common to all groups. */
    struct ElementSettings
    {
      /** Linear bulk viscosity coefficient (LS-DYNA Q2, default 0.06). */
      double bulk_viscosity_linear = 0.06;
      /** Quadratic bulk viscosity coefficient (LS-DYNA Q1, default 1.5). */
      double bulk_viscosity_quadratic = 1.5;
      /**
       * F-bar only: an element fails (FailureKind::fbar_collapse) when the
       * volume ratio $r_q = J_q/J_0$ of one of its Gauss points falls below
       * this value (-); 0: never. F-bar's hull instability drives $r_q$ to
       * about 0.1 while $J_0$ stays near 1 and the run would go on with a
       * collapsed, unphysical mesh; healthy deep-compression runs stay above
       * about 0.75 (doc/theory.md section 8.1). It also bounds the
       * stabilisation's stiffness, kappa / r_q <= kappa / r_c, in the stable
       * step (section 8.3). Range [0, 1).
       */
      double fbar_collapse_ratio = 0.25;
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
     * Elements are evaluated eight at a time (internal::HexBlock), and the
     * law through its batched materials::StressKernel.
     *
     * Bulk viscosity (LS-DYNA style): in compression a pressure
     * $q = \rho\,l\,(C_q\,l\,\dot\varepsilon_v^2 - C_l\,c\,\dot\varepsilon_v)$
     * is added at every Gauss point; the power of the force it gives is
     * reported. The stable step of an element is $\Delta t_e = l / (Q +
     * \sqrt{Q^2 + c^2})$, $Q = C_l c + C_q l |\dot\varepsilon_v|$ in
     * compression (in the step only from $|\dot\varepsilon_v|\, l / c =
     * 10^{-10}$ on, above the round-off of a rigid motion), $c$ the largest current
     * dilatational wave speed of its Gauss points, with the stiffness of the
     * F-bar stabilisation added, and
     * @f[
     *   l = 2 \Big/ \sqrt{\textstyle\sum_a |g^0_a|^2 / \mu_a},
     * @f]
     * $\mu_a = \int N_a\,dV / V$ the lumped-mass share of node a: the bound
     * of Flanagan and Belytschko (IJNME 17 (1981) 679-706) on the element's
     * largest frequency, $\omega_{max} \le 2c/l$, in the current
     * configuration; $l = h/\sqrt3$ for a cube of side h (doc/theory.md
     * sections 8.1, 8.3, 8.4).
     *
     * A model has several element groups (parts), each with its own law and
     * formulation; blocks never mix groups, and each block is evaluated with
     * its group's formulation. Cells of material ids in no group get no
     * element (rigid parts).
     */
    class SolidHexElements : public ImplicitElements
    {
    public:
      /**
       * Precompute element data for the locally owned cells of
       * @p dof_handler (FESystem of three FE_Q(1)): one element per cell whose
       * material id is in one of @p groups, none for the other cells.
       *
       * @throw std::invalid_argument if a material id is in two groups or a
       *   group has no law (the caller validates user input before).
       */
      void
      initialize(const DoFHandler<3, 3> &dof_handler,
                 const std::shared_ptr<const Utilities::MPI::Partitioner>
                   &                                partitioner,
                 const std::vector<ElementGroup> &groups,
                 const ElementSettings &          settings);

      /** Number of element groups, as given to initialize(). */
      unsigned int
      n_groups() const override;

      /** 24: eight nodes, three components. */
      unsigned int
      n_dofs_per_element() const override
      {
        return 3 * internal::n_nodes;
      }

      /**
       * The quasi-static residual: compute_forces() at zero velocity and
       * without mass scaling (no bulk viscosity), the explicit engine's
       * internal force.
       */
      void
      compute_residual(const VectorType  &u,
                       VectorType        &f,
                       ElementStepResult &result) override;

      /**
       * Number of locally owned elements. Elements are numbered group by
       * group (the numbering of density_scaling and reference_time_steps()).
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
       * Mass (kg) of this rank's elements of each group, with the densities
       * scaled by @p density_scaling; the caller sums over ranks. The
       * difference with and without scaling is the added mass of mass
       * scaling per part.
       */
      std::vector<double>
      mass_by_group(const std::vector<double> &density_scaling) const;

      /**
       * Where element @p e's nodes are and what they weigh: the local
       * indices of the x, y, z dofs of its eight nodes, the lumped
       * (row-summed) mass of each node from this element (kg, unscaled),
       * and the element's group.
       */
      struct NodalMasses
      {
        std::array<std::array<unsigned int, 3>, 8> dofs;
        std::array<double, 8>                      mass;
        /** The nodes' reference positions (mm). */
        std::array<std::array<double, 3>, 8> position;
        unsigned int                               group;
      };
      NodalMasses
      nodal_masses(const unsigned int e) const;

      /**
       * Multiply each element's stable step by @p factors[e] from now on
       * (selective mass scaling: the square root of the factor by which
       * the element's added mass lowers its highest frequency squared).
       * Empty: none.
       */
      void
      set_time_step_factors(std::vector<double> factors);

      /**
       * Stable time step $l/c$ of each element in the reference
       * configuration (the length of the class documentation), without bulk
       * viscosity, with the F-bar stabilisation's stiffness (for mass
       * scaling), times the factors of set_time_step_factors().
       */
      std::vector<double>
      reference_time_steps() const;

      /**
       * Internal forces at displacement @p u (ghosted), with bulk viscosity
       * from velocity @p v (ghosted), added into @p f (ghost entries
       * included), and the new history. Elements that fail (inversion,
       * F-bar collapse) are reported in @p result, not thrown; the forces of
       * a failed element are not added. @p result is overwritten
       * (ElementStepResult).
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

      /**
       * The element stiffness for Newton's method: the exact consistent
       * tangent $K_{ai,bj} = \partial f_{ai} / \partial u_{bj}$ of the
       * internal force that compute_forces() returns at zero velocity (no
       * bulk viscosity), F-bar stabilisation included, with the history of
       * the last accepted state (accept_history()) as the start of the
       * step; for an inelastic law it is the algorithmic tangent (not
       * symmetric); for a hyperelastic law it is symmetric, the force being
       * the gradient of the stored energy (doc/theory.md, section 10). Evaluated
       * element by element in scalar code from the same geometry
       * (internal::HexBlock) as the force kernel
       * (source/elements/solid_hex_tangent.cc).
       *
       * @param u Displacement (ghosted, mm).
       * @param add Called once per locally owned element with its 24 local
       *   dof indices (node a, component i at 3 a + i, indices into the
       *   ghosted vectors) and its 24 x 24 matrix, row-major, rows
       *   3 a + i, columns 3 b + j (kN/mm).
       *
       * @throw materials::InvertedMaterialError if the law cannot evaluate
       *   an element (call compute_forces() first: it reports failures).
       */
      void
      compute_tangents(
        const VectorType &u,
        const std::function<void(const unsigned int *dofs, const double *K)>
          &add) const override;

      /**
       * Whether a law of some group keeps a history (inelastic: its
       * tangent is not symmetric).
       */
      bool
      has_history() const override;

      /** Accept the history computed by the last compute_forces(). */
      void
      accept_history() override;

      /**
       * Let pretension sections cut the elements (after initialize(); once).
       * Section s cuts the elements of its group that have nodes strictly on
       * both sides of its plane (signed distances beyond 1e-9 of the
       * element size); their nodes on the positive side get the unit offset
       * $g = n$, the others none. With a shortening $\delta_s$
       * (set_section_shortenings()) an element then sees its positive nodes
       * at $u_a + \delta_s n$: the cut layer is the stress-free length
       * shorter by $\delta_s$ across the section, and the force through it
       * is $N_s = \partial\Pi/\partial\delta_s = \sum_e g_e\cdot f_e$
       * (doc/theory.md, section 12). Elements without a cut are evaluated as
       * before, at no cost.
       *
       * @return The number of this rank's elements each section cuts (the
       *   caller sums over the ranks and refuses a section that cuts none).
       * @throw std::invalid_argument if an element is cut by two sections.
       */
      std::vector<unsigned int>
      cut_sections(const std::vector<SectionPlane> &sections);

      unsigned int
      n_sections() const override
      {
        return shortenings.size();
      }

      void
      set_section_shortenings(const std::vector<double> &shortenings) override;

      /**
       * The force through each section (kN, this rank's elements; the
       * caller sums over the ranks) at displacement @p u (ghosted), without
       * bulk viscosity, with the accepted history: what compute_forces()
       * reports in ElementStepResult::section_force at zero velocity,
       * evaluating the cut elements only (for output).
       */
      std::vector<double>
      section_forces(const VectorType &u) const;

      /**
       * The resultants through the planes @p planes (cross sections for
       * output, not pretension sections) at displacement @p u (ghosted):
       * for each, the internal forces of this rank's elements of its group
       * that the plane cuts, at their nodes on the normal's side, without
       * bulk viscosity, with the accepted history (as section_forces()).
       * Each call finds the cut elements anew: meant for history rows, not
       * for every step.
       */
      std::vector<SectionResultant>
      section_resultants(const VectorType                &u,
                         const std::vector<SectionPlane> &planes) const;

      /** The current shortenings (mm). */
      const std::vector<double> &
      section_shortenings() const
      {
        return shortenings;
      }

      void
      compute_section_couplings(
        const VectorType &u,
        const std::function<void(const unsigned int *dofs,
                                 const unsigned int  section,
                                 const double       *K_g,
                                 const double       *KT_g,
                                 const double        gKg)> &add) const override;

      using CellAverages = elements::CellAverages;

      /**
       * Cell averages at displacement @p u, one value per active cell in the
       * order of the triangulation's active cell iterator (locally owned
       * cells filled, the others zero).
       */
      CellAverages
      cell_averages(const VectorType  &u,
                    const unsigned int n_active_cells) const override;

      /** The history of all Gauss points, for checkpoints. */
      std::vector<double> &
      history();

      /** The same, read-only. */
      const std::vector<double> &
      history() const
      {
        return history_old;
      }

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

      /** Per group, what the kernel needs. */
      struct GroupData
      {
        const materials::MaterialModel<3> *     law;
        Formulation                             formulation;
        std::unique_ptr<materials::StressKernel> kernel;
        /** Reference density (kg/mm^3). */
        double density;
        /** beta of the F-bar stabilisation (-); 0: none. */
        double stabilization;
        /** kappa = beta K of the F-bar stabilisation (GPa); 0: none. */
        double stabilization_modulus;
        /** What to change after a hull collapse (ElementGroup). */
        std::string collapse_advice;
      };

      /**
       * The exact tangent of element @p element (24 x 24, row-major, rows
       * 3 a + i) at @p u with its section offset, and its dof indices.
       */
      void
      element_tangent(const unsigned int element,
                      const double      *u,
                      unsigned int      *dofs,
                      double            *K) const;

      /**
       * The offsets of the nodes of block @p block (mm, [node][component]
       * [lane]) with the current shortenings; false if no section cuts it.
       */
      bool
      block_offsets(const unsigned int block,
                    double offsets[internal::n_nodes][3][internal::lanes]) const;

      /** The elements of one block that sections cut. */
      struct SectionCut
      {
        /** The block. */
        unsigned int block;
        /** Section of each lane (numbers::invalid_unsigned_int: none). */
        unsigned int section[internal::lanes];
        /** Unit offset g of each node, [node][component][lane]. */
        double direction[internal::n_nodes][3][internal::lanes];
      };
      /** Index into `cuts` of each block's cut, invalid if none. */
      std::vector<unsigned int> cut_of_block;
      std::vector<SectionCut>   cuts;
      /** Shortening of each section (mm). */
      std::vector<double> shortenings;

      internal::ReferenceShapes       reference;
      std::vector<internal::HexBlock> blocks;
      std::vector<ElementInfo>        elements;
      std::vector<GroupData>          groups;
      /** Per element: factor on its stable step (empty: 1). */
      std::vector<double> time_step_factors;
      ElementSettings                 settings;
      std::vector<double>             history_old, history_new;
    };
  } // namespace elements
} // namespace rubberdyn

#endif
