#ifndef rubberdyn_contact_mortar_contact_pair_h
#define rubberdyn_contact_mortar_contact_pair_h

#include <deal.II/base/partitioner.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <rubberdyn/base/vector.h>
#include <rubberdyn/contact/mortar_segment.h>
#include <rubberdyn/model/force_contribution.h>

#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace rubberdyn
{
  namespace model
  {
    class Model;
    struct ContactPairDefinition;
  } // namespace model

  namespace contact
  {
    /**
     * What a contact pair did at its last evaluation, this rank's share
     * (the columns of time_history.csv: postprocess::ContactPairColumns sums
     * and extremises it over the ranks).
     */
    struct ContactPairStatistics
    {
      /** Force of the master side on the slave side (kN). */
      Tensor<1, 3> force;
      /** Sum of the active slave nodes' normal forces p_a A_a (kN). */
      double normal_force = 0.;
      /** Sum of the magnitudes of their tangential forces (kN). */
      double tangential_force = 0.;
      /**
       * Largest and smallest nodal pressure of the active nodes (GPa; a
       * tied node's may be negative: tension). Without active nodes, the
       * lowest and the largest double.
       */
      double max_pressure = std::numeric_limits<double>::lowest();
      double min_pressure = std::numeric_limits<double>::max();
      /** Sum of the active slave nodes' covered areas A_a (mm^2). */
      double contact_area = 0.;
      /** Largest penetration, -g_a, of the slave nodes (mm, >= 0). */
      double       max_penetration = 0.;
      unsigned int active_nodes    = 0;
      unsigned int slipping_nodes  = 0;
    };

    /** A slave node's gap (MortarContactPair::slave_node_gaps()). */
    struct SlaveNodeGap
    {
      /** Global indices of its x, y, z dofs. */
      types::global_dof_index dofs[3];
      /** Its position (mm). */
      Point<3> x;
      /** Its mean normal gap g_a (mm; negative: penetration). */
      double gap = 0.;
      /** Its unit normal n_a (the slave facets' outward mean). */
      Tensor<1, 3> normal;
    };

    /** Where a pair's time went, this rank (for benchmarks). */
    struct ContactPairTimings
    {
      /** Number of searches (the first and every re-sort). */
      unsigned int searches = 0;
      /** Wall time of the searches and of all evaluations (s). */
      double search_seconds = 0., evaluation_seconds = 0.;
      /**
       * The part of evaluation_seconds spent waiting for the other ranks:
       * for the surfaces' positions and for the forces' sums (s).
       */
      double waiting_seconds = 0.;
      /** Candidate master facets after the last search. */
      unsigned long candidates = 0;
    };

    /**
     * One contact pair of the Model study (`Contact pairs/<name>`):
     * segment-to-segment mortar contact between the boundary faces of two
     * surfaces of deformable or rigid parts (Puso & Laursen, Comput.
     * Methods Appl. Mech. Engrg. 193 (2004) 601), as a force contribution.
     *
     * <h3>Discretisation</h3>
     * The slave facets are integrated against the master facets they
     * overlap (integrate_mortar_segment()): D_ab and M_ak give each slave
     * node a its covered area $A_a = \sum_b D_{ab}$ and weighted gap vector
     * $\tilde{\mathbf g}_a = \sum_b D_{ab}\mathbf x_b - \sum_k M_{ak}\hat
     * {\mathbf x}_k$. Its normal gap is the mean over that area, $g_a =
     * -\mathbf n_a\cdot\tilde{\mathbf g}_a / A_a$ (positive open), with
     * $\mathbf n_a$ the area-weighted mean of the outward normals of the
     * slave facets around a.
     *
     * <h3>Normal contact (frictionless)</h3>
     * A penalty on the mean gap: the nodal pressure is $p_a = \varepsilon
     * \langle -g_a\rangle$, from the potential $\sum_a \tfrac12\varepsilon
     * A_a \langle -g_a\rangle^2$ with D, M and the normals held over the
     * step. The slave node b then feels $-\sum_a p_a D_{ab}\mathbf n_a$ and
     * the master node k $+\sum_a p_a M_{ak}\mathbf n_a$: the two sum to
     * zero, since $\sum_b D_{ab} = \sum_k M_{ak}$ (momentum is exchanged
     * exactly), and a uniform gap gives a uniform pressure (the patch
     * test). The stiffness per area is the pair's
     * $\varepsilon = s\,\min(\overline{K/h}_{slave}, \overline{K/h}_{master})$,
     * s the `Penalty scale` and $\overline{K/h}$ the mean over a side's
     * facets of the bulk modulus of the element under it over its
     * thickness V/A (GPa/mm), with A the facet's current area (V that of
     * the reference: the pair has the facets, not their cells). It is
     * computed when follow_geometry() asks, at the next add_forces(), and
     * held until the next request (every explicit step; in the
     * quasi-static solver after a load step's predictor and on the run's
     * last convergence, doc/quasi_static.md), so
     * that the tangent is exact for the penalty held; a compressed rubber
     * face that spreads stiffens its penalty as its elements stiffen. An
     * update adds $\tfrac12\Delta\varepsilon A_a g_a^2$ to a closed
     * node's spring without work; the energy the pair reports is the work
     * done on its springs (what they hold less what the updates added), so
     * the energy balance closes.
     *
     * <h3>Coulomb friction</h3>
     * A return mapping on the weighted slip (Puso & Laursen 2004, sect. 5):
     * the slip increment of node a since the accepted step is
     * $\Delta\mathbf s_a = (1 - \mathbf n_a\otimes\mathbf n_a)
     * [\sum_b D_{ab}\Delta\mathbf x_b - \sum_k M_{ak}\Delta\hat{\mathbf
     * x}_k]/A_a$ (zero for a rigid motion of the touching pair). The
     * accepted tangential traction, turned into the current tangent plane
     * with its magnitude kept (objective under rotations), takes the
     * elastic trial $\mathbf t_T = \mathbf t_T^{old} - \varepsilon\Delta
     * \mathbf s_a$ and is scaled back to $\mu p_a$ if it exceeds it (slip),
     * with LS-DYNA's $\mu = FD + (FS - FD)\,e^{-DC\,|\Delta\mathbf
     * s_a|/\Delta t}$. The friction work of a step is the work done on the
     * tangential spring (trapezoidal rule) less the change of its energy
     * $A_a|\mathbf t_T|^2/2\varepsilon$ (which is contact energy); a node
     * that opens dissipates its spring's energy. The accepted state moves
     * on in accept_step().
     *
     * <h3>Tied contact</h3>
     * D and M are integrated once, in the reference configuration; every
     * slave node whose mean gap is within the `Tie tolerance` is tied by a
     * penalty on the change of its weighted gap vector in all directions,
     * $\mathbf t_a = -\varepsilon(\tilde{\mathbf g}_a(\mathbf x) -
     * \tilde{\mathbf g}_a(\mathbf X))/A_a$ (the initial offset is kept).
     *
     * <h3>Stable step</h3>
     * By Gershgorin's bound on the penalty matrix $\varepsilon G^T
     * A^{-1} G$ (rows of G: $[D_{a\cdot}, -M_{a\cdot}]$, all entries $\ge
     * 0$), whose row sums are $2\varepsilon\int N_b$: $\Delta t \le
     * 2/\sqrt{2\varepsilon\max_b (\int N_b\,dA)/m_b}$, with the whole facet
     * area around each surface node. The explicit solver takes the smaller
     * of it and the elements' step.
     *
     * <h3>Search and parallel</h3>
     * Every rank keeps both surfaces whole (the facets are gathered once;
     * their nodes are ghosts of a partitioner of the pair, 4C's
     * "redundant master" ghosting), and integrates its own slave facets plus
     * those of other ranks that share a node with them, so that the gaps of
     * its facets' nodes are complete without a reduction. The forces of its
     * own facets' segments are added into ghosted entries and compressed.
     * Candidate master facets come from an R-tree of their bounding boxes
     * enlarged by a capture margin (half the mean facet diagonal), rebuilt
     * when a surface node has moved by a quarter of the margin since.
     *
     * Self-contact is a pair whose slave and master ids are the same: facets
     * that share a node are not paired, and since every facet is then the
     * slave of the facets it faces and their master too, the pair acts
     * both ways in one pass, with half the penalty. `Two-pass` adds the
     * pass with the roles swapped, each pass with half the penalty (it
     * changes nothing for self-contact).
     */
    class MortarContactPair : public model::ForceContribution
    {
    public:
      /**
       * Find the pair's facets (collective) and, for a tied pair, integrate
       * its segments.
       *
       * @throws InputError naming `Contact pairs/<name>/Tie tolerance` if a
       *   tied pair ties no node.
       */
      MortarContactPair(const model::Model                 &model,
                        const model::ContactPairDefinition &definition);

      ~MortarContactPair() override;

      std::string
      name() const override;

      Accumulation
      accumulation() const override;

      /**
       * The forces at @p point: start_forces(), compute_forces() (unless
       * they were called for this point), then the exchange of the forces
       * on other ranks' nodes completed and this rank's added into @p f.
       */
      void
      add_forces(const model::EvaluationPoint &point,
                 VectorType                   &f,
                 model::ContributionResults   &results) override;

      /** Send the positions of this rank's surface nodes (nonblocking). */
      void
      start_forces(const model::EvaluationPoint &point) override;

      /**
       * Receive the other ranks' positions, integrate this rank's slave
       * facets and send the forces on other ranks' nodes (nonblocking).
       */
      void
      compute_forces(const model::EvaluationPoint &point,
                     model::ContributionResults   &results) override;

      /** Yes: the forces are static, add_tangents() their derivative. */
      bool
      supports_implicit() const override;

      /** No: D and M differ, and only the slave side's normal turns. */
      bool
      symmetric_tangent() const override;

      /**
       * The exact derivative of the forces of add_forces() at @p point, for
       * the quasi-static solver: one block per active slave node of this
       * rank's facets, over the nodes of its slave facets and their
       * candidate master facets, by forward automatic differentiation
       * (Sacado) of the force computation (clipping, integration, nodal
       * normal, return mapping). It uses the candidates of the last
       * add_forces() (the solver evaluates the residual first) and the
       * accepted friction state. Collective (one ghost update).
       */
      void
      add_tangents(const model::EvaluationPoint &point,
                   const TangentBlock           &add) const override;

      /**
       * Mark the slave nodes of this rank whose traction is live at
       * @p point (node_forces(): a closed gap, or a tied node); a node
       * once marked stays so. Collective (one ghost update).
       */
      void
      update_couplings(const model::EvaluationPoint &point) override;

      /**
       * The blocks add_tangents() may write: over the patch of every
       * marked node (update_couplings()), its slave facets and all their
       * candidate master facets of the last search. Open nodes write no
       * block: leaving them out keeps the direct solver's factor small
       * (the bolt's shank in its holes, open during the preload, was a
       * third of a Newton step's time on the coarse bushing mesh).
       */
      void
      add_couplings(const CouplingBlock &add) const override;

      /**
       * Changes with every search (new candidates) and every
       * update_couplings() that marked a node.
       */
      unsigned int
      couplings_version() const override;

      /** The penalty follows the facets' current areas. */
      bool
      follow_geometry() override;

      /** Make the friction state of the last evaluation the accepted one. */
      void
      accept_step() override;

      /**
       * The last evaluation's results (for the columns) and, with
       * friction, the accepted tractions, positions and friction work.
       */
      void
      save(std::ostream &out) const override;

      /** Read what save() wrote; the next evaluation searches anew. */
      void
      load(std::istream &in) override;

      /**
       * The accepted friction state for the hand-off from the quasi-static
       * load path to the explicit run (Scheme = quasi-static then
       * explicit): per pass the tangential tractions (GPa), their springs'
       * energies (J) and the distances slipped (mm) of every node, then
       * the nodes' accepted positions (mm). Empty for frictionless and
       * tied pairs (they have no state). The same on every rank.
       */
      std::vector<double>
      friction_state() const;

      /**
       * Take the state @p state of friction_state() of the same pair on the
       * same mesh, accepted at the time @p time (the explicit run's start:
       * the first step's slip rate is measured from it). The friction work
       * starts from zero: the explicit run's energy balance starts at the
       * hand-off.
       *
       * @throws ExcMessage if @p state does not fit the pair.
       */
      void
      set_friction_state(const std::vector<double> &state, const double time);

      /**
       * Add the pair's ParaView fields at the last evaluation into
       * @p fields (owned entries of the Q1^3 dofs, as
       * postprocess::NodalScalars): at each slave node, into
       * its x dof the pressure (GPa), its y dof the mean normal gap (mm,
       * negative: penetration; 0 where no master facet is near), its z dof
       * the distance it has slipped (mm, Coulomb pairs). A tied node's
       * pressure is -t.n and its gap the normal separation. Collective.
       */
      void
      add_surface_fields(VectorType &fields) const;

      /**
       * The mean normal gap g_a = -n_a . g~_a / A_a of each slave node this
       * rank books (of every pass: two-pass and self-contact pairs have
       * both sides' nodes) at the positions X + @p u (owned entries of a
       * vector of the model's dofs), all segments integrated; nodes that
       * no master facet covers are left out. For the check of the initial
       * penetrations (resolve_initial_penetrations()), on a pair built for
       * it: it leaves the evaluation's scratch at these positions, so the
       * pair is not to be evaluated afterwards. Not for tied pairs.
       * Collective (a ghost update).
       */
      std::vector<SlaveNodeGap>
      slave_node_gaps(const VectorType &u);

      /** This rank's share of the last evaluation. */
      const ContactPairStatistics &
      last_statistics() const
      {
        return statistics;
      }

      /**
       * Energy dissipated by the pair's friction up to the last
       * evaluation, this rank's nodes (J): 0 for frictionless and tied
       * pairs.
       */
      double
      friction_work() const;

      /**
       * Energy in the pair's penalty springs at the last evaluation, less
       * what the penalty updates added to them (the term the energy balance
       * books as contact energy), this rank's nodes (J).
       */
      double
      contact_energy() const;

      /**
       * The energy the pair created since the run's first accepted
       * evaluation (J, this rank's share; negative: destroyed): the work
       * its forces did on the solid (trapezoidal rule over the accepted
       * evaluations) plus the change of contact_energy() plus the
       * friction_work() since then. Zero for a pair whose forces derive
       * from its springs' energy; the parts it leaves out (the nodal
       * normals', the mortar integrals' and the covered areas' change with
       * the motion) and the time discretisation show here. The sum over
       * the pairs is their share of the run's energy error. 0 before the
       * first accepted evaluation; the hand-off from a preload
       * (set_friction_state()) starts it again.
       */
      double
      energy_error() const;

      /** The pair's penalty stiffness per area of each pass (GPa/mm). */
      double
      penalty_stiffness() const;

      /**
       * The factor by which the pair's Penalty time step lowered the
       * material-based penalty at the last evaluation (1: not lowered).
       */
      double
      penalty_factor() const;

      /** Where the time went, this rank. */
      const ContactPairTimings &
      timings() const;


    private:
      struct Implementation;
      std::unique_ptr<Implementation> impl;
      ContactPairStatistics           statistics;
    };
  } // namespace contact
} // namespace rubberdyn

#endif
