// The developer's trace of a mortar pair's energy error
// (--trace-pair <pair name>[:EVERY]; doc/contact.md, "Where a pair makes
// energy"): which slave nodes make a step's error, and how.
//
// The pair's forces are linear in its nodes' tractions: node a's traction
// t_a acts through its rows of the segments (w D_ab t_a on the slave
// corners, -w M_ak t_a on the master corners) and through its share of the
// weights' forces (weight_forces()). So the step's trapezoidal work
// splits exactly into the nodes' shares, and with each node's springs'
// energy a node's share of the step's error is
//   delta_a = (W_a(old state) + W_a(new state)) / 2 + E_a(new) - E_a(old),
// W_a(state) the work of node a's forces of that state over the step's
// displacements, plus friction's dissipation at the node. The shares sum
// to the pair's error increment up to the penalty updates' energy, which
// the trace leaves out. The work splits into the normal part of the
// segments' tractions (WN), their tangential part (WT) and the weights'
// forces (Ww), the energy into the normal (EN) and the tangential springs
// (ET): a conservative normal part has WN = -dEN, a consistent friction
// WT + dET + D = 0. Every EVERY accepted steps
// (default 1000) the shares summed since the last report are written, with
// the largest nodes' and the two largest nodes' segments.
#include <rubberdyn/contact/mortar_contact_pair.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <utility>

#include "mortar_contact_pair_implementation.h"

namespace rubberdyn
{
  namespace contact
  {
    void
    MortarContactPair::Implementation::trace_step(const double error_now)
    {
      const unsigned int n = x.size();
      // This evaluation's springs' energy and mean gap per node.
      std::vector<double> normal_now(n, 0.), tangential_now(n, 0.),
        gap_now(n, 0.), penalty_now(n, 0.);
      for (const Pass &pass : passes)
        for (const unsigned int node : pass.nodes)
          {
            const double A    = area[node];
            const double g    = A > 0. ? -(normal[node] * gap[node]) / A : 0.;
            gap_now[node]     = g;
            penalty_now[node] = pass.penalty;
            if (A > 0. && g < 0.)
              normal_now[node] += 0.5 * pass.penalty * A * g * g;
            if (coulomb)
              tangential_now[node] += pass.trial_spring_energy[node];
          }
      if (trace.shares_since_report.size() != n)
        trace.shares_since_report.assign(n, {});

      if (trace.have_old)
        {
          add_trace_shares(normal_now,
                           tangential_now,
                           gap_now,
                           penalty_now,
                           error_now);
          if (++trace.steps_since_report >= trace.report_every)
            {
              report_trace(gap_now, error_now);
              trace.shares_since_report.assign(n, {});
              trace.steps_since_report = 0;
              trace.error_at_report    = error_now;
            }
        }
      else
        trace.error_at_report = error_now;
      trace.have_old = true;
      trace.x        = x;
      trace.segments.resize(passes.size());
      for (unsigned int p = 0; p < passes.size(); ++p)
        trace.segments[p] = passes[p].segments;
      trace.traction          = traction;
      trace.normal            = normal;
      trace.normal_energy     = std::move(normal_now);
      trace.tangential_energy = std::move(tangential_now);
      trace.gap               = std::move(gap_now);
      trace.penalty           = std::move(penalty_now);
      trace.error             = error_now;
    }



    void
    MortarContactPair::Implementation::trace_state_work(
      const std::vector<StoredSegment> &segments,
      const Pass                       &pass,
      const std::vector<Point<3>>      &at,
      const std::vector<Tensor<1, 3>>  &t,
      const std::vector<Tensor<1, 3>>  &normals,
      const std::vector<double>        &gaps,
      const std::vector<double>        &penalties,
      std::vector<double>              &W_normal,
      std::vector<double>              &W_tangential,
      std::vector<double>              &W_weight) const
    {
      // A state's (its segments, positions, tractions, normals, gaps
      // and penalties) work over the step's displacements, by node:
      // the normal and the tangential part of its segments'
      // tractions, and its share of the weights' forces.
      for (const StoredSegment &s : segments)
        {
          const auto &sn = facet_nodes[pass.gap_facets[s.slave]];
          const auto &mn = facet_nodes[s.master];
          // The weight's change over the step, to first order.
          double weight_change = 0., column_D[4], column_M[4];
          column_sums(s.integrals, column_D, column_M);
          for (unsigned int b = 0; b < 4; ++b)
            weight_change +=
              s.weight_gradient * (column_D[b] * (x[sn[b]] - trace.x[sn[b]]) -
                                   column_M[b] * (x[mn[b]] - trace.x[mn[b]]));
          for (unsigned int a = 0; a < 4; ++a)
            {
              const unsigned int node = sn[a];
              Tensor<1, 3>       displacement;
              double             row_area = 0.;
              Tensor<1, 3>       row_gap;
              for (unsigned int b = 0; b < 4; ++b)
                {
                  displacement +=
                    s.integrals.D[a][b] * (x[sn[b]] - trace.x[sn[b]]) -
                    s.integrals.M[a][b] * (x[mn[b]] - trace.x[mn[b]]);
                  row_area += s.integrals.D[a][b];
                  row_gap += s.integrals.D[a][b] * at[sn[b]] -
                             s.integrals.M[a][b] * at[mn[b]];
                }
              const double g = gaps[node];
              const double p = g < 0. ? -penalties[node] * g : 0.;
              if (t[node].norm_square() == 0.)
                continue;
              // The segment's traction (add_forces()) and its
              // tangential part (the node's traction's).
              const Tensor<1, 3> full       = segment_traction(t[node],
                                                         p,
                                                         normals[node],
                                                         s.integrals.normal,
                                                         s.integrals.slope);
              const Tensor<1, 3> tangential = t[node] + p * normals[node];
              W_tangential[node] += s.weight * (tangential * displacement);
              W_normal[node] += s.weight * ((full - tangential) * displacement);
              if (weight_change != 0. && g < 0.)
                W_weight[node] -= spring_energy_weight_derivative(p,
                                                                  g,
                                                                  normals[node],
                                                                  row_gap,
                                                                  row_area) *
                                  weight_change;
            }
        }
    }



    void
    MortarContactPair::Implementation::add_trace_shares(
      const std::vector<double> &normal_now,
      const std::vector<double> &tangential_now,
      const std::vector<double> &gap_now,
      const std::vector<double> &penalty_now,
      const double               error_now)
    {
      const unsigned int  n = x.size();
      std::vector<double> WN_old(n, 0.), WN_new(n, 0.), WT_old(n, 0.),
        WT_new(n, 0.), WW_old(n, 0.), WW_new(n, 0.);
      for (unsigned int p = 0; p < passes.size(); ++p)
        {
          trace_state_work(passes[p].segments,
                           passes[p],
                           x,
                           traction,
                           normal,
                           gap_now,
                           penalty_now,
                           WN_new,
                           WT_new,
                           WW_new);
          trace_state_work(trace.segments[p],
                           passes[p],
                           trace.x,
                           trace.traction,
                           trace.normal,
                           trace.gap,
                           trace.penalty,
                           WN_old,
                           WT_old,
                           WW_old);
        }
      // The step's shares; the largest one for the jump line.
      double       sum = 0., largest_share = 0.;
      unsigned int largest_node = 0;
      for (unsigned int a = 0; a < n; ++a)
        {
          const std::array<double, Trace::n_shares> step_shares = {
            {0.5 * (WN_old[a] + WN_new[a]),
             0.5 * (WT_old[a] + WT_new[a]),
             0.5 * (WW_old[a] + WW_new[a]),
             normal_now[a] - trace.normal_energy[a],
             tangential_now[a] - trace.tangential_energy[a],
             trace.dissipation.empty() ? 0. : trace.dissipation[a]}};
          double delta = 0.;
          for (unsigned int k = 0; k < Trace::n_shares; ++k)
            {
              trace.shares_since_report[a][k] += step_shares[k];
              delta += step_shares[k];
            }
          sum += delta;
          if (std::abs(delta) > std::abs(largest_share))
            {
              largest_share = delta;
              largest_node  = a;
            }
        }
      const double increment = error_now - trace.error;
      if (std::abs(increment) > 0.02 || std::abs(largest_share) > 0.02)
        std::fprintf(stderr,
                     "TRACE %s t=%.5f jump inc=%.4f sum=%.4f node %u\n",
                     definition.name.c_str(),
                     trial_time,
                     increment,
                     sum,
                     largest_node);
    }



    void
    MortarContactPair::Implementation::report_trace(
      const std::vector<double> &gap_now,
      const double               error_now) const
    {
      const unsigned int n = x.size();
      // The nodes with the largest shares since the last report,
      // and the split of the pair's sum.
      const auto print_shares =
        [](const std::array<double, Trace::n_shares> &shares) {
          for (unsigned int k = 0; k < Trace::n_shares; ++k)
            std::fprintf(stderr,
                         " %s %+.4f",
                         Trace::share_labels[k],
                         shares[k]);
        };
      std::vector<std::pair<double, unsigned int>> largest;
      std::array<double, Trace::n_shares>          totals = {};
      double                                       total  = 0.;
      for (unsigned int a = 0; a < n; ++a)
        {
          double delta = 0.;
          for (unsigned int k = 0; k < Trace::n_shares; ++k)
            {
              totals[k] += trace.shares_since_report[a][k];
              delta += trace.shares_since_report[a][k];
            }
          total += delta;
          if (delta != 0.)
            largest.emplace_back(delta, a);
        }
      std::sort(largest.begin(), largest.end(), [](auto &l, auto &r) {
        return std::abs(l.first) > std::abs(r.first);
      });
      std::vector<unsigned int> n_segments(n, 0);
      for (const Pass &pass : passes)
        for (const StoredSegment &s : pass.segments)
          for (const unsigned int node : facet_nodes[pass.gap_facets[s.slave]])
            ++n_segments[node];
      std::fprintf(stderr,
                   "TRACE %s t=%.5f steps=%u error %+.4f (inc %+.4f) "
                   "nodes' sum %+.4f =",
                   definition.name.c_str(),
                   trial_time,
                   trace.steps_since_report,
                   error_now,
                   error_now - trace.error_at_report,
                   total);
      print_shares(totals);
      std::fprintf(stderr, "\n");
      for (unsigned int k = 0; k < std::min<std::size_t>(8, largest.size());
           ++k)
        {
          const unsigned int a = largest[k].second;
          std::fprintf(stderr,
                       "  node %u x=(%.2f %.2f %.2f) n=(%.2f %.2f %.2f) "
                       "d=%+.4f",
                       a,
                       x[a][0],
                       x[a][1],
                       x[a][2],
                       normal[a][0],
                       normal[a][1],
                       normal[a][2],
                       largest[k].first);
          print_shares(trace.shares_since_report[a]);
          std::fprintf(stderr,
                       " g=%.4f A=%.3f nseg=%u slip=%d |t|=%.4f\n",
                       gap_now[a],
                       area[a],
                       n_segments[a],
                       trace.slipping.empty() ? 0 : int(trace.slipping[a]),
                       traction[a].norm());
          // The two largest shares' segments.
          if (k < 2)
            print_trace_segments(a);
        }
    }



    void
    MortarContactPair::Implementation::print_trace_segments(
      const unsigned int a) const
    {
      // Node a's segments: weight, the node's
      // row of the covered area, the slave plane's normal n0,
      // the master facet's normal m (from its diagonals), the
      // slope in the forces and the slope of a flat master
      // facet with normal m, -(m - (m.n0) n0) / (m.n0): where
      // they differ, the slope was limited (max_mortar_slope)
      // or the facet is warped.
      for (const Pass &pass : passes)
        for (const StoredSegment &s : pass.segments)
          {
            const auto  &sn  = facet_nodes[pass.gap_facets[s.slave]];
            unsigned int row = 4;
            for (unsigned int c = 0; c < 4; ++c)
              if (sn[c] == a)
                row = c;
            if (row == 4)
              continue;
            const auto  &mn = facet_nodes[s.master];
            Tensor<1, 3> m =
              cross_product_3d(x[mn[2]] - x[mn[0]], x[mn[3]] - x[mn[1]]);
            m /= m.norm();
            const Tensor<1, 3> n0         = s.integrals.normal;
            const Tensor<1, 3> flat_slope = -(m - (m * n0) * n0) / (m * n0);
            double             row_area   = 0.;
            for (unsigned int b = 0; b < 4; ++b)
              row_area += s.integrals.D[row][b];
            std::fprintf(stderr,
                         "    segment master %u w=%.3f A_row=%.3f "
                         "n0=(%.3f %.3f %.3f) m=(%.3f %.3f %.3f) "
                         "slope=(%.3f %.3f %.3f) "
                         "flat=(%.3f %.3f %.3f)\n",
                         s.master,
                         s.weight,
                         row_area,
                         n0[0],
                         n0[1],
                         n0[2],
                         m[0],
                         m[1],
                         m[2],
                         s.integrals.slope[0],
                         s.integrals.slope[1],
                         s.integrals.slope[2],
                         flat_slope[0],
                         flat_slope[1],
                         flat_slope[2]);
          }
    }
  } // namespace contact
} // namespace rubberdyn
