#include <deal.II/base/bounding_box.h>
#include <deal.II/base/geometry_info.h>
#include <deal.II/base/mpi.h>
#include <deal.II/numerics/rtree.h>

#include <rubberdyn/base/binary_io.h>
#include <rubberdyn/base/exceptions.h>
#include <rubberdyn/base/run_options.h>
#include <rubberdyn/contact/mortar_contact_pair.h>
#include <rubberdyn/model/model.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iterator>
#include <map>
#include <tuple>

#include "mortar_contact_pair_implementation.h"

namespace rubberdyn
{
  namespace contact
  {



    MortarContactPair::Implementation::Implementation(
      const model::Model                 &model,
      const model::ContactPairDefinition &definition)
      : definition(definition)
      , comm(model.comm)
      , my_rank(Utilities::MPI::this_mpi_process(model.comm))
    {
      AssertThrow(!model.uses_mixed_up(),
                  ExcMessage("mortar contact pairs need the Q1 dofs"));
      for (unsigned int k = 0; k < model.contact_pairs.size(); ++k)
        if (model.contact_pairs[k].name == definition.name)
          channel = 1 + k % 199; // deal.II's channels are below 200
      // --trace-pair NAME[:EVERY] (RunOptions; doc/contact.md).
      trace.enabled      = definition.name == run_options().traced_pair;
      trace.report_every = std::max(1u, run_options().trace_every);
      gather_facets(model);
      set_up_nodes(model);
      set_up_passes();
      // (x is the reference configuration here.)
      area_now.resize(facets.size());
      for (unsigned int f = 0; f < facets.size(); ++f)
        area_now[f] = current_facet_area(f);
      reference_area = area_now;
      set_penalty();
    }



    void
    MortarContactPair::Implementation::gather_facets(const model::Model &model)
    {
      // This rank's facets, then all of them, in an order that does not
      // depend on the partition (by their centres).
      std::vector<GatheredFacet>           own;
      const FiniteElement<3>              &fe = model.dof_handler.get_fe();
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      for (const auto &cell : model.dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const unsigned int face : cell->face_indices())
            if (cell->at_boundary(face))
              {
                const types::boundary_id id = cell->face(face)->boundary_id();
                const unsigned int       sides =
                  (definition.slave_boundary_ids.count(id) ? 1u : 0u) |
                  (definition.master_boundary_ids.count(id) ? 2u : 0u);
                if (sides == 0)
                  continue;
                cell->get_dof_indices(dofs);
                GatheredFacet facet;
                // The face's lexicographic vertices 0, 1, 3, 2 go round it.
                constexpr unsigned int cyclic[4] = {0, 1, 3, 2};
                unsigned int           vertex[4];
                for (unsigned int c = 0; c < 4; ++c)
                  vertex[c] =
                    GeometryInfo<3>::face_to_cell_vertices(face, cyclic[c]);
                // Outward: turn the order round if the normal points into
                // the cell.
                const Tensor<1, 3> n = cross_product_3d(
                  cell->vertex(vertex[2]) - cell->vertex(vertex[0]),
                  cell->vertex(vertex[3]) - cell->vertex(vertex[1]));
                if (n * (cell->face(face)->center() - cell->center()) < 0.)
                  std::swap(vertex[1], vertex[3]);
                for (unsigned int c = 0; c < 4; ++c)
                  {
                    for (unsigned int d = 0; d < 3; ++d)
                      {
                        facet.dofs[c][d] =
                          dofs[fe.component_to_system_index(d, vertex[c])];
                        facet.X[c][d] = cell->vertex(vertex[c])[d];
                      }
                  }
                const model::Part &part =
                  model.parts[model.part_of_material_id(cell->material_id())];
                facet.stiffness = part.law->bulk_modulus() *
                                  cell->face(face)->measure() / cell->measure();
                facet.rank  = my_rank;
                facet.sides = sides;
                own.push_back(facet);
              }
      for (const std::vector<GatheredFacet> &from_rank :
           Utilities::MPI::all_gather(comm, own))
        facets.insert(facets.end(), from_rank.begin(), from_rank.end());
      const auto centre_key = [](const GatheredFacet &f) {
        std::array<double, 3> c{};
        for (unsigned int a = 0; a < 4; ++a)
          for (unsigned int d = 0; d < 3; ++d)
            c[d] += 0.25 * f.X[a][d];
        return c;
      };
      std::sort(facets.begin(),
                facets.end(),
                [&](const GatheredFacet &a, const GatheredFacet &b) {
                  const auto ka = centre_key(a), kb = centre_key(b);
                  if (ka != kb)
                    return ka < kb;
                  return a.sides < b.sides;
                });
    }



    void
    MortarContactPair::Implementation::set_up_nodes(const model::Model &model)
    {
      // The nodes, numbered in the order of the facets.
      std::map<types::global_dof_index, unsigned int> node_of_dof;
      IndexSet ghosts(model.dof_handler.n_dofs());
      facet_nodes.resize(facets.size());
      for (unsigned int f = 0; f < facets.size(); ++f)
        for (unsigned int c = 0; c < 4; ++c)
          {
            const auto [it, inserted] =
              node_of_dof.emplace(facets[f].dofs[c][0], node_dofs.size());
            if (inserted)
              {
                node_dofs.push_back({});
                node_global_dofs.push_back({{facets[f].dofs[c][0],
                                             facets[f].dofs[c][1],
                                             facets[f].dofs[c][2]}});
                node_reference.emplace_back(facets[f].X[c][0],
                                            facets[f].X[c][1],
                                            facets[f].X[c][2]);
                for (unsigned int d = 0; d < 3; ++d)
                  if (!model.partitioner->in_local_range(facets[f].dofs[c][d]))
                    ghosts.add_index(facets[f].dofs[c][d]);
              }
            facet_nodes[f][c] = it->second;
          }
      ghosts.compress();
      partitioner = std::make_shared<Utilities::MPI::Partitioner>(
        model.partitioner->locally_owned_range(),
        ghosts,
        comm);
      for (unsigned int f = 0; f < facets.size(); ++f)
        for (unsigned int c = 0; c < 4; ++c)
          for (unsigned int d = 0; d < 3; ++d)
            node_dofs[facet_nodes[f][c]][d] =
              partitioner->global_to_local(facets[f].dofs[c][d]);
      u_pair.reinit(partitioner);
      f_pair.reinit(partitioner);
      for (const auto &dofs : node_dofs)
        for (const unsigned int i : dofs)
          if (i < partitioner->locally_owned_size())
            owned_surface_dofs.push_back(i);
      std::sort(owned_surface_dofs.begin(), owned_surface_dofs.end());
      audit.u_accepted.assign(owned_surface_dofs.size(), 0.);
      audit.f_accepted.assign(owned_surface_dofs.size(), 0.);
      const unsigned int n_nodes = node_dofs.size();
      x                          = node_reference;
      area.assign(n_nodes, 0.);
      gap.assign(n_nodes, Tensor<1, 3>());
      normal.assign(n_nodes, Tensor<1, 3>());
      traction.assign(n_nodes, Tensor<1, 3>());
      coulomb = definition.type == model::ContactPairDefinition::Type::coulomb;
      if (coulomb)
        {
          slip.assign(n_nodes, Tensor<1, 3>());
          x_accepted = node_reference;
        }
      node_stiffness.assign(n_nodes, 0.);
    }



    void
    MortarContactPair::Implementation::set_up_passes()
    {
      // The passes: slave -> master, and back for two-pass.
      std::vector<unsigned int> side_facets[2];
      double                    diagonal = 0.;
      for (unsigned int f = 0; f < facets.size(); ++f)
        {
          const GatheredFacet &facet = facets[f];
          diagonal += std::hypot(facet.X[2][0] - facet.X[0][0],
                                 facet.X[2][1] - facet.X[0][1],
                                 facet.X[2][2] - facet.X[0][2]);
          for (unsigned int side = 0; side < 2; ++side)
            if (facet.sides & (1u << side))
              side_facets[side].push_back(f);
        }
      margin = facets.empty() ? 0. : 0.5 * diagonal / facets.size();
      margin = std::max(margin, definition.tie_tolerance);
      // Self-contact (the same ids on both sides): every facet is a slave
      // of the others already, both ways: one pass, half the penalty, as
      // a two-pass pair.
      const bool self_contact =
        definition.slave_boundary_ids == definition.master_boundary_ids;
      const unsigned int n_passes =
        definition.two_pass && !self_contact ? 2 : 1;
      penalty_divisor = self_contact ? 2 : n_passes;
      passes.resize(n_passes);
      for (unsigned int p = 0; p < n_passes; ++p)
        {
          passes[p].slave_facets  = side_facets[p];
          passes[p].master_facets = side_facets[1 - p];
          set_up_pass(passes[p]);
        }
    }



    void
    MortarContactPair::Implementation::set_up_pass(Pass &pass)
    {
      const unsigned int n_nodes = node_dofs.size();
      // Which rank books a node: the lowest that owns a slave facet
      // around it; the gap facets: own ones and their neighbours.
      std::vector<unsigned int> booking_rank(
        n_nodes,
        std::numeric_limits<unsigned int>::max());
      std::vector<bool> near_own(n_nodes, false);
      for (const unsigned int f : pass.slave_facets)
        for (const unsigned int node : facet_nodes[f])
          {
            booking_rank[node] = std::min(booking_rank[node], facets[f].rank);
            if (facets[f].rank == my_rank)
              near_own[node] = true;
          }
      pass.counted.assign(n_nodes, false);
      for (unsigned int n = 0; n < n_nodes; ++n)
        pass.counted[n] = booking_rank[n] == my_rank;
      for (const unsigned int f : pass.slave_facets)
        {
          bool near = false;
          for (const unsigned int node : facet_nodes[f])
            near = near || near_own[node];
          if (near)
            pass.gap_facets.push_back(f);
        }
      // The gap facets' nodes and, for each, its slave facets.
      std::map<unsigned int, std::vector<unsigned int>> facets_of_node;
      for (const unsigned int f : pass.gap_facets)
        for (const unsigned int node : facet_nodes[f])
          facets_of_node[node];
      for (const unsigned int f : pass.slave_facets)
        for (const unsigned int node : facet_nodes[f])
          {
            const auto it = facets_of_node.find(node);
            if (it != facets_of_node.end())
              it->second.push_back(f);
          }
      pass.facet_start.push_back(0);
      for (const auto &[node, around] : facets_of_node)
        {
          pass.nodes.push_back(node);
          pass.node_facets.insert(pass.node_facets.end(),
                                  around.begin(),
                                  around.end());
          pass.facet_start.push_back(pass.node_facets.size());
        }
      {
        std::vector<std::vector<unsigned int>> around(pass.nodes.size());
        for (unsigned int i = 0; i < pass.gap_facets.size(); ++i)
          for (const unsigned int node : facet_nodes[pass.gap_facets[i]])
            around[std::lower_bound(pass.nodes.begin(),
                                    pass.nodes.end(),
                                    node) -
                   pass.nodes.begin()]
              .push_back(i);
        pass.gap_start.push_back(0);
        for (const auto &facets_around : around)
          {
            pass.node_gap_facets.insert(pass.node_gap_facets.end(),
                                        facets_around.begin(),
                                        facets_around.end());
            pass.gap_start.push_back(pass.node_gap_facets.size());
          }
      }
      pass.candidates.resize(pass.gap_facets.size());
      if (coulomb)
        {
          pass.accepted_tangential.assign(n_nodes, Tensor<1, 3>());
          pass.trial_tangential.assign(n_nodes, Tensor<1, 3>());
          pass.accepted_spring_energy.assign(n_nodes, 0.);
          pass.trial_spring_energy.assign(n_nodes, 0.);
          pass.accepted_slip_distance.assign(n_nodes, 0.);
          pass.trial_slip_distance.assign(n_nodes, 0.);
        }
      pass.shown_pressure.assign(n_nodes, 0.);
      pass.shown_gap.assign(n_nodes, 0.);
    }



    void
    MortarContactPair::Implementation::set_penalty()
    {
      for (unsigned int f = 0; f < facets.size(); ++f)
        area_now[f] = current_facet_area(f);
      // The smaller of the two sides' mean stiffness per area, K A / V, with
      // A the facet's area now.
      double mean_stiffness[2] = {0., 0.};
      for (unsigned int side = 0; side < 2; ++side)
        {
          const std::vector<unsigned int> &side_facets =
            side == 0 ? passes[0].slave_facets : passes[0].master_facets;
          for (const unsigned int f : side_facets)
            mean_stiffness[side] +=
              facets[f].stiffness * (area_now[f] / reference_area[f]);
          if (!side_facets.empty())
            mean_stiffness[side] /= side_facets.size();
        }
      const double penalty = definition.penalty_scale *
                             std::min(mean_stiffness[0], mean_stiffness[1]) /
                             penalty_divisor;
      std::fill(node_stiffness.begin(), node_stiffness.end(), 0.);
      for (Pass &pass : passes)
        {
          pass.penalty = penalty;
          // The penalty times the facet area around each node (the
          // stable step).
          for (const unsigned int side : {0u, 1u})
            for (const unsigned int f :
                 side == 0 ? pass.slave_facets : pass.master_facets)
              for (const unsigned int node : facet_nodes[f])
                node_stiffness[node] += pass.penalty * 0.25 * area_now[f];
        }
      if (!node_mass.empty())
        {
          double largest = 0.;
          for (unsigned int n = 0; n < x.size(); ++n)
            largest = std::max(largest, node_stiffness[n] / node_mass[n]);
          time_step = largest > 0. ? 2. / std::sqrt(2. * largest) :
                                     std::numeric_limits<double>::max();
          // A bound on the springs' step (LS-DYNA SOFT = 1): the penalty
          // from the nodal masses and the step where the material's would
          // be stiffer. The step goes as 1 / sqrt(penalty).
          penalty_factor = 1.;
          if (time_step < definition.penalty_time_step)
            {
              penalty_factor =
                (time_step / definition.penalty_time_step) *
                (time_step / definition.penalty_time_step);
              for (Pass &pass : passes)
                pass.penalty *= penalty_factor;
              for (double &k : node_stiffness)
                k *= penalty_factor;
              time_step = definition.penalty_time_step;
            }
        }
    }



    bool
    MortarContactPair::Implementation::share_a_node(const unsigned int f,
                                                    const unsigned int g) const
    {
      for (const unsigned int a : facet_nodes[f])
        for (const unsigned int b : facet_nodes[g])
          if (a == b)
            return true;
      return false;
    }



    void
    MortarContactPair::Implementation::update_positions(const VectorType &u)
    {
      for (unsigned int n = 0; n < node_dofs.size(); ++n)
        for (unsigned int d = 0; d < 3; ++d)
          x[n][d] = node_reference[n][d] + u.local_element(node_dofs[n][d]);
    }



    void
    MortarContactPair::Implementation::load_positions(const VectorType &u)
    {
      // Only the surfaces' owned dofs: they are all the pair reads and all
      // that other ranks import as their ghosts.
      for (const unsigned int i : owned_surface_dofs)
        u_pair.local_element(i) = u.local_element(i);
      u_pair.update_ghost_values();
      update_positions(u_pair);
    }



    void
    MortarContactPair::Implementation::book_trial_work()
    {
      double work = 0.;
      for (unsigned int k = 0; k < owned_surface_dofs.size(); ++k)
        {
          const unsigned int i = owned_surface_dofs[k];
          work += (audit.f_accepted[k] + f_pair.local_element(i)) *
                  (u_pair.local_element(i) - audit.u_accepted[k]);
        }
      audit.trial_work = audit.started ? audit.accepted_work + 0.5 * work : 0.;
    }



    void
    MortarContactPair::Implementation::search_if_needed()
    {
      if (searched)
        {
          double moved = 0.;
          for (unsigned int n = 0; n < x.size(); ++n)
            moved = std::max(moved, x[n].distance_square(x_at_search[n]));
          if (std::sqrt(moved) <= 0.25 * margin)
            return;
        }
      const auto start  = std::chrono::steady_clock::now();
      const auto box_of = [&](const unsigned int f) {
        Point<3> low = x[facet_nodes[f][0]], high = low;
        for (const unsigned int node : facet_nodes[f])
          for (unsigned int d = 0; d < 3; ++d)
            {
              low[d]  = std::min(low[d], x[node][d]);
              high[d] = std::max(high[d], x[node][d]);
            }
        BoundingBox<3> box(std::make_pair(low, high));
        box.extend(margin);
        return box;
      };
      std::vector<unsigned int> hits;
      for (Pass &pass : passes)
        {
          std::vector<BoundingBox<3>> master_boxes;
          master_boxes.reserve(pass.master_facets.size());
          for (const unsigned int f : pass.master_facets)
            master_boxes.push_back(box_of(f));
          const auto tree = pack_rtree_of_indices(master_boxes);
          for (unsigned int i = 0; i < pass.gap_facets.size(); ++i)
            {
              const unsigned int slave = pass.gap_facets[i];
              hits.clear();
              tree.query(boost::geometry::index::intersects(box_of(slave)),
                         std::back_inserter(hits));
              std::vector<unsigned int> &candidates = pass.candidates[i];
              candidates.clear();
              for (const unsigned int h : hits)
                if (!share_a_node(slave, pass.master_facets[h]))
                  candidates.push_back(pass.master_facets[h]);
              std::sort(candidates.begin(), candidates.end());
            }
          // Kept segments may miss a new candidate's.
          for (Pass::KeptSegments &kept : pass.kept)
            kept.valid = false;
        }
      x_at_search = x;
      searched    = true;
      ++timings.searches;
      timings.candidates = 0;
      for (const Pass &pass : passes)
        for (const auto &candidates : pass.candidates)
          timings.candidates += candidates.size();
      timings.search_seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
    }



    void
    MortarContactPair::Implementation::compute_normals(const Pass &pass)
    {
      const auto position =
        [this](const unsigned int node) -> const Point<3> & { return x[node]; };
      for (unsigned int k = 0; k < pass.nodes.size(); ++k)
        normal[pass.nodes[k]] = nodal_normal<double>(pass, k, position);
    }



    void
    MortarContactPair::Implementation::mark_open_nodes(const Pass &pass)
    {
      open_node.assign(x.size(), 0);
      // Per gap facet: clearly open towards each of its candidates, by
      // 1e-9 of its diagonal (far above the heights' round-off).
      open_facet.assign(pass.gap_facets.size(), 0);
      FacetCorners master_corners;
      for (unsigned int i = 0; i < pass.gap_facets.size(); ++i)
        {
          const auto             &s = facet_nodes[pass.gap_facets[i]];
          const MortarSlaveFacet &slave_facet = slave_facets[i];
          const double clearance = 1e-9 * (x[s[2]] - x[s[0]]).norm();
          bool         open      = true;
          for (const unsigned int m : pass.candidates[i])
            {
              const auto &mc = facet_nodes[m];
              for (unsigned int k = 0; k < 4; ++k)
                master_corners[k] = x[mc[k]];
              if (!slave_facet.clearly_open(master_corners,
                                            clearance,
                                            &master_bounds_of(m)))
                {
                  open = false;
                  break;
                }
            }
          open_facet[i] = open;
        }
      // A node is open if all its gap facets are, and its normal points
      // their normals' way (so that a positive multiple of a facet's
      // normal gives a positive gap at the node).
      for (unsigned int k = 0; k < pass.nodes.size(); ++k)
        {
          const unsigned int node = pass.nodes[k];
          bool               open = true;
          for (unsigned int j = pass.gap_start[k];
               j < pass.gap_start[k + 1] && open;
               ++j)
            {
              const unsigned int i = pass.node_gap_facets[j];
              open = open_facet[i] &&
                     normal[node] * slave_facets[i].unit_normal() > 0.;
            }
          open_node[node] = open;
        }
    }



    bool
    MortarContactPair::Implementation::kept_segments_hold(
      const Pass::KeptSegments &kept,
      const FacetCorners       &slave,
      const Tensor<1, 3>       &n) const
    {
      Tensor<1, 3> mean;
      for (unsigned int a = 0; a < 4; ++a)
        mean += 0.25 * (slave[a] - kept.slave_corners[a]);
      const double limit = definition.segment_reuse_slip;
      // The motion of a corner along the plane, relative to the facet's.
      const auto moved = [&](const Point<3> &now, const Point<3> &then) {
        Tensor<1, 3> relative = (now - then) - mean;
        relative -= (relative * n) * n;
        return relative.norm_square() > limit * limit;
      };
      for (unsigned int a = 0; a < 4; ++a)
        if (moved(slave[a], kept.slave_corners[a]))
          return false;
      for (const Pass::KeptSegment &k : kept.segments)
        for (unsigned int b = 0; b < 4; ++b)
          if (moved(x[facet_nodes[k.master][b]], k.master_corners[b]))
            return false;
      return true;
    }



    void
    MortarContactPair::Implementation::weight_forces(
      const Pass          &pass,
      const StoredSegment &s,
      Tensor<1, 3> (&on_slave)[4],
      Tensor<1, 3> (&on_master)[4]) const
    {
      const auto &sn = facet_nodes[pass.gap_facets[s.slave]];
      const auto &mn = facet_nodes[s.master];
      // -dE/dw, E = sum_a p_a^2 A_a / 2 eps over the segment's active
      // nodes: with G_a = w G_as + ..., A_a = w A_as + ... and the gap
      // g_a = -n . G_a / A_a, dE_a/dw = p_a (n . G_as + g_a A_as / 2).
      double minus_dE_dw = 0.;
      for (unsigned int a = 0; a < 4; ++a)
        {
          const unsigned int node = sn[a];
          const double       g    = pass.shown_gap[node];
          if (!(area[node] > 0.) || !(g < 0.))
            continue;
          const double p        = -pass.penalty * g;
          double       row_area = 0.;
          Tensor<1, 3> row_gap;
          for (unsigned int b = 0; b < 4; ++b)
            {
              row_area += s.integrals.D[a][b];
              row_gap +=
                s.integrals.D[a][b] * x[sn[b]] - s.integrals.M[a][b] * x[mn[b]];
            }
          minus_dE_dw -= spring_energy_weight_derivative(p,
                                                         g,
                                                         normal[node],
                                                         row_gap,
                                                         row_area);
        }
      double column_D[4], column_M[4];
      column_sums(s.integrals, column_D, column_M);
      for (unsigned int b = 0; b < 4; ++b)
        {
          on_slave[b]  = (minus_dE_dw * column_D[b]) * s.weight_gradient;
          on_master[b] = (-minus_dE_dw * column_M[b]) * s.weight_gradient;
        }
    }



    bool
    MortarContactPair::Implementation::integrate(Pass      &pass,
                                                 const bool keep_all,
                                                 const bool skip_open,
                                                 const bool reuse)
    {
      for (const unsigned int node : pass.nodes)
        {
          area[node] = 0.;
          gap[node]  = Tensor<1, 3>();
          if (coulomb)
            slip[node] = Tensor<1, 3>();
        }
      pass.segments.clear();
      // Each gap facet's plane and projected corners once for all its
      // candidates.
      FacetCorners slave_corners, master_corners;
      slave_facets.clear();
      for (const unsigned int f : pass.gap_facets)
        {
          const auto &s = facet_nodes[f];
          for (unsigned int a = 0; a < 4; ++a)
            slave_corners[a] = x[s[a]];
          slave_facets.emplace_back(slave_corners);
        }
      // Each candidate master facet's bounds once for all its slave
      // facets, when first asked for (master_bounds_of()).
      master_bounds.resize(facet_nodes.size());
      master_bounds_stamp.resize(facet_nodes.size(), 0);
      ++bounds_evaluation;
      if (skip_open)
        mark_open_nodes(pass);
      if (reuse)
        pass.kept.resize(pass.gap_facets.size());
      // A segment's share of its slave nodes' sums (weighted[a]: its
      // weighted gap vectors at the current positions).
      const auto add_segment = [&](const unsigned int   i,
                                   const unsigned int   m,
                                   const MortarSegment &segment,
                                   const Tensor<1, 3>(&weighted)[4],
                                   const double        w,
                                   const Tensor<1, 3> &weight_gradient) {
        const auto &s  = facet_nodes[pass.gap_facets[i]];
        const auto &mc = facet_nodes[m];
        for (unsigned int a = 0; a < 4; ++a)
          {
            for (unsigned int b = 0; b < 4; ++b)
              area[s[a]] += w * segment.D[a][b];
            gap[s[a]] += w * weighted[a];
          }
        if (coulomb)
          for (unsigned int a = 0; a < 4; ++a)
            for (unsigned int b = 0; b < 4; ++b)
              slip[s[a]] +=
                w * (segment.D[a][b] * (x[s[b]] - x_accepted[s[b]]) -
                     segment.M[a][b] * (x[mc[b]] - x_accepted[mc[b]]));
        if (keep_all || owns(pass, i))
          pass.segments.push_back({i, m, segment, w, weight_gradient});
      };
      bool          skipped = false;
      MortarSegment segment;
      Tensor<1, 3>  weighted[4], weight_gradient;
      for (unsigned int i = 0; i < pass.gap_facets.size(); ++i)
        {
          const auto &s = facet_nodes[pass.gap_facets[i]];
          if (skip_open && open_node[s[0]] && open_node[s[1]] &&
              open_node[s[2]] && open_node[s[3]])
            {
              skipped = true;
              continue;
            }
          for (unsigned int a = 0; a < 4; ++a)
            slave_corners[a] = x[s[a]];
          const MortarSlaveFacet &slave_facet = slave_facets[i];
          if (reuse)
            {
              Pass::KeptSegments &kept = pass.kept[i];
              // The kept integrals at the current positions, each within
              // the capture margin as a new one must be
              // (mortar_segment_weight()).
              bool hold = kept.valid &&
                          kept_segments_hold(kept,
                                             slave_corners,
                                             slave_facet.unit_normal());
              kept_weighted.resize(kept.segments.size());
              for (unsigned int k = 0; hold && k < kept.segments.size(); ++k)
                {
                  const auto &mc = facet_nodes[kept.segments[k].master];
                  for (unsigned int c = 0; c < 4; ++c)
                    master_corners[c] = x[mc[c]];
                  kept_weighted[k].weight =
                    mortar_segment_weight(slave_corners,
                                          master_corners,
                                          kept.segments[k].integrals,
                                          margin,
                                          kept_weighted[k].vectors,
                                          kept_weighted[k].gradient);
                  hold = kept_weighted[k].weight > 0.;
                }
              if (hold)
                {
                  for (unsigned int k = 0; k < kept.segments.size(); ++k)
                    add_segment(i,
                                kept.segments[k].master,
                                kept.segments[k].integrals,
                                kept_weighted[k].vectors,
                                kept_weighted[k].weight,
                                kept_weighted[k].gradient);
                  continue;
                }
              kept.valid         = true;
              kept.slave_corners = slave_corners;
              kept.segments.clear();
            }
          for (const unsigned int m : pass.candidates[i])
            {
              const auto &mc = facet_nodes[m];
              for (unsigned int k = 0; k < 4; ++k)
                master_corners[k] = x[mc[k]];
              if (!slave_facet.integrate(master_corners,
                                         segment,
                                         4,
                                         &master_bounds_of(m)))
                continue;
              const double w = mortar_segment_weight(slave_corners,
                                                     master_corners,
                                                     segment,
                                                     margin,
                                                     weighted,
                                                     weight_gradient);
              if (!(w > 0.))
                continue;
              add_segment(i, m, segment, weighted, w, weight_gradient);
              if (reuse)
                pass.kept[i].segments.push_back({m, segment, master_corners});
            }
        }
      return skipped;
    }



    void
    MortarContactPair::Implementation::refresh_shown_gaps(Pass &pass)
    {
      // The evaluation's sums and segments stay as they were. (The other
      // nodes' gaps come out as add_forces() gave them, to the bit.)
      const std::vector<double>        area_kept     = area;
      const std::vector<Tensor<1, 3>>  gap_kept      = gap;
      const std::vector<Tensor<1, 3>>  slip_kept     = slip;
      const std::vector<StoredSegment> segments_kept = pass.segments;
      compute_normals(pass);
      integrate(pass, false, false);
      for (const unsigned int node : pass.nodes)
        pass.shown_gap[node] =
          area[node] > 0. ? -(normal[node] * gap[node]) / area[node] : 0.;
      area          = area_kept;
      gap           = gap_kept;
      slip          = slip_kept;
      pass.segments = segments_kept;
    }



    void
    MortarContactPair::Implementation::save_kept_segments(
      std::ostream &out) const
    {
      std::vector<double> data = {double(searched)};
      for (const Point<3> &p : x_at_search)
        data.insert(data.end(), {p[0], p[1], p[2]});
      const auto add_corners = [&data](const FacetCorners &corners) {
        for (const Point<3> &p : corners)
          data.insert(data.end(), {p[0], p[1], p[2]});
      };
      for (const Pass &pass : passes)
        {
          data.push_back(pass.candidates.size());
          for (const std::vector<unsigned int> &candidates : pass.candidates)
            {
              data.push_back(candidates.size());
              data.insert(data.end(), candidates.begin(), candidates.end());
            }
          data.push_back(pass.kept.size());
          for (const Pass::KeptSegments &kept : pass.kept)
            {
              data.push_back(kept.valid);
              add_corners(kept.slave_corners);
              data.push_back(kept.segments.size());
              for (const Pass::KeptSegment &k : kept.segments)
                {
                  data.push_back(k.master);
                  const MortarSegment &g = k.integrals;
                  data.insert(data.end(), &g.D[0][0], &g.D[0][0] + 16);
                  data.insert(data.end(), &g.M[0][0], &g.M[0][0] + 16);
                  data.push_back(g.area);
                  for (unsigned int d = 0; d < 3; ++d)
                    data.insert(data.end(), {g.slope[d], g.normal[d]});
                  add_corners(k.master_corners);
                }
            }
        }
      const double size = data.size();
      binary_io::write_doubles(out, &size, 1);
      binary_io::write_doubles(out, data.data(), data.size());
    }



    void
    MortarContactPair::Implementation::load_kept_segments(std::istream &in)
    {
      double size = 0.;
      binary_io::read_doubles(in, &size, 1, "contact pair kept segments");
      std::vector<double> data(static_cast<std::size_t>(size));
      binary_io::read_doubles(in,
                              data.data(),
                              data.size(),
                              "contact pair kept segments");
      const double *value = data.data();
      const auto    next  = [&]() { return *value++; };
      const auto    corners = [&](FacetCorners &c) {
        for (Point<3> &p : c)
          for (unsigned int d = 0; d < 3; ++d)
            p[d] = next();
      };
      searched = next() != 0.;
      x_at_search.resize(x.size());
      for (Point<3> &p : x_at_search)
        for (unsigned int d = 0; d < 3; ++d)
          p[d] = next();
      for (Pass &pass : passes)
        {
          pass.candidates.resize(static_cast<std::size_t>(next()));
          for (std::vector<unsigned int> &candidates : pass.candidates)
            {
              candidates.resize(static_cast<std::size_t>(next()));
              for (unsigned int &m : candidates)
                m = static_cast<unsigned int>(next());
            }
          pass.kept.resize(static_cast<std::size_t>(next()));
          for (Pass::KeptSegments &kept : pass.kept)
            {
              kept.valid = next() != 0.;
              corners(kept.slave_corners);
              kept.segments.resize(static_cast<std::size_t>(next()));
              for (Pass::KeptSegment &k : kept.segments)
                {
                  k.master         = static_cast<unsigned int>(next());
                  MortarSegment &g = k.integrals;
                  for (unsigned int a = 0; a < 4; ++a)
                    for (unsigned int b = 0; b < 4; ++b)
                      g.D[a][b] = next();
                  for (unsigned int a = 0; a < 4; ++a)
                    for (unsigned int b = 0; b < 4; ++b)
                      g.M[a][b] = next();
                  g.area = next();
                  for (unsigned int d = 0; d < 3; ++d)
                    {
                      g.slope[d]  = next();
                      g.normal[d] = next();
                    }
                  corners(k.master_corners);
                }
            }
        }
      AssertThrow(value == data.data() + data.size(),
                  ExcMessage("The kept segments of the contact pair '" +
                             definition.name + "' do not fit it"));
    }



    MortarContactPair::MortarContactPair(
      const model::Model                 &model,
      const model::ContactPairDefinition &definition)
      : impl(std::make_unique<Implementation>(model, definition))
    {
      if (definition.type != model::ContactPairDefinition::Type::tied)
        return;
      // Tied: the segments of the reference configuration, for good.
      Implementation &I = *impl;
      I.search_if_needed();
      unsigned int n_tied = 0;
      for (Implementation::Pass &pass : I.passes)
        {
          I.integrate(pass, true);
          I.compute_normals(pass);
          pass.tied.assign(I.x.size(), false);
          pass.tied_area.assign(I.x.size(), 0.);
          for (const unsigned int node : pass.nodes)
            if (I.area[node] > 0.)
              {
                const double g = -(I.normal[node] * I.gap[node]) / I.area[node];
                if (std::abs(g) <= definition.tie_tolerance + 1e-9 * I.margin)
                  {
                    pass.tied[node]      = true;
                    pass.tied_area[node] = I.area[node];
                    if (pass.counted[node])
                      ++n_tied;
                  }
              }
        }
      if (Utilities::MPI::sum(n_tied, I.comm) == 0)
        throw InputError("Contact pairs/" + definition.name + "/Tie tolerance",
                         "no slave node lies within " +
                           Utilities::to_string(definition.tie_tolerance) +
                           " mm of the master surface: the tied pair ties "
                           "nothing (raise the tolerance or check the "
                           "boundary ids)");
    }



    MortarContactPair::~MortarContactPair() = default;



    std::string
    MortarContactPair::name() const
    {
      return "contact pair " + impl->definition.name;
    }



    model::ForceContribution::Accumulation
    MortarContactPair::accumulation() const
    {
      return Accumulation::external_owned;
    }




    double
    MortarContactPair::penalty_factor() const
    {
      return impl->penalty_factor;
    }


    double
    MortarContactPair::penalty_stiffness() const
    {
      return impl->passes.empty() ? 0. : impl->passes[0].penalty;
    }



    double
    MortarContactPair::friction_work() const
    {
      return impl->accepted_friction_work + impl->trial_dissipation;
    }



    double
    MortarContactPair::contact_energy() const
    {
      return impl->energy;
    }



    double
    MortarContactPair::energy_error() const
    {
      const Implementation::WorkAudit &audit = impl->audit;
      return audit.started ? audit.trial_work + impl->energy +
                               friction_work() - audit.energy_at_start :
                             0.;
    }



    void
    MortarContactPair::start_forces(const model::EvaluationPoint &point)
    {
      Implementation &I = *impl;
      for (const unsigned int i : I.owned_surface_dofs)
        I.u_pair.local_element(i) = point.displacement.local_element(i);
      I.u_pair.update_ghost_values_start(I.channel);
      I.exchange = Implementation::Exchange::positions_sent;
    }



    void
    MortarContactPair::add_forces(const model::EvaluationPoint &point,
                                  VectorType                   &f,
                                  model::ContributionResults   &results)
    {
      Implementation &I = *impl;
      if (I.exchange != Implementation::Exchange::forces_sent)
        compute_forces(point, results);
      const auto start = std::chrono::steady_clock::now();
      I.f_pair.compress_finish(VectorOperation::add);
      I.timings.waiting_seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
      I.exchange = Implementation::Exchange::idle;
      for (const unsigned int i : I.owned_surface_dofs)
        f.local_element(i) += I.f_pair.local_element(i);
      I.book_trial_work();
      I.timings.evaluation_seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
    }



    namespace
    {
      /** An active node's share of the columns: pressure @p p, tangential
       * traction @p t (GPa) on its covered area @p A (mm^2). */
      void
      book_active_node(ContactPairStatistics &statistics,
                       const double           p,
                       const double           t,
                       const double           A)
      {
        statistics.normal_force += p * A;
        statistics.tangential_force += t * A;
        statistics.max_pressure = std::max(statistics.max_pressure, p);
        statistics.min_pressure = std::min(statistics.min_pressure, p);
        statistics.contact_area += A;
        ++statistics.active_nodes;
      }
    } // namespace



    void
    MortarContactPair::Implementation::prepare_evaluation(
      const model::EvaluationPoint &point)
    {
      const auto start = std::chrono::steady_clock::now();
      u_pair.update_ghost_values_finish();
      timings.waiting_seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
      update_positions(u_pair);
      // (The quasi-static solver has no masses: no stable step there.)
      if (node_mass.empty() && point.mass.linfty_norm() > 0.)
        {
          // The masses do not change during a run: gathered once.
          VectorType mass(partitioner);
          mass.copy_locally_owned_data_from(point.mass);
          mass.update_ghost_values();
          node_mass.resize(x.size());
          for (unsigned int n = 0; n < x.size(); ++n)
            node_mass[n] = mass.local_element(node_dofs[n][0]);
          follow_pending = true;
        }
      if (follow_pending)
        {
          set_penalty();
          follow_pending = false;
        }
      // What the penalty updates since the accepted state added to the
      // springs: (eps - eps_accepted) A g^2 / 2 normal, and the accepted
      // tangential spring's energy A |t|^2 / 2 eps at the new penalty.
      trial_stiffness_energy = 0.;
      if (definition.type != model::ContactPairDefinition::Type::tied)
        search_if_needed();
    }



    void
    MortarContactPair::Implementation::tied_tractions(
      Pass                  &pass,
      EvaluationEnergies    &energies,
      ContactPairStatistics &statistics)
    {
      // The change of each tied node's weighted gap vector: the reference
      // integrals times the displacements.
      for (const unsigned int node : pass.nodes)
        gap[node] = Tensor<1, 3>();
      for (const StoredSegment &s : pass.segments)
        {
          const auto &sn = facet_nodes[pass.gap_facets[s.slave]];
          const auto &mn = facet_nodes[s.master];
          for (unsigned int a = 0; a < 4; ++a)
            for (unsigned int b = 0; b < 4; ++b)
              gap[sn[a]] +=
                s.integrals.D[a][b] * (x[sn[b]] - node_reference[sn[b]]) -
                s.integrals.M[a][b] * (x[mn[b]] - node_reference[mn[b]]);
        }
      compute_normals(pass);
      for (const unsigned int node : pass.nodes)
        {
          traction[node] = Tensor<1, 3>();
          if (!pass.tied[node])
            continue;
          const double       A    = pass.tied_area[node];
          const Tensor<1, 3> mean = gap[node] / A;
          traction[node]          = -pass.penalty * mean;
          if (pass.accepted_penalty >= 0. && pass.counted[node])
            trial_stiffness_energy +=
              0.5 * (pass.penalty - pass.accepted_penalty) * A * (mean * mean);
          const double p            = -(traction[node] * normal[node]);
          pass.shown_gap[node]      = normal[node] * mean;
          pass.shown_pressure[node] = p;
          if (pass.counted[node])
            {
              energies.stored += 0.5 * pass.penalty * A * (mean * mean);
              book_active_node(statistics,
                               p,
                               (traction[node] + p * normal[node]).norm(),
                               A);
              statistics.max_penetration =
                std::max(statistics.max_penetration, pass.shown_gap[node]);
            }
        }
    }



    void
    MortarContactPair::Implementation::contact_tractions(
      Pass                  &pass,
      const double           time,
      EvaluationEnergies    &energies,
      ContactPairStatistics &statistics)
    {
      compute_normals(pass);
      // Segments are kept only in explicit runs (the masses known): the
      // quasi-static residual must be the tangent's.
      shown_gaps_partial |=
        integrate(pass,
                  false,
                  true,
                  definition.segment_reuse_slip > 0. && !node_mass.empty());
      const double step = time - time_accepted;
      const bool   book = pass.accepted_penalty >= 0.;
      // The accepted springs' energy at the present penalty.
      const double spring_scale =
        book ? pass.accepted_penalty / pass.penalty : 1.;
      for (const unsigned int node : pass.nodes)
        {
          traction[node] = Tensor<1, 3>();
          const double A = area[node];
          const double g = A > 0. ? -(normal[node] * gap[node]) / A : 0.;
          const double accepted_spring =
            coulomb ? spring_scale * pass.accepted_spring_energy[node] : 0.;
          if (book && pass.counted[node])
            trial_stiffness_energy +=
              (accepted_spring -
               (coulomb ? pass.accepted_spring_energy[node] : 0.)) +
              (A > 0. && g < 0. ?
                 0.5 * (pass.penalty - pass.accepted_penalty) * A * g * g :
                 0.);
          pass.shown_gap[node]      = g;
          pass.shown_pressure[node] = g < 0. ? -pass.penalty * g : 0.;
          if (coulomb)
            pass.trial_slip_distance[node] = pass.accepted_slip_distance[node];
          if (A > 0. && pass.counted[node])
            statistics.max_penetration =
              std::max(statistics.max_penetration, -g);
          if (!(A > 0.) || !(g < 0.))
            {
              // Open: a frictional node forgets its spring, whose energy is
              // dissipated.
              if (coulomb)
                {
                  pass.trial_tangential[node]    = Tensor<1, 3>();
                  pass.trial_spring_energy[node] = 0.;
                  if (pass.counted[node])
                    {
                      energies.dissipated += accepted_spring;
                      if (trace.enabled)
                        trace.dissipation[node] += accepted_spring;
                    }
                }
              continue;
            }
          const Tensor<1, 3> &n = normal[node];
          const double        p = -pass.penalty * g;
          traction[node]        = -p * n;
          Tensor<1, 3> tangential;
          bool         slipping = false;
          if (coulomb)
            {
              Tensor<1, 3> old, increment;
              tangential =
                coulomb_return_mapping(pass.accepted_tangential[node],
                                       n,
                                       slip[node],
                                       A,
                                       p,
                                       pass.penalty,
                                       step,
                                       definition,
                                       old,
                                       increment,
                                       slipping);
              if (slipping)
                pass.trial_slip_distance[node] += increment.norm();
              traction[node] += tangential;
              pass.trial_tangential[node] = tangential;
              const double spring =
                0.5 * A * (tangential * tangential) / pass.penalty;
              pass.trial_spring_energy[node] = spring;
              if (pass.counted[node])
                {
                  // The work done on the spring over the step (trapezoidal)
                  // less what it stores.
                  const double node_dissipation =
                    -0.5 * A * ((old + tangential) * increment) -
                    (spring - accepted_spring);
                  energies.dissipated += node_dissipation;
                  energies.stored += spring;
                  if (trace.enabled)
                    {
                      trace.dissipation[node] += node_dissipation;
                      trace.slipping[node] = slipping;
                    }
                }
            }
          if (pass.counted[node])
            {
              energies.stored += 0.5 * pass.penalty * A * g * g;
              book_active_node(statistics, p, tangential.norm(), A);
              if (slipping)
                ++statistics.slipping_nodes;
            }
        }
    }



    void
    MortarContactPair::Implementation::scatter_segment_forces(
      const Pass            &pass,
      ContactPairStatistics &statistics)
    {
      const bool tied =
        definition.type == model::ContactPairDefinition::Type::tied;
      for (const StoredSegment &s : pass.segments)
        {
          if (!owns(pass, s.slave))
            continue;
          const auto &sn = facet_nodes[pass.gap_facets[s.slave]];
          const auto &mn = facet_nodes[s.master];
          for (unsigned int a = 0; a < 4; ++a)
            {
              if (traction[sn[a]].norm_square() == 0.)
                continue;
              // The segment's traction: its normal part follows the master
              // face's slope (segment_traction()).
              const double       p = tied ? 0. : pass.shown_pressure[sn[a]];
              const Tensor<1, 3> t =
                s.weight * segment_traction(traction[sn[a]],
                                            p,
                                            normal[sn[a]],
                                            s.integrals.normal,
                                            s.integrals.slope);
              for (unsigned int b = 0; b < 4; ++b)
                for (unsigned int d = 0; d < 3; ++d)
                  {
                    const double on_slave = s.integrals.D[a][b] * t[d];
                    f_pair.local_element(node_dofs[sn[b]][d]) += on_slave;
                    statistics.force[d] += on_slave;
                    f_pair.local_element(node_dofs[mn[b]][d]) -=
                      s.integrals.M[a][b] * t[d];
                  }
            }
          if (tied || s.weight_gradient.norm_square() == 0.)
            continue;
          Tensor<1, 3> on_slave[4], on_master[4];
          weight_forces(pass, s, on_slave, on_master);
          for (unsigned int b = 0; b < 4; ++b)
            for (unsigned int d = 0; d < 3; ++d)
              {
                f_pair.local_element(node_dofs[sn[b]][d]) += on_slave[b][d];
                statistics.force[d] += on_slave[b][d];
                f_pair.local_element(node_dofs[mn[b]][d]) += on_master[b][d];
              }
        }
    }



    void
    MortarContactPair::compute_forces(const model::EvaluationPoint &point,
                                      model::ContributionResults   &results)
    {
      Implementation &I = *impl;
      if (I.exchange != Implementation::Exchange::positions_sent)
        start_forces(point);
      const auto start = std::chrono::steady_clock::now();
      I.prepare_evaluation(point);

      statistics           = ContactPairStatistics();
      I.shown_gaps_partial = false;
      if (I.trace.enabled)
        {
          I.trace.dissipation.assign(I.x.size(), 0.);
          I.trace.slipping.assign(I.x.size(), 0);
        }
      // (compress() left the ghost entries at zero.)
      for (const unsigned int i : I.owned_surface_dofs)
        I.f_pair.local_element(i) = 0.;
      Implementation::EvaluationEnergies energies;
      for (Implementation::Pass &pass : I.passes)
        {
          if (I.definition.type == model::ContactPairDefinition::Type::tied)
            I.tied_tractions(pass, energies, statistics);
          else
            I.contact_tractions(pass, point.time, energies, statistics);
          I.scatter_segment_forces(pass, statistics);
        }
      I.f_pair.compress_start(I.channel, VectorOperation::add);
      I.exchange = Implementation::Exchange::forces_sent;
      // The springs' energy less what the penalty updates put in: the work
      // done on them.
      const double energy = energies.stored - (I.accepted_stiffness_energy +
                                               I.trial_stiffness_energy);
      results.contact_energy += energy;
      results.friction_dissipation += energies.dissipated;
      if (I.time_step > 0.)
        results.contact_time_step =
          std::min(results.contact_time_step, I.time_step);
      I.energy            = energy;
      I.trial_dissipation = energies.dissipated;
      I.trial_time        = point.time;
      I.trial_pending     = true;
      I.timings.evaluation_seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
    }



    const ContactPairTimings &
    MortarContactPair::timings() const
    {
      return impl->timings;
    }



    bool
    MortarContactPair::follow_geometry()
    {
      impl->follow_pending = true;
      return true;
    }



    void
    MortarContactPair::accept_step()
    {
      Implementation &I = *impl;
      if (!I.trial_pending)
        return;
      if (I.trace.enabled)
        I.trace_step(energy_error());
      if (!I.audit.started)
        {
          I.audit.started         = true;
          I.audit.energy_at_start = I.energy + friction_work();
        }
      // (u_pair and f_pair still hold the last evaluation's values.)
      I.audit.accepted_work = I.audit.trial_work;
      for (unsigned int k = 0; k < I.owned_surface_dofs.size(); ++k)
        {
          const unsigned int i  = I.owned_surface_dofs[k];
          I.audit.u_accepted[k] = I.u_pair.local_element(i);
          I.audit.f_accepted[k] = I.f_pair.local_element(i);
        }
      I.accepted_stiffness_energy += I.trial_stiffness_energy;
      I.trial_stiffness_energy = 0.;
      for (Implementation::Pass &pass : I.passes)
        pass.accepted_penalty = pass.penalty;
      if (!I.coulomb)
        {
          I.trial_pending = false;
          return;
        }
      for (Implementation::Pass &pass : I.passes)
        for (const unsigned int node : pass.nodes)
          {
            pass.accepted_tangential[node]    = pass.trial_tangential[node];
            pass.accepted_spring_energy[node] = pass.trial_spring_energy[node];
            pass.accepted_slip_distance[node] = pass.trial_slip_distance[node];
          }
      I.x_accepted    = I.x;
      I.time_accepted = I.trial_time;
      I.accepted_friction_work += I.trial_dissipation;
      I.trial_dissipation = 0.;
      I.trial_pending     = false;
    }



    void
    MortarContactPair::add_surface_fields(VectorType &fields) const
    {
      Implementation &I = *impl;
      // The gaps of the nodes that the evaluation left out as clearly
      // open, for the picture only.
      if (I.shown_gaps_partial)
        {
          for (Implementation::Pass &pass : I.passes)
            I.refresh_shown_gaps(pass);
          I.shown_gaps_partial = false;
        }
      VectorType            values(I.partitioner);
      for (const Implementation::Pass &pass : I.passes)
        for (const unsigned int node : pass.nodes)
          if (pass.counted[node])
            {
              const auto &dofs = I.node_dofs[node];
              values.local_element(dofs[0]) += pass.shown_pressure[node];
              values.local_element(dofs[1]) += pass.shown_gap[node];
              if (I.coulomb)
                values.local_element(dofs[2]) +=
                  I.trial_pending ? pass.trial_slip_distance[node] :
                                    pass.accepted_slip_distance[node];
            }
      values.compress(VectorOperation::add);
      for (unsigned int i = 0; i < I.partitioner->locally_owned_size(); ++i)
        fields.local_element(i) += values.local_element(i);
    }



    std::vector<SlaveNodeGap>
    MortarContactPair::slave_node_gaps(const VectorType &u)
    {
      Implementation &I = *impl;
      AssertThrow(I.definition.type != model::ContactPairDefinition::Type::tied,
                  ExcMessage("slave_node_gaps() is not for tied pairs"));
      I.load_positions(u);
      I.search_if_needed();
      std::vector<SlaveNodeGap> gaps;
      for (Implementation::Pass &pass : I.passes)
        {
          I.compute_normals(pass);
          I.integrate(pass, false);
          for (const unsigned int node : pass.nodes)
            if (pass.counted[node] && I.area[node] > 0.)
              {
                SlaveNodeGap g;
                for (unsigned int d = 0; d < 3; ++d)
                  g.dofs[d] = I.node_global_dofs[node][d];
                g.x      = I.x[node];
                g.normal = I.normal[node];
                g.gap    = -(I.normal[node] * I.gap[node]) / I.area[node];
                gaps.push_back(g);
              }
        }
      return gaps;
    }



    void
    MortarContactPair::save(std::ostream &out) const
    {
      const Implementation &I = *impl;
      // What the columns show of the last evaluation, for an identical
      // first row after a restart.
      const double shown[] = {statistics.force[0],
                              statistics.force[1],
                              statistics.force[2],
                              statistics.normal_force,
                              statistics.tangential_force,
                              statistics.max_pressure,
                              statistics.min_pressure,
                              statistics.contact_area,
                              statistics.max_penetration,
                              double(statistics.active_nodes),
                              double(statistics.slipping_nodes),
                              I.energy};
      binary_io::write_doubles(out, shown, std::size(shown));
      // The penalty updates' bookkeeping.
      binary_io::write_doubles(out, &I.accepted_stiffness_energy, 1);
      for (const Implementation::Pass &pass : I.passes)
        binary_io::write_doubles(out, &pass.accepted_penalty, 1);
      // The work audit.
      const double audit[] = {double(I.audit.started),
                              I.audit.accepted_work,
                              I.audit.energy_at_start};
      binary_io::write_doubles(out, audit, std::size(audit));
      binary_io::write_doubles(out,
                               I.audit.u_accepted.data(),
                               I.audit.u_accepted.size());
      binary_io::write_doubles(out,
                               I.audit.f_accepted.data(),
                               I.audit.f_accepted.size());
      if (I.definition.segment_reuse_slip > 0.)
        I.save_kept_segments(out);
      if (!I.coulomb || I.x.empty())
        return;
      // Friction's history: the accepted tractions and spring energies,
      // the accepted positions and time, the friction work.
      for (const Implementation::Pass &pass : I.passes)
        {
          binary_io::write_doubles(out,
                                   &pass.accepted_tangential[0][0],
                                   3 * pass.accepted_tangential.size());
          binary_io::write_doubles(out,
                                   pass.accepted_spring_energy.data(),
                                   pass.accepted_spring_energy.size());
          binary_io::write_doubles(out,
                                   pass.accepted_slip_distance.data(),
                                   pass.accepted_slip_distance.size());
        }
      binary_io::write_doubles(out, &I.x_accepted[0][0], 3 * I.x.size());
      binary_io::write_doubles(out, &I.time_accepted, 1);
      binary_io::write_doubles(out, &I.accepted_friction_work, 1);
    }



    std::vector<double>
    MortarContactPair::friction_state() const
    {
      const Implementation &I = *impl;
      std::vector<double>   state;
      if (!I.coulomb)
        return state;
      for (const Implementation::Pass &pass : I.passes)
        {
          for (const Tensor<1, 3> &t : pass.accepted_tangential)
            state.insert(state.end(), {t[0], t[1], t[2]});
          state.insert(state.end(),
                       pass.accepted_spring_energy.begin(),
                       pass.accepted_spring_energy.end());
          state.insert(state.end(),
                       pass.accepted_slip_distance.begin(),
                       pass.accepted_slip_distance.end());
        }
      for (const Point<3> &x : I.x_accepted)
        state.insert(state.end(), {x[0], x[1], x[2]});
      return state;
    }



    void
    MortarContactPair::set_friction_state(const std::vector<double> &state,
                                          const double               time)
    {
      Implementation   &I = *impl;
      const std::size_t n = I.x.size();
      AssertThrow(state.size() ==
                    (I.coulomb ? (5 * I.passes.size() + 3) * n : 0),
                  ExcMessage("The friction state of the contact pair '" +
                             I.definition.name + "' does not fit it"));
      // The explicit run's energy balance, and the pair's, start here.
      I.audit.started       = false;
      I.audit.accepted_work = 0.;
      I.audit.trial_work    = 0.;
      if (!I.coulomb)
        return;
      const double *value = state.data();
      for (Implementation::Pass &pass : I.passes)
        {
          for (Tensor<1, 3> &t : pass.accepted_tangential)
            for (unsigned int d = 0; d < 3; ++d)
              t[d] = *value++;
          for (double &energy : pass.accepted_spring_energy)
            energy = *value++;
          for (double &distance : pass.accepted_slip_distance)
            distance = *value++;
          pass.trial_tangential    = pass.accepted_tangential;
          pass.trial_spring_energy = pass.accepted_spring_energy;
          pass.trial_slip_distance = pass.accepted_slip_distance;
        }
      for (Point<3> &x : I.x_accepted)
        for (unsigned int d = 0; d < 3; ++d)
          x[d] = *value++;
      I.time_accepted          = time;
      I.accepted_friction_work = 0.;
      I.trial_dissipation      = 0.;
      I.trial_pending          = false;
    }



    void
    MortarContactPair::load(std::istream &in)
    {
      Implementation &I = *impl;
      double          shown[12];
      binary_io::read_doubles(in, shown, 12, "contact pair results");
      statistics.force[0]         = shown[0];
      statistics.force[1]         = shown[1];
      statistics.force[2]         = shown[2];
      statistics.normal_force     = shown[3];
      statistics.tangential_force = shown[4];
      statistics.max_pressure     = shown[5];
      statistics.min_pressure     = shown[6];
      statistics.contact_area     = shown[7];
      statistics.max_penetration  = shown[8];
      statistics.active_nodes     = static_cast<unsigned int>(shown[9]);
      statistics.slipping_nodes   = static_cast<unsigned int>(shown[10]);
      I.energy                    = shown[11];
      binary_io::read_doubles(in,
                              &I.accepted_stiffness_energy,
                              1,
                              "contact pair penalty update energy");
      for (Implementation::Pass &pass : I.passes)
        binary_io::read_doubles(in,
                                &pass.accepted_penalty,
                                1,
                                "contact pair accepted penalty");
      double audit[3];
      binary_io::read_doubles(in, audit, 3, "contact pair work audit");
      I.audit.started         = audit[0] != 0.;
      I.audit.accepted_work   = audit[1];
      I.audit.trial_work      = audit[1];
      I.audit.energy_at_start = audit[2];
      binary_io::read_doubles(in,
                              I.audit.u_accepted.data(),
                              I.audit.u_accepted.size(),
                              "contact pair audit displacements");
      binary_io::read_doubles(in,
                              I.audit.f_accepted.data(),
                              I.audit.f_accepted.size(),
                              "contact pair audit forces");
      I.trial_stiffness_energy = 0.;
      // The candidates are found anew from the loaded positions (the
      // segments do not depend on which extra candidates a search keeps),
      // but for kept segments, which depend on when the searches were.
      I.searched = false;
      if (I.definition.segment_reuse_slip > 0.)
        I.load_kept_segments(in);
      if (!I.coulomb || I.x.empty())
        return;
      for (Implementation::Pass &pass : I.passes)
        {
          binary_io::read_doubles(in,
                                  &pass.accepted_tangential[0][0],
                                  3 * pass.accepted_tangential.size(),
                                  "contact pair tractions");
          binary_io::read_doubles(in,
                                  pass.accepted_spring_energy.data(),
                                  pass.accepted_spring_energy.size(),
                                  "contact pair spring energies");
          binary_io::read_doubles(in,
                                  pass.accepted_slip_distance.data(),
                                  pass.accepted_slip_distance.size(),
                                  "contact pair slip distances");
        }
      binary_io::read_doubles(in,
                              &I.x_accepted[0][0],
                              3 * I.x.size(),
                              "contact pair positions");
      binary_io::read_doubles(in, &I.time_accepted, 1, "contact pair time");
      binary_io::read_doubles(in,
                              &I.accepted_friction_work,
                              1,
                              "contact pair friction work");
      I.trial_dissipation = 0.;
      I.trial_pending     = false;
    }
  } // namespace contact
} // namespace rubberdyn
