// The developer's trace of a mortar pair's energy error
// (RUBBERDYN_PAIR_TRACE=<pair name>; doc/contact.md, "Where a pair makes
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
// displacements. The shares sum to the pair's error increment, up to
// friction's dissipation and the penalty updates' energy, which the trace
// leaves out.
#include <rubberdyn/contact/mortar_contact_pair.h>

#include <algorithm>
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
      std::vector<double> energy_now(n, 0.), gap_now(n, 0.), penalty_now(n, 0.);
      for (const Pass &pass : passes)
        for (const unsigned int node : pass.nodes)
          {
            const double A    = area[node];
            const double g    = A > 0. ? -(normal[node] * gap[node]) / A : 0.;
            gap_now[node]     = g;
            penalty_now[node] = pass.penalty;
            if (A > 0. && g < 0.)
              energy_now[node] += 0.5 * pass.penalty * A * g * g;
            if (coulomb)
              energy_now[node] += pass.trial_spring_energy[node];
          }
      std::vector<unsigned int> n_segments(n, 0);
      for (const Pass &pass : passes)
        for (const StoredSegment &s : pass.segments)
          for (const unsigned int node : facet_nodes[pass.gap_facets[s.slave]])
            ++n_segments[node];

      if (trace.have_old)
        {
          // W_a of a state (its segments, positions, tractions, normals,
          // gaps and penalties) over the step's displacements.
          const auto work = [&](const std::vector<StoredSegment> &segments,
                                const Pass                       &pass,
                                const std::vector<Point<3>>      &at,
                                const std::vector<Tensor<1, 3>>  &t,
                                const std::vector<Tensor<1, 3>>  &normals,
                                const std::vector<double>        &gaps,
                                const std::vector<double>        &penalties,
                                std::vector<double>              &W) {
            for (const StoredSegment &s : segments)
              {
                const auto &sn = facet_nodes[pass.gap_facets[s.slave]];
                const auto &mn = facet_nodes[s.master];
                // The weight's change over the step, to first order.
                double weight_change = 0., column_D[4], column_M[4];
                column_sums(s.integrals, column_D, column_M);
                for (unsigned int b = 0; b < 4; ++b)
                  weight_change += s.weight_gradient *
                                   (column_D[b] * (x[sn[b]] - trace.x[sn[b]]) -
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
                    // The segment's traction (add_forces()).
                    W[node] += s.weight * (segment_traction(t[node],
                                                            p,
                                                            normals[node],
                                                            s.integrals.normal,
                                                            s.integrals.slope) *
                                           displacement);
                    if (weight_change != 0. && g < 0.)
                      W[node] -= spring_energy_weight_derivative(p,
                                                                 g,
                                                                 normals[node],
                                                                 row_gap,
                                                                 row_area) *
                                 weight_change;
                  }
              }
          };
          std::vector<double> W_old(n, 0.), W_new(n, 0.);
          for (unsigned int p = 0; p < passes.size(); ++p)
            {
              work(passes[p].segments,
                   passes[p],
                   x,
                   traction,
                   normal,
                   gap_now,
                   penalty_now,
                   W_new);
              work(trace.segments[p],
                   passes[p],
                   trace.x,
                   trace.traction,
                   trace.normal,
                   trace.gap,
                   trace.penalty,
                   W_old);
            }
          std::vector<std::pair<double, unsigned int>> shares;
          double                                       sum = 0.;
          for (unsigned int a = 0; a < n; ++a)
            {
              const double delta =
                0.5 * (W_old[a] + W_new[a]) + energy_now[a] - trace.energy[a];
              sum += delta;
              if (delta != 0.)
                shares.emplace_back(delta, a);
            }
          std::sort(shares.begin(), shares.end(), [](auto &l, auto &r) {
            return std::abs(l.first) > std::abs(r.first);
          });
          const double increment = error_now - trace.error;
          if (std::abs(increment) > 0.02 ||
              (!shares.empty() && std::abs(shares[0].first) > 0.02))
            {
              std::fprintf(stderr,
                           "TRACE %s t=%.5f inc=%.4f sum=%.4f\n",
                           definition.name.c_str(),
                           trial_time,
                           increment,
                           sum);
              for (unsigned int k = 0;
                   k < std::min<std::size_t>(5, shares.size());
                   ++k)
                {
                  const unsigned int a = shares[k].second;
                  std::fprintf(
                    stderr,
                    "  node %u x=(%.3f %.3f %.3f) d=%.4f A=%.3f->%.3f "
                    "g=%.5f->%.5f nseg=%u->%u E=%.4f->%.4f W=%.4f,%.4f "
                    "|t|=%.4f->%.4f\n",
                    a,
                    x[a][0],
                    x[a][1],
                    x[a][2],
                    shares[k].first,
                    trace.area[a],
                    area[a],
                    trace.gap[a],
                    gap_now[a],
                    trace.n_segments[a],
                    n_segments[a],
                    trace.energy[a],
                    energy_now[a],
                    W_old[a],
                    W_new[a],
                    trace.traction[a].norm(),
                    traction[a].norm());
                }
            }
        }
      trace.have_old = true;
      trace.x        = x;
      trace.segments.resize(passes.size());
      for (unsigned int p = 0; p < passes.size(); ++p)
        trace.segments[p] = passes[p].segments;
      trace.traction   = traction;
      trace.normal     = normal;
      trace.energy     = std::move(energy_now);
      trace.area       = area;
      trace.gap        = std::move(gap_now);
      trace.penalty    = std::move(penalty_now);
      trace.n_segments = std::move(n_segments);
      trace.error      = error_now;
    }
  } // namespace contact
} // namespace rubberdyn
