// The mortar contact pair's tangent for the quasi-static solver: the exact
// derivative of its forces (doc/theory.md, section 15.7), by forward
// automatic differentiation of the force computation itself, node by node.
#include <deal.II/base/tensor.h>

#include <rubberdyn/contact/mortar_contact_pair.h>

#include <algorithm>
#include <cmath>

#include "ad_number.h"
#include "mortar_contact_pair_implementation.h"

namespace rubberdyn
{
  namespace contact
  {
    namespace
    {
      /** y - X for a point of numbers and one of doubles. */
      template <typename Number>
      Tensor<1, 3, Number>
      minus(const Point<3, Number> &y, const Point<3> &X)
      {
        Tensor<1, 3, Number> result;
        for (unsigned int d = 0; d < 3; ++d)
          result[d] = y[d] - X[d];
        return result;
      }

      /** The index of node @p n in the (sorted) @p patch. */
      unsigned int
      patch_index(const std::vector<unsigned int> &patch, const unsigned int n)
      {
        return std::lower_bound(patch.begin(), patch.end(), n) - patch.begin();
      }

      /** Which corner of a facet with the corner nodes @p corners is
       * @p node. */
      unsigned int
      corner_of(const std::array<unsigned int, 4> &corners,
                const unsigned int                 node)
      {
        for (unsigned int a = 0; a < 4; ++a)
          if (corners[a] == node)
            return a;
        Assert(false, ExcInternalError());
        return 0u;
      }
    } // namespace



    void
    MortarContactPair::Implementation::patch_of(
      const Pass                &pass,
      const unsigned int         k,
      std::vector<unsigned int> &patch) const
    {
      patch.clear();
      const auto add_facet = [&](const unsigned int f) {
        patch.insert(patch.end(), facet_nodes[f].begin(), facet_nodes[f].end());
      };
      for (unsigned int j = pass.facet_start[k]; j < pass.facet_start[k + 1];
           ++j)
        add_facet(pass.node_facets[j]);
      const bool tied =
        definition.type == model::ContactPairDefinition::Type::tied;
      for (unsigned int j = pass.gap_start[k]; j < pass.gap_start[k + 1]; ++j)
        {
          const unsigned int i = pass.node_gap_facets[j];
          add_facet(pass.gap_facets[i]);
          if (!tied)
            for (const unsigned int m : pass.candidates[i])
              add_facet(m);
        }
      if (tied)
        for (const StoredSegment &s : pass.segments)
          for (unsigned int j = pass.gap_start[k]; j < pass.gap_start[k + 1];
               ++j)
            if (s.slave == pass.node_gap_facets[j])
              add_facet(s.master);
      std::sort(patch.begin(), patch.end());
      patch.erase(std::unique(patch.begin(), patch.end()), patch.end());
    }



    template <typename Number>
    bool
    MortarContactPair::Implementation::node_forces(
      const Pass                               &pass,
      const unsigned int                        k,
      const std::vector<unsigned int>          &patch,
      const std::vector<Point<3, Number>>      &y,
      const double                              time,
      std::vector<Tensor<1, 3, Number>>        &force,
      std::vector<std::array<unsigned int, 3>> &overlaps,
      const bool                                record) const
    {
      using Vector            = Tensor<1, 3, Number>;
      const unsigned int node = pass.nodes[k];
      const bool         tied =
        definition.type == model::ContactPairDefinition::Type::tied;
      if (tied && !pass.tied[node])
        return false;

      // The rows of this node in this rank's segments (they carry its
      // traction), its covered area, weighted gap and weighted slip.
      std::vector<SegmentRow<Number>> rows;
      Number                          A = 0.;
      Vector                          gap, slip;
      if (tied)
        {
          tied_rows(pass, node, patch, y, rows, gap);
          A = pass.tied_area[node];
        }
      else
        contact_rows(pass, k, patch, y, overlaps, record, rows, A, gap, slip);
      if (rows.empty() || !(value_of(A) > 0.))
        return false;

      // The traction, as add_forces() has it.
      Vector traction, n;
      Number g = 0., p = 0.;
      if (tied)
        traction = Number(-pass.penalty / A) * gap;
      else
        {
          const auto position =
            [&](const unsigned int node) -> const Point<3, Number> & {
            return y[patch_index(patch, node)];
          };
          n = nodal_normal<Number>(pass, k, position);
          g = -(n * gap) / A;
          // A closed gap (g = 0, to the round-off of the integrals) is
          // active: its derivative is the closed side's, so that a body
          // held only by faces that touch in the mesh has stiffness; its
          // force, p = 0, is the same. (A gap within the round-off is
          // taken as 0 itself: its p < 0 would make friction's cone
          // negative.)
          if (!(value_of(g) <= closed_gap))
            return false;
          if (value_of(g) > 0.)
            g -= value_of(g);
          p        = -pass.penalty * g;
          traction = Number(-p) * n;
          if (coulomb)
            {
              Vector     old, increment;
              bool       slipping;
              const auto tangential =
                coulomb_return_mapping(pass.accepted_tangential[node],
                                       n,
                                       slip,
                                       A,
                                       p,
                                       pass.penalty,
                                       time - time_accepted,
                                       definition,
                                       old,
                                       increment,
                                       slipping);
              traction += tangential;
            }
        }
      add_row_forces(rows, tied, traction, p, g, n, patch, y, force);
      return true;
    }



    template <typename Number>
    void
    MortarContactPair::Implementation::tied_rows(
      const Pass                          &pass,
      const unsigned int                   node,
      const std::vector<unsigned int>     &patch,
      const std::vector<Point<3, Number>> &y,
      std::vector<SegmentRow<Number>>     &rows,
      Tensor<1, 3, Number>                &gap) const
    {
      const auto at = [&](const unsigned int n) {
        return patch_index(patch, n);
      };
      // The reference integrals, fixed: the gap is linear in y.
      for (const StoredSegment &s : pass.segments)
        {
          const unsigned int f = pass.gap_facets[s.slave];
          if (std::find(facet_nodes[f].begin(), facet_nodes[f].end(), node) ==
              facet_nodes[f].end())
            continue;
          const unsigned int a  = corner_of(facet_nodes[f], node);
          const auto        &sn = facet_nodes[f];
          const auto        &mn = facet_nodes[s.master];
          SegmentRow<Number> row{};
          row.slave_facet  = f;
          row.master_facet = s.master;
          for (unsigned int b = 0; b < 4; ++b)
            {
              row.D[b] = s.integrals.D[a][b];
              row.M[b] = s.integrals.M[a][b];
              gap += row.D[b] * minus(y[at(sn[b])], node_reference[sn[b]]) -
                     row.M[b] * minus(y[at(mn[b])], node_reference[mn[b]]);
            }
          if (owns(pass, s.slave))
            rows.push_back(row);
        }
    }



    template <typename Number>
    void
    MortarContactPair::Implementation::contact_rows(
      const Pass                               &pass,
      const unsigned int                        k,
      const std::vector<unsigned int>          &patch,
      const std::vector<Point<3, Number>>      &y,
      std::vector<std::array<unsigned int, 3>> &overlaps,
      const bool                                record,
      std::vector<SegmentRow<Number>>          &rows,
      Number                                   &A,
      Tensor<1, 3, Number>                     &gap,
      Tensor<1, 3, Number>                     &slip) const
    {
      const unsigned int node = pass.nodes[k];
      const auto         at   = [&](const unsigned int n) {
        return patch_index(patch, n);
      };
      // The pairs of a gap facet around the node and a master facet to
      // integrate: all candidates, or those of @p overlaps (the cut
      // is decided on doubles only).
      Assert((!record || std::is_same<Number, double>::value),
             ExcInternalError());
      if (record)
        {
          overlaps.clear();
          for (unsigned int j = pass.gap_start[k]; j < pass.gap_start[k + 1];
               ++j)
            for (const unsigned int m :
                 pass.candidates[pass.node_gap_facets[j]])
              overlaps.push_back({{pass.node_gap_facets[j], m, 0u}});
        }
      std::vector<std::array<unsigned int, 3>> kept;
      FacetCornersOf<Number>                   slave_corners, master_corners;
      MortarSegmentOf<Number>                  segment;
      for (const auto &[i, m, tapered] : overlaps)
        {
          const unsigned int f  = pass.gap_facets[i];
          const unsigned int a  = corner_of(facet_nodes[f], node);
          const auto        &sn = facet_nodes[f];
          const auto        &mn = facet_nodes[m];
          for (unsigned int b = 0; b < 4; ++b)
            {
              slave_corners[b]  = y[at(sn[b])];
              master_corners[b] = y[at(mn[b])];
            }
          // The values: the whole segment, for the same weight as
          // add_forces(). The derivatives: the node's row only, of the
          // segments that passed, all rows where the weight is below
          // 1 (it depends on them).
          const bool all_rows = record || tapered;
          if (!integrate_mortar_segment(slave_corners,
                                        master_corners,
                                        segment,
                                        all_rows ? 4 : a))
            continue;
          SegmentRow<Number> row{};
          row.slave_facet  = f;
          row.master_facet = m;
          if (all_rows)
            {
              Tensor<1, 3, Number> weighted[4];
              row.weight = mortar_segment_weight(slave_corners,
                                                 master_corners,
                                                 segment,
                                                 margin,
                                                 weighted,
                                                 row.weight_gradient);
              if (record)
                {
                  if (!(value_of(row.weight) > 0.))
                    continue;
                  kept.push_back({{i, m, value_of(row.weight) < 1. ? 1u : 0u}});
                }
              row.tapered = value_of(row.weight) < 1.;
              column_sums(segment, row.column_D, row.column_M);
            }
          row.slope  = segment.slope;
          row.normal = segment.normal;
          for (unsigned int b = 0; b < 4; ++b)
            {
              row.D[b] = segment.D[a][b];
              row.M[b] = segment.M[a][b];
              A += row.weight * row.D[b];
              gap += row.weight * (row.D[b] * slave_corners[b] -
                                   row.M[b] * master_corners[b]);
              if (coulomb)
                slip +=
                  row.weight *
                  (row.D[b] * minus(slave_corners[b], x_accepted[sn[b]]) -
                   row.M[b] * minus(master_corners[b], x_accepted[mn[b]]));
            }
          if (owns(pass, i))
            rows.push_back(row);
        }
      if (record)
        overlaps = kept;
    }



    template <typename Number>
    void
    MortarContactPair::Implementation::add_row_forces(
      const std::vector<SegmentRow<Number>> &rows,
      const bool                             tied,
      const Tensor<1, 3, Number>            &traction,
      const Number                          &p,
      const Number                          &g,
      const Tensor<1, 3, Number>            &n,
      const std::vector<unsigned int>       &patch,
      const std::vector<Point<3, Number>>   &y,
      std::vector<Tensor<1, 3, Number>>     &force) const
    {
      using Vector  = Tensor<1, 3, Number>;
      const auto at = [&](const unsigned int node) {
        return patch_index(patch, node);
      };
      // w D t on the slave side, -w M t on the master side, t with the
      // segment's normal traction (add_forces()); where the weight is
      // below 1, the node's spring's share of the weight's forces
      // (weight_forces()).
      for (const SegmentRow<Number> &row : rows)
        {
          const auto  &sn = facet_nodes[row.slave_facet];
          const auto  &mn = facet_nodes[row.master_facet];
          const Vector t =
            tied ? traction :
                   segment_traction(traction, p, n, row.normal, row.slope);
          for (unsigned int b = 0; b < 4; ++b)
            {
              force[at(sn[b])] += Number(row.weight * row.D[b]) * t;
              force[at(mn[b])] -= Number(row.weight * row.M[b]) * t;
            }
          if (tied || !row.tapered || !(value_of(p) > 0.))
            continue;
          Number row_area = 0.;
          Vector row_gap;
          for (unsigned int b = 0; b < 4; ++b)
            {
              row_area += row.D[b];
              row_gap += row.D[b] * y[at(sn[b])] - row.M[b] * y[at(mn[b])];
            }
          const Number minus_dE_dw =
            -spring_energy_weight_derivative(p, g, n, row_gap, row_area);
          for (unsigned int b = 0; b < 4; ++b)
            {
              force[at(sn[b])] +=
                Number(minus_dE_dw * row.column_D[b]) * row.weight_gradient;
              force[at(mn[b])] -=
                Number(minus_dE_dw * row.column_M[b]) * row.weight_gradient;
            }
        }
    }



    void
    MortarContactPair::Implementation::add_tangents(
      const Pass                                   &pass,
      const double                                  time,
      const model::ForceContribution::TangentBlock &add) const
    {
      std::vector<unsigned int>                patch;
      std::vector<Point<3>>                    y;
      std::vector<Tensor<1, 3>>                force;
      std::vector<Point<3, ADNumber>>          y_ad;
      std::vector<Tensor<1, 3, ADNumber>>      force_ad;
      std::vector<types::global_dof_index>     dofs;
      std::vector<double>                      K;
      std::vector<std::array<unsigned int, 3>> overlaps;
      // (Tied pairs integrate their stored segments, not candidates.)
      const bool tied =
        definition.type == model::ContactPairDefinition::Type::tied;
      for (unsigned int k = 0; k < pass.nodes.size(); ++k)
        {
          // Only a node with a facet of this rank carries forces here.
          if (!has_own_facet(pass, k))
            continue;
          patch_of(pass, k, patch);
          const unsigned int n_nodes = patch.size();
          // The values first: most nodes carry no traction.
          y.resize(n_nodes);
          for (unsigned int j = 0; j < n_nodes; ++j)
            y[j] = x[patch[j]];
          force.assign(n_nodes, Tensor<1, 3>());
          if (!node_forces(pass, k, patch, y, time, force, overlaps, true))
            continue;

          // The derivatives on the nodes that count: those of the node's
          // slave facets and of the master facets they overlap (a third of
          // the candidates' in the patch test; a tied pair's patch has
          // only its segments' already).
          if (!tied)
            {
              patch.clear();
              for (unsigned int j = pass.facet_start[k];
                   j < pass.facet_start[k + 1];
                   ++j)
                for (const unsigned int node : facet_nodes[pass.node_facets[j]])
                  patch.push_back(node);
              for (const auto &overlap : overlaps)
                for (const unsigned int node : facet_nodes[overlap[1]])
                  patch.push_back(node);
              std::sort(patch.begin(), patch.end());
              patch.erase(std::unique(patch.begin(), patch.end()), patch.end());
            }
          const unsigned int n_patch = patch.size();
          const unsigned int n       = 3 * n_patch;
          y_ad.resize(n_patch);
          for (unsigned int j = 0; j < n_patch; ++j)
            for (unsigned int d = 0; d < 3; ++d)
              y_ad[j][d] = ADNumber(n, 3 * j + d, x[patch[j]][d]);
          force_ad.assign(n_patch, Tensor<1, 3, ADNumber>());
          node_forces(pass, k, patch, y_ad, time, force_ad, overlaps, false);
          // The resisting force is minus the force on the solid.
          dofs.resize(n);
          K.assign(n * n, 0.);
          for (unsigned int i = 0; i < n_patch; ++i)
            for (unsigned int d = 0; d < 3; ++d)
              {
                dofs[3 * i + d]   = node_global_dofs[patch[i]][d];
                const ADNumber &f = force_ad[i][d];
                if (f.size() == 0)
                  continue;
                for (unsigned int j = 0; j < n; ++j)
                  K[n * (3 * i + d) + j] = -f.dx(j);
              }
          add(dofs, K);
        }
    }



    bool
    MortarContactPair::supports_implicit() const
    {
      return true;
    }



    bool
    MortarContactPair::symmetric_tangent() const
    {
      // D and M differ, and the normal turns with the slave side only.
      return false;
    }



    void
    MortarContactPair::add_tangents(const model::EvaluationPoint &point,
                                    const TangentBlock           &add) const
    {
      Implementation &I = *impl;
      I.load_positions(point.displacement);
      for (const Implementation::Pass &pass : I.passes)
        I.add_tangents(pass, point.time, add);
    }



    void
    MortarContactPair::update_couplings(const model::EvaluationPoint &point)
    {
      Implementation &I = *impl;
      I.load_positions(point.displacement);
      std::vector<unsigned int>                patch;
      std::vector<Point<3>>                    y;
      std::vector<Tensor<1, 3>>                force;
      std::vector<std::array<unsigned int, 3>> overlaps;
      bool                                     grown = false;
      for (Implementation::Pass &pass : I.passes)
        {
          pass.coupled.resize(pass.nodes.size(), false);
          for (unsigned int k = 0; k < pass.nodes.size(); ++k)
            {
              if (pass.coupled[k] || !I.has_own_facet(pass, k))
                continue;
              // The same test as add_tangents()'s, at the same positions:
              // a node it will write a block for is marked here first.
              I.patch_of(pass, k, patch);
              y.resize(patch.size());
              for (unsigned int j = 0; j < patch.size(); ++j)
                y[j] = I.x[patch[j]];
              force.assign(patch.size(), Tensor<1, 3>());
              if (I.node_forces(pass,
                                k,
                                patch,
                                y,
                                point.time,
                                force,
                                overlaps,
                                true))
                {
                  pass.coupled[k] = true;
                  grown           = true;
                }
            }
        }
      if (grown)
        ++I.coupling_growths;
    }



    void
    MortarContactPair::add_couplings(const CouplingBlock &add) const
    {
      const Implementation                &I = *impl;
      std::vector<unsigned int>            patch;
      std::vector<types::global_dof_index> dofs;
      for (const Implementation::Pass &pass : I.passes)
        for (unsigned int k = 0; k < pass.nodes.size(); ++k)
          {
            if (k >= pass.coupled.size() || !pass.coupled[k] ||
                !I.has_own_facet(pass, k))
              continue;
            I.patch_of(pass, k, patch);
            dofs.clear();
            for (const unsigned int node : patch)
              dofs.insert(dofs.end(),
                          I.node_global_dofs[node].begin(),
                          I.node_global_dofs[node].end());
            add(dofs);
          }
    }



    unsigned int
    MortarContactPair::couplings_version() const
    {
      return impl->timings.searches + impl->coupling_growths;
    }
  } // namespace contact
} // namespace rubberdyn
