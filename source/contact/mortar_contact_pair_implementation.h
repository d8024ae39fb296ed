#ifndef rubberdyn_source_contact_mortar_contact_pair_implementation_h
#define rubberdyn_source_contact_mortar_contact_pair_implementation_h
// What is behind contact::MortarContactPair's interface (private to
// source/contact: the pair's forces in mortar_contact_pair.cc, its tangent
// for the quasi-static solver in mortar_contact_tangent.cc).

#include <deal.II/base/partitioner.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <rubberdyn/base/vector.h>
#include <rubberdyn/contact/mortar_contact_pair.h>
#include <rubberdyn/contact/mortar_segment.h>
#include <rubberdyn/model/force_contribution.h>
#include <rubberdyn/model/model.h>

#include <array>
#include <memory>
#include <vector>

namespace rubberdyn
{
  namespace contact
  {
    namespace mortar_internal
    {
      /** A facet as gathered from its rank. */
      struct GatheredFacet
      {
        /** Global dofs x, y, z of its corners, in FacetCorners' order. */
        types::global_dof_index dofs[4][3];
        /** Reference coordinates of its corners (mm). */
        double X[4][3];
        /** Bulk modulus of its element times area over volume (GPa/mm). */
        double stiffness;
        /** Rank that owns its cell. */
        unsigned int rank;
        /** Bit 0: on the slave surface; bit 1: on the master surface. */
        unsigned int sides;

        /** For Utilities::MPI::all_gather(). */
        template <class Archive>
        void
        serialize(Archive &archive, const unsigned int)
        {
          archive &dofs &X &stiffness &rank &sides;
        }
      };

      /**
       * A segment: its slave facet (an index into the pass's gap facets),
       * its master facet and the integrals.
       */
      struct StoredSegment
      {
        unsigned int  slave, master;
        MortarSegment integrals;
        /** Its weight and the weight's gradient (mortar_segment_weight();
         * tied segments: 1 and 0). */
        double       weight = 1.;
        Tensor<1, 3> weight_gradient;
      };

      /**
       * A segment's traction from its slave node's, @p traction = -p n +
       * t_T: the normal part turned to -p (n . n_0)(n_0 - slope), the
       * derivative of the node's weighted normal gap where the master face
       * has the mean @p slope over the segment relative to its plane of
       * unit normal @p n_0 (MortarSegment::slope; doc/theory.md §15.2).
       * The one traction of add_forces(), the tangent and the trace.
       */
      template <typename Number>
      Tensor<1, 3, Number>
      segment_traction(const Tensor<1, 3, Number> &traction,
                       const Number               &p,
                       const Tensor<1, 3, Number> &n,
                       const Tensor<1, 3, Number> &n_0,
                       const Tensor<1, 3, Number> &slope)
      {
        return traction + p * (n - Number(n * n_0) * (n_0 - slope));
      }

      /**
       * The column sums of a segment's D and M, sum_a D_ab and sum_a M_ak:
       * with the weight's gradient, the weight's derivative with respect
       * to the corners (mortar_segment_weight()).
       */
      template <typename Number>
      void
      column_sums(const MortarSegmentOf<Number> &segment,
                  Number (&column_D)[4],
                  Number (&column_M)[4])
      {
        for (unsigned int b = 0; b < 4; ++b)
          {
            column_D[b] = column_M[b] = 0.;
            for (unsigned int a = 0; a < 4; ++a)
              {
                column_D[b] += segment.D[a][b];
                column_M[b] += segment.M[a][b];
              }
          }
      }

      /**
       * The derivative of an active slave node's normal spring energy
       * p^2 A / 2 eps with respect to a segment's weight (J): with the
       * node's pressure @p p, mean gap @p g and normal @p n and the
       * segment's unweighted row of the weighted gap vector @p row_gap
       * and of the covered area @p row_area, p (n . row_gap + g row_area /
       * 2) (weight_forces(), the tangent and the trace).
       */
      template <typename Number>
      Number
      spring_energy_weight_derivative(const Number               &p,
                                      const Number               &g,
                                      const Tensor<1, 3, Number> &n,
                                      const Tensor<1, 3, Number> &row_gap,
                                      const Number               &row_area)
      {
        return p * (n * row_gap + 0.5 * g * row_area);
      }

      /**
       * Coulomb's return mapping on the weighted slip (Puso & Laursen
       * 2004, sect. 5), the one of add_forces() and of the tangent (with
       * Sacado numbers): the @p accepted tangential traction (GPa) turned
       * into the tangent plane of the unit normal @p n, its magnitude kept;
       * the slip increment @p increment = weighted slip over the covered
       * area, projected on the plane; the elastic trial old - eps
       * increment; the cone mu p with LS-DYNA's mu(FS, FD, DC, rate), the
       * rate |increment| / @p step. Returns the tangential traction, and
       * @p old, @p increment and whether it slips.
       */
      template <typename Number>
      Tensor<1, 3, Number>
      coulomb_return_mapping(const Tensor<1, 3>                 &accepted,
                             const Tensor<1, 3, Number>         &n,
                             const Tensor<1, 3, Number>         &weighted_slip,
                             const Number                       &area,
                             const Number                       &p,
                             const double                        penalty,
                             const double                        step,
                             const model::ContactPairDefinition &def,
                             Tensor<1, 3, Number>               &old,
                             Tensor<1, 3, Number>               &increment,
                             bool                               &slipping)
      {
        for (unsigned int d = 0; d < 3; ++d)
          old[d] = accepted[d];
        old -= (old * n) * n;
        // (The norms only where they are not zero: with Sacado numbers
        // their derivative is undefined there.)
        if (old.norm() > 0.)
          old *= Number(accepted.norm() / old.norm());
        increment = weighted_slip / area;
        increment -= (increment * n) * n;
        Tensor<1, 3, Number> tangential = old - penalty * increment;
        Number               rate       = 0.;
        if (step > 0. && increment.norm() > 0.)
          rate = increment.norm() / step;
        using std::exp;
        const Number mu =
          def.dynamic_friction +
          (def.static_friction - def.dynamic_friction) * exp(-def.decay * rate);
        const Number limit = mu * p;
        slipping           = tangential.norm() > limit;
        if (slipping)
          tangential *= Number(limit / tangential.norm());
        return tangential;
      }

      /** The forces of one segment's row a on the patch (the tangent's
       * MortarContactPair::Implementation::node_forces()): its integrals,
       * and the segment's weight, the weight's gradient and the column sums
       * of D and M (mortar_segment_weight(); 1 and zeros where it is 1). */
      template <typename Number>
      struct SegmentRow
      {
        unsigned int         slave_facet, master_facet;
        Number               D[4], M[4];
        Number               weight = 1.;
        Tensor<1, 3, Number> weight_gradient;
        bool                 tapered = false;
        Number               column_D[4], column_M[4];
        /** The master face's mean slope and the plane's normal
         * (MortarSegment::slope). */
        Tensor<1, 3, Number> slope, normal;
      };
    } // namespace mortar_internal
    using namespace mortar_internal;



    /** Everything behind the interface (the class documentation). */
    struct MortarContactPair::Implementation
    {
      /**
       * The largest weighted gap that counts as closed in the tangent (mm):
       * faces that touch in the mesh have gaps of the integrals' round-off.
       */
      static constexpr double closed_gap = 1e-12;

      /** One direction of the pair: a slave and a master surface. */
      struct Pass
      {
        std::vector<unsigned int> slave_facets, master_facets;
        /** Penalty stiffness per area (GPa/mm), held between updates. */
        double penalty = 0.;
        /**
         * The penalty of the last accepted evaluation (negative: none since
         * the start, no update to book) (GPa/mm).
         */
        double accepted_penalty = -1.;
        /**
         * The slave facets this rank integrates (its own and those of other
         * ranks that share a node with them), ascending.
         */
        std::vector<unsigned int> gap_facets;
        /** Candidate master facets of each gap facet (ascending). */
        std::vector<std::vector<unsigned int>> candidates;
        /** The nodes of the gap facets (ascending), and for each its slave
         * facets (for the normal) in CSR form. */
        std::vector<unsigned int> nodes, facet_start, node_facets;
        /** For each of the nodes, the gap facets around it (indices into
         * gap_facets), in CSR form. */
        std::vector<unsigned int> gap_start, node_gap_facets;
        /** Whether this rank books a node's statistics (by node index). */
        std::vector<bool> counted;
        /** Segments of the last evaluation (tied: of the reference). */
        std::vector<StoredSegment> segments;
        /** Tied: whether each node (by node index) is tied, and its
         * covered area in the reference configuration (mm^2). */
        std::vector<bool>   tied;
        std::vector<double> tied_area;
        /**
         * Coulomb, by node index: the tangential traction (GPa) and the
         * energy in its spring (J), of the last accepted step and of the
         * last evaluation.
         */
        std::vector<Tensor<1, 3>> accepted_tangential, trial_tangential;
        std::vector<double>       accepted_spring_energy, trial_spring_energy;
        /** Coulomb: the distance each node has slipped (mm), accepted and
         * trial. */
        std::vector<double> accepted_slip_distance, trial_slip_distance;
        /** By node index, of the last evaluation: pressure (GPa) and mean
         * gap (mm, 0 where nothing is covered), for ParaView. */
        std::vector<double> shown_pressure, shown_gap;
        /** By node index: whether the implicit solver's pattern holds the
         * node's patch (its traction was live at some assembly, never
         * cleared; MortarContactPair::update_couplings()). */
        std::vector<bool> coupled;

        /** A segment kept for reuse: its master facet, the integrals and
         * the master facet's corners when they were integrated. */
        struct KeptSegment
        {
          unsigned int  master;
          MortarSegment integrals;
          FacetCorners  master_corners;
        };
        /** A gap facet's segments kept for reuse (Segment reuse slip), with
         * its corners when they were integrated. */
        struct KeptSegments
        {
          bool                     valid = false;
          FacetCorners             slave_corners;
          std::vector<KeptSegment> segments;
        };
        /** By gap facet: the kept segments (explicit runs with reuse; all
         * invalid after a search). */
        std::vector<KeptSegments> kept;
      };

      Implementation(const model::Model                 &model,
                     const model::ContactPairDefinition &definition);

      // The steps of the constructor, in its order.

      /**
       * The facets of the pair's boundary ids on every rank (facets), in
       * an order that does not depend on the partition (by their centres):
       * gathered on this rank, then from all (collective).
       */
      void
      gather_facets(const model::Model &model);

      /**
       * Number the facets' nodes in the order of the facets; the pair's
       * partitioner and vectors, and the per-node state.
       */
      void
      set_up_nodes(const model::Model &model);

      /**
       * The search margin and the passes: slave -> master, and back for
       * two-pass pairs (one pass for self-contact).
       */
      void
      set_up_passes();

      /**
       * What @p pass (its slave and master facets set) needs beyond them:
       * the nodes this rank books, its gap facets, their nodes with the
       * slave facets around each, and the per-node state.
       */
      void
      set_up_pass(Pass &pass);

      /** Positions x = X + u of every surface node. */
      void
      update_positions(const VectorType &u_pair);

      /**
       * Positions from the solver's displacement @p u: its owned surface
       * dofs to the pair's vector, whose ghosts are then updated
       * (collective), and update_positions().
       */
      void
      load_positions(const VectorType &u);

      /**
       * The work audit's trial: the work up to the pair's forces on this
       * rank's owned surface dofs (f_pair, after the evaluation) at the
       * displacements there (u_pair, load_positions()), by the
       * trapezoidal rule from the accepted ones.
       */
      void
      book_trial_work();

      /** Rebuild the candidate lists if a node moved far enough. */
      void
      search_if_needed();

      /**
       * Integrate the segments of @p pass at the current positions. With
       * @p skip_open, the gap facets whose four nodes are all clearly open
       * (mark_open_nodes()) are left out: those nodes carry no traction
       * whatever their other facets give (their weighted gaps are sums of
       * positive terms), so the forces, and every sum at the other nodes,
       * are those of the full integration to the bit; only the open
       * nodes' areas and gaps are partial (refresh_shown_gaps() makes the
       * shown gaps whole again). The nodal normals must be current
       * (compute_normals()).
       *
       * @return Whether a facet was left out.
       */
      bool
      integrate(Pass      &pass,
                const bool keep_all,
                const bool skip_open = false,
                const bool reuse     = false);

      /**
       * Whether the kept segments of a gap facet still hold (integrate()
       * with reuse): no corner of the facet, now at @p slave, nor of the
       * kept segments' master facets has moved along the facet's plane
       * (unit normal @p n), relative to the facet's mean motion, by more
       * than the pair's Segment reuse slip since they were integrated.
       */
      bool
      kept_segments_hold(const Pass::KeptSegments &kept,
                         const FacetCorners       &slave,
                         const Tensor<1, 3>       &n) const;

      /** The search's state and the kept segments, for an exact restart
       * with segment reuse (save(), load()). */
      void
      save_kept_segments(std::ostream &out) const;
      void
      load_kept_segments(std::istream &in);

      /**
       * Mark in open_node (by node index) the nodes of @p pass that are
       * clearly open: every gap facet around the node is clearly open
       * towards each of its candidates (MortarSlaveFacet::clearly_open()
       * with a clearance of 1e-9 of the facet's diagonal), and the nodal
       * normal points the facet normals' way. Each segment then adds a
       * positive multiple of its facet's normal to the node's weighted gap
       * vector: its gap is positive and it carries no traction. Needs
       * slave_facets of the current positions.
       */
      void
      mark_open_nodes(const Pass &pass);

      /** The shown gaps (ParaView) of the nodes that the last skipping
       * integrate() left partial: integrates @p pass in full again, at the
       * positions of the last evaluation, and restores the evaluation's
       * sums and segments. */
      void
      refresh_shown_gaps(Pass &pass);

      /** The nodal normals of @p pass's nodes at the current positions. */
      void
      compute_normals(const Pass &pass);

      /** What an evaluation's passes add up (J): the springs' stored
       * energy and the friction's dissipation over the trial step. */
      struct EvaluationEnergies
      {
        double stored = 0., dissipated = 0.;
      };

      /**
       * The first phase of an evaluation (compute_forces()): the ghosted
       * surface displacements in, the current positions, the masses on
       * the first call with masses, a pending penalty update, and the
       * search if the motion since the last one asks for it.
       */
      void
      prepare_evaluation(const model::EvaluationPoint &point);

      /**
       * The tied nodes' tractions of @p pass at the current positions:
       * the penalty on the change of each node's weighted gap vector since
       * the reference state (the stored reference integrals times the
       * displacements), with their energy and the columns' sums.
       */
      void
      tied_tractions(Pass                  &pass,
                     EvaluationEnergies    &energies,
                     ContactPairStatistics &statistics);

      /**
       * The contact nodes' tractions of @p pass at the current positions
       * and @p time: integrates the segments (skipping the clearly open
       * facets), then per node the normal penalty on the weighted gap and,
       * for Coulomb pairs, the return mapping on the weighted slip, with
       * the springs' energy, the friction's dissipation and the columns'
       * sums.
       */
      void
      contact_tractions(Pass                  &pass,
                        const double           time,
                        EvaluationEnergies    &energies,
                        ContactPairStatistics &statistics);

      /**
       * The forces of this rank's segments of @p pass into f_pair: w D t
       * on the slave side, -w M t on the master side, and where the weight
       * w is below 1 the springs' share of its gradient (weight_forces()).
       */
      void
      scatter_segment_forces(const Pass            &pass,
                             ContactPairStatistics &statistics);

      /**
       * The unit normal at the @p k-th node of @p pass: the sum of its
       * slave facets' diagonal cross products, normalised, with the
       * positions @p position(node) (compute_normals(), and node_forces()
       * with derivatives).
       */
      template <typename Number, typename Position>
      Tensor<1, 3, Number>
      nodal_normal(const Pass        &pass,
                   const unsigned int k,
                   const Position    &position) const
      {
        Tensor<1, 3, Number> n;
        for (unsigned int j = pass.facet_start[k]; j < pass.facet_start[k + 1];
             ++j)
          {
            const auto &c = facet_nodes[pass.node_facets[j]];
            n += cross_product_3d(position(c[2]) - position(c[0]),
                                  position(c[3]) - position(c[1]));
          }
        return n / n.norm();
      }

      /**
       * The forces on the solid of the segment @p s's weight: minus the
       * derivative of the normal springs' energy of its active slave nodes
       * (pass.shown_gap of the evaluation) with respect to the weight,
       * times the weight's gradient (mortar_segment_weight()), on its slave
       * corners (@p on_slave) and master corners (@p on_master). With them
       * a segment that fades out at the capture margin does work on the
       * solid for the energy its nodes' springs gain or lose.
       */
      void
      weight_forces(const Pass          &pass,
                    const StoredSegment &s,
                    Tensor<1, 3> (&on_slave)[4],
                    Tensor<1, 3> (&on_master)[4]) const;

      /** Whether a gap facet of this rank lies around the @p k-th node of
       * @p pass (its forces then are partly this rank's). */
      bool
      has_own_facet(const Pass &pass, const unsigned int k) const
      {
        for (unsigned int j = pass.gap_start[k]; j < pass.gap_start[k + 1]; ++j)
          if (owns(pass, pass.node_gap_facets[j]))
            return true;
        return false;
      }

      /** Whether this rank owns the @p i-th gap facet of @p pass. */
      bool
      owns(const Pass &pass, const unsigned int i) const
      {
        return facets[pass.gap_facets[i]].rank == my_rank;
      }

      /**
       * The nodes (ascending) on which the forces of the @p k-th node of
       * @p pass depend or act: those of its slave facets, and of their
       * candidate master facets (tied: of their segments' master facets).
       */
      void
      patch_of(const Pass                &pass,
               const unsigned int         k,
               std::vector<unsigned int> &patch) const;

      /**
       * The forces that the traction of the @p k-th node of @p pass puts,
       * through this rank's segments, on the nodes of its @p patch, at the
       * positions @p y of those nodes (by patch index): the same arithmetic
       * as add_forces(), as a function of @p y alone (the accepted
       * friction state and the candidates fixed). With Sacado numbers in
       * @p y the forces carry their derivatives (the tangent). Returns
       * false (and leaves @p force alone) if the node carries no traction.
       *
       * @p overlaps: the pairs (gap facet index, master facet) whose
       * segments count, and whether the segment's weight is below 1 there
       * (0 or 1). With @p record, all candidate pairs are tried and
       * @p overlaps becomes those that gave a segment (a first evaluation
       * in doubles); without, only those are integrated (the evaluation
       * with derivatives, on a patch reduced to their nodes: the node's
       * row of D and M, all rows where the weight, which needs them, is
       * below 1).
       */
      template <typename Number>
      bool
      node_forces(const Pass                               &pass,
                  const unsigned int                        k,
                  const std::vector<unsigned int>          &patch,
                  const std::vector<Point<3, Number>>      &y,
                  const double                              time,
                  std::vector<Tensor<1, 3, Number>>        &force,
                  std::vector<std::array<unsigned int, 3>> &overlaps,
                  const bool                                record) const;

      // The steps of node_forces().

      /**
       * A tied node's rows (@p rows, of this rank's segments) and its
       * weighted gap vector @p gap from the reference integrals: node
       * @p node of @p pass, at the positions @p y of its @p patch.
       */
      template <typename Number>
      void
      tied_rows(const Pass                          &pass,
                const unsigned int                   node,
                const std::vector<unsigned int>     &patch,
                const std::vector<Point<3, Number>> &y,
                std::vector<SegmentRow<Number>>     &rows,
                Tensor<1, 3, Number>                &gap) const;

      /**
       * A contact node's rows (@p rows, of this rank's segments), covered
       * area @p A, weighted gap @p gap and weighted slip @p slip: the
       * segments of the @p overlaps (with @p record, of all candidates,
       * and @p overlaps becomes those that gave a segment), integrated at
       * the positions @p y of the @p k-th node's @p patch.
       */
      template <typename Number>
      void
      contact_rows(const Pass                               &pass,
                   const unsigned int                        k,
                   const std::vector<unsigned int>          &patch,
                   const std::vector<Point<3, Number>>      &y,
                   std::vector<std::array<unsigned int, 3>> &overlaps,
                   const bool                                record,
                   std::vector<SegmentRow<Number>>          &rows,
                   Number                                   &A,
                   Tensor<1, 3, Number>                     &gap,
                   Tensor<1, 3, Number>                     &slip) const;

      /**
       * The forces of the node's @p traction (pressure @p p, gap @p g,
       * normal @p n) through its @p rows on its @p patch, at the positions
       * @p y: w D t on the slave side, -w M t on the master side, and the
       * spring's share of the weight's forces where it is below 1.
       */
      template <typename Number>
      void
      add_row_forces(const std::vector<SegmentRow<Number>> &rows,
                     const bool                             tied,
                     const Tensor<1, 3, Number>            &traction,
                     const Number                          &p,
                     const Number                          &g,
                     const Tensor<1, 3, Number>            &n,
                     const std::vector<unsigned int>       &patch,
                     const std::vector<Point<3, Number>>   &y,
                     std::vector<Tensor<1, 3, Number>>     &force) const;

      /**
       * Add the tangent blocks of @p pass at the current positions: one
       * per active slave node, over its patch (patch_of()), by forward
       * automatic differentiation of node_forces().
       */
      void
      add_tangents(const Pass                                   &pass,
                   const double                                  time,
                   const model::ForceContribution::TangentBlock &add) const;

      /** Whether facets f and g share a corner. */
      bool
      share_a_node(const unsigned int f, const unsigned int g) const;

      /** A copy: the pair does not depend on where it was defined. */
      const model::ContactPairDefinition definition;
      MPI_Comm                           comm;
      unsigned int                       my_rank;

      std::vector<GatheredFacet> facets;
      /** Corners' node indices of each facet. */
      std::vector<std::array<unsigned int, 4>> facet_nodes;
      /** Per node: local indices (pair partitioner) of x, y, z; X. */
      std::vector<std::array<unsigned int, 3>> node_dofs;
      /** Per node: global dofs of x, y, z (for the tangent's blocks). */
      std::vector<std::array<types::global_dof_index, 3>> node_global_dofs;
      std::vector<Point<3>>                               node_reference;
      std::vector<Point<3>>                               x, x_at_search;
      /**
       * Per node: the sum over passes of the penalty times the whole facet
       * area around it, its side's int N dA (kN/mm).
       */
      std::vector<double> node_stiffness;

      /**
       * The passes' penalties and the nodes' stiffness (node_stiffness,
       * and with it the stable step) from the facets' areas at the
       * positions x: each facet's stiffness K A / V grows with its area (V
       * is the reference volume: the pair holds the facets, not their
       * cells; for rubber, nearly incompressible, it is the current one
       * within the volume strain).
       */
      void
      set_penalty();

      /** Area of facet @p f now (mm^2). */
      double
      current_facet_area(const unsigned int f) const
      {
        const auto &c = facet_nodes[f];
        return 0.5 *
               cross_product_3d(x[c[2]] - x[c[0]], x[c[3]] - x[c[1]]).norm();
      }

      /** Each facet's area in the reference configuration (mm^2), and
       * scratch for its area now. */
      std::vector<double> reference_area, area_now;
      /** Whether the next add_forces() calls set_penalty(). */
      bool follow_pending = false;
      /** The divisor of each pass's penalty: 2 for two-pass and self-contact
       * pairs (symmetric treatment), else 1. */
      double penalty_divisor = 1.;
      /** Lumped mass of each node (kg, with mass scaling), once known. */
      std::vector<double> node_mass;
      /**
       * Energy the penalty updates added to the springs up to the accepted
       * state and in the last evaluation, this rank's booked nodes (J).
       */
      double accepted_stiffness_energy = 0., trial_stiffness_energy = 0.;

      std::vector<Pass> passes;
      /** Capture margin of the search (mm). */
      double margin   = 0.;
      bool   searched = false;

      std::shared_ptr<const Utilities::MPI::Partitioner> partitioner;
      VectorType                                         u_pair, f_pair;
      /**
       * The MPI channel of u_pair's and f_pair's exchanges: 1 + the pair's
       * index in the model (channel 0 is the solver's), so that the pairs'
       * messages in flight at once never share a tag.
       */
      unsigned int channel = 1;
      /** Where the split evaluation stands (start_forces(),
       * compute_forces(), add_forces()). */
      enum class Exchange
      {
        idle,
        positions_sent,
        forces_sent
      } exchange = Exchange::idle;
      /** Local indices of the surface nodes' dofs that this rank owns. */
      std::vector<unsigned int> owned_surface_dofs;

      /** Scratch by node index: covered area, weighted gap, normal,
       * traction. */
      std::vector<double>       area;
      std::vector<Tensor<1, 3>> gap, normal, traction;

      /** Stable step of the penalty (ms), once the masses are known (a
       * negative number until then). */
      double time_step = -1.;
      /**
       * The factor on the material-based penalty that keeps the springs'
       * step at the pair's Penalty time step (1: not lowered).
       */
      double penalty_factor = 1.;

      /** Coulomb: whether the pair has friction. */
      bool coulomb = false;
      /** Coulomb: the weighted slip increment since the accepted step
       * (mm^3: times the covered area), by node index. */
      std::vector<Tensor<1, 3>> slip;
      /** Coulomb: node positions and time of the last accepted step. */
      std::vector<Point<3>> x_accepted;
      double                time_accepted = 0.;
      /** Coulomb: friction work up to the accepted step, and of the last
       * evaluation, this rank's booked nodes (J). */
      double accepted_friction_work = 0., trial_dissipation = 0.;
      /** Time of the last evaluation; whether it awaits accept_step(). */
      double trial_time    = 0.;
      bool   trial_pending = false;
      /** Energy in the pair's springs at the last evaluation (J). */
      double             energy = 0.;
      ContactPairTimings timings;
      /** How many update_couplings() have marked new nodes. */
      unsigned int coupling_growths = 0;

      /** By facet: its bounds as a master facet (master_bounds_of()), and
       * the integrate() call they belong to. */
      std::vector<MasterFacetBounds> master_bounds;
      std::vector<unsigned long>     master_bounds_stamp;
      /** Counts integrate()'s calls (from 1). */
      unsigned long bounds_evaluation = 0;

      /** Master facet @p m's bounds at the current positions, computed at
       * the first request of this integrate() call. */
      const MasterFacetBounds &
      master_bounds_of(const unsigned int m)
      {
        if (master_bounds_stamp[m] != bounds_evaluation)
          {
            FacetCorners corners;
            for (unsigned int k = 0; k < 4; ++k)
              corners[k] = x[facet_nodes[m][k]];
            master_bounds[m]       = master_facet_bounds(corners);
            master_bounds_stamp[m] = bounds_evaluation;
          }
        return master_bounds[m];
      }
      /** By node index: open (mark_open_nodes()). */
      std::vector<char> open_node;

      /** Scratch of mark_open_nodes(), by gap facet: clearly open towards
       * all its candidates (capacity kept between evaluations). */
      std::vector<char> open_facet;

      /** Scratch of integrate(): the gap facets prepared for their
       * segments (capacity kept between evaluations). */
      std::vector<MortarSlaveFacet> slave_facets;

      /** Scratch of integrate() with reuse: a facet's kept segments'
       * weighted gap vectors, weights and their gradients (capacity kept
       * between evaluations). */
      struct WeightedGaps
      {
        Tensor<1, 3> vectors[4];
        double       weight = 1.;
        Tensor<1, 3> gradient;
      };
      std::vector<WeightedGaps> kept_weighted;

      /** Whether the last evaluation left facets out (integrate()), so
       * that the shown gaps of open nodes need refresh_shown_gaps(). */
      bool shown_gaps_partial = false;

      /**
       * The work the pair's forces did on the solid, for the pair's energy
       * error (MortarContactPair::energy_error()): by the trapezoidal rule
       * over the accepted evaluations since the first one of the run (the
       * hand-off from a preload starts it again), on this rank's owned
       * surface dofs. A conservative pair's work is minus the change of its
       * springs' energy less its friction work.
       */
      struct WorkAudit
      {
        /** Whether an evaluation has been accepted since the start. */
        bool started = false;
        /** Work up to the accepted evaluation and to the last one (J). */
        double accepted_work = 0., trial_work = 0.;
        /** Springs' energy plus friction work at the first accepted
         * evaluation (J). */
        double energy_at_start = 0.;
        /** By owned surface dof: displacement (mm) and force on the solid
         * (kN) of the accepted evaluation (the last one's are in u_pair and
         * f_pair). */
        std::vector<double> u_accepted, f_accepted;
      };
      WorkAudit audit;

      /**
       * The developer's trace of a pair's energy error (command-line
       * option --trace-pair <pair name>[:EVERY], RunOptions; doc/contact.md,
       * "Where a pair makes energy"): at each accepted evaluation, each
       * slave node's share of the step's error, the trapezoidal work of
       * its traction's forces (the normal and the tangential part through
       * its rows of the segments, and its share of the weights' forces)
       * plus the change of its normal and tangential springs' energy plus
       * friction's dissipation at it. Summed over
       * EVERY steps (default 1000) and written to stderr with the
       * largest nodes; single steps where a share or the pair's error
       * moved by more than 0.02 J are written at once. The state of the
       * last accepted evaluation and the sums since the last report.
       */
      struct Trace
      {
        bool                                    enabled  = false;
        bool                                    have_old = false;
        std::vector<Point<3>>                   x;
        std::vector<std::vector<StoredSegment>> segments;
        std::vector<Tensor<1, 3>>               traction, normal;
        std::vector<double>                     gap, penalty;
        double                                  error = 0.;
        /** Friction's dissipation of the last evaluation, by node (J). */
        std::vector<double> dissipation;
        /** Whether each node slipped in the last evaluation. */
        std::vector<char> slipping;
        /**
         * Each node's shares of the error since the last report (J), by
         * share_labels: the work of the normal part of its segments'
         * tractions, of their tangential part, of the weights' forces, the
         * change of the normal and of the tangential springs' energy, and
         * friction's dissipation.
         */
        static constexpr unsigned int n_shares = 6;
        static constexpr const char  *share_labels[n_shares] =
          {"WN", "WT", "Ww", "dEN", "dET", "D"};
        std::vector<std::array<double, n_shares>> shares_since_report;
        /** Its normal and tangential springs' energy (J). */
        std::vector<double> normal_energy, tangential_energy;
        /** Accepted steps since the last report, and the pair's error
         * there (J). */
        unsigned int steps_since_report = 0;
        double       error_at_report    = 0.;
        /** Steps between reports (RunOptions::trace_every). */
        unsigned int report_every = 1000;
      };
      Trace trace;

      /** The trace's step (Trace), @p error_now the pair's energy error
       * at this evaluation (J). */
      void
      trace_step(const double error_now);

      // The steps of trace_step().

      /**
       * A state's work over the step's displacements (x - trace.x), by
       * node: its @p segments of @p pass, at the positions @p at, with the
       * nodes' tractions @p t, normals @p normals, gaps @p gaps and
       * penalties @p penalties; the normal (@p W_normal) and the
       * tangential part (@p W_tangential) of the segments' tractions, and
       * the node's share of the weights' forces (@p W_weight).
       */
      void
      trace_state_work(const std::vector<StoredSegment> &segments,
                       const Pass                       &pass,
                       const std::vector<Point<3>>      &at,
                       const std::vector<Tensor<1, 3>>  &t,
                       const std::vector<Tensor<1, 3>>  &normals,
                       const std::vector<double>        &gaps,
                       const std::vector<double>        &penalties,
                       std::vector<double>              &W_normal,
                       std::vector<double>              &W_tangential,
                       std::vector<double>              &W_weight) const;

      /**
       * The step's shares of each node, from the old state (trace) and
       * this evaluation's (the springs' energies @p normal_now and
       * @p tangential_now, gaps @p gap_now, penalties @p penalty_now),
       * added to trace.shares_since_report; a jump line if the pair's
       * error (@p error_now) or a node's share moved by more than 0.02 J.
       */
      void
      add_trace_shares(const std::vector<double> &normal_now,
                       const std::vector<double> &tangential_now,
                       const std::vector<double> &gap_now,
                       const std::vector<double> &penalty_now,
                       const double               error_now);

      /** The report of the shares since the last one: the pair's split and
       * the largest nodes' (with their gaps @p gap_now). */
      void
      report_trace(const std::vector<double> &gap_now,
                   const double               error_now) const;

      /** The report's lines of node @p a's segments. */
      void
      print_trace_segments(const unsigned int a) const;
    };
  } // namespace contact
} // namespace rubberdyn

#endif
