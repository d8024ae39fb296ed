#include <deal.II/base/geometry_info.h>
#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe.h>

#include <rubberdyn/base/durable_files.h>
#include <rubberdyn/base/exceptions.h>
#include <rubberdyn/base/parameter_tools.h>
#include <rubberdyn/base/vector.h>
#include <rubberdyn/contact/initial_penetrations.h>
#include <rubberdyn/contact/mortar_contact_pair.h>
#include <rubberdyn/contact/rigid_surface_contact.h>
#include <rubberdyn/model/model.h>

#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <vector>

namespace rubberdyn
{
  namespace contact
  {
    using namespace dealii;
    using model::InitialPenetrationReport;
    using parameters::InitialPenetration;

    namespace
    {
      /**
       * The penetrating nodes of one interaction: how many, and the
       * largest penetration with its node (of equal ones to the
       * tolerance, the lowest in x, then y, then z, so that the node
       * named does not depend on the ranks or the round-off).
       */
      struct Penetrations
      {
        unsigned int n_nodes = 0;
        double       largest = 0.;
        Point<3>     where;

        /** Book a node at @p x that penetrates by @p penetration (mm). */
        void
        add(const double penetration, const Point<3> &x, const double tolerance)
        {
          ++n_nodes;
          bool lower = false;
          for (unsigned int d = 0; d < 3; ++d)
            if (x[d] != where[d])
              {
                lower = x[d] < where[d];
                break;
              }
          if (n_nodes == 1 || penetration > largest + tolerance ||
              (penetration >= largest - tolerance && lower))
            where = x;
          largest = n_nodes == 1 ? penetration : std::max(largest, penetration);
        }

        /** The same over all ranks (collective). */
        void
        gather(const MPI_Comm comm, const double tolerance)
        {
          const std::array<double, 5> mine = {
            {double(n_nodes), largest, where[0], where[1], where[2]}};
          Penetrations all;
          for (const std::array<double, 5> &r :
               Utilities::MPI::all_gather(comm, mine))
            if (r[0] > 0.)
              {
                const unsigned int n = all.n_nodes;
                all.add(r[1], Point<3>(r[2], r[3], r[4]), tolerance);
                all.n_nodes = n + static_cast<unsigned int>(r[0]);
              }
          *this = all;
        }
      };

      /** "(x, y, z)" with six digits each. */
      std::string
      coordinates(const Point<3> &x)
      {
        return "(" + parameter_tools::format_short(x[0]) + ", " +
               parameter_tools::format_short(x[1]) + ", " +
               parameter_tools::format_short(x[2]) + ")";
      }

      /** The diagonal of the mesh's bounding box (mm). Collective. */
      double
      model_size(const model::Model &model)
      {
        double bounds[6];
        for (unsigned int d = 0; d < 3; ++d)
          {
            bounds[d]     = std::numeric_limits<double>::max();
            bounds[3 + d] = std::numeric_limits<double>::max();
          }
        for (const auto &cell : model.triangulation.active_cell_iterators())
          if (cell->is_locally_owned())
            for (const unsigned int v : cell->vertex_indices())
              for (unsigned int d = 0; d < 3; ++d)
                {
                  bounds[d]     = std::min(bounds[d], cell->vertex(v)[d]);
                  bounds[3 + d] = std::min(bounds[3 + d], -cell->vertex(v)[d]);
                }
        Utilities::MPI::min(ArrayView<const double>(bounds, 6),
                            model.comm,
                            ArrayView<double>(bounds, 6));
        double size = 0.;
        for (unsigned int d = 0; d < 3; ++d)
          size += (bounds[3 + d] + bounds[d]) * (bounds[3 + d] + bounds[d]);
        return std::sqrt(size);
      }

      /**
       * After the moves @p moved of one interaction (ghosted): the first
       * node of this rank's cells that must not move, as a message, or "".
       * A rigid part's node would change its body's shape (and the body
       * could only move it as a whole); a move of half a cell's shortest
       * edge or more folds the cell.
       */
      std::string
      refused_move(const model::Model &model,
                   const VectorType   &moved,
                   const std::string  &slave_nodes)
      {
        const FiniteElement<3>              &fe = model.dof_handler.get_fe();
        std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
        for (const auto &cell : model.dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              cell->get_dof_indices(dofs);
              double shortest = std::numeric_limits<double>::max();
              for (unsigned int e = 0; e < cell->n_lines(); ++e)
                shortest = std::min(shortest,
                                    cell->line(e)->vertex(0).distance(
                                      cell->line(e)->vertex(1)));
              for (const unsigned int v : cell->vertex_indices())
                {
                  Tensor<1, 3> move;
                  for (unsigned int d = 0; d < 3; ++d)
                    move[d] = moved(dofs[fe.component_to_system_index(d, v)]);
                  if (move.norm() == 0.)
                    continue;
                  const model::Part &part =
                    model.parts[model.part_of_material_id(cell->material_id())];
                  if (part.rigid)
                    return "the node at " + coordinates(cell->vertex(v)) +
                           " of " + slave_nodes +
                           " belongs to the rigid part '" + part.name +
                           "', whose nodes are not moved: make the "
                           "deformable side the slave, or correct the mesh";
                  if (move.norm() >= 0.5 * shortest)
                    return "moving the node at " +
                           coordinates(cell->vertex(v)) + " out by " +
                           parameter_tools::format_short(move.norm()) +
                           " mm would fold its element (shortest edge " +
                           parameter_tools::format_short(shortest) +
                           " mm): correct the mesh";
                }
            }
        return "";
      }

      /**
       * A verdict on the moves @p moved (owned entries; its ghosts are
       * updated here) of the nodes @p nodes (this rank's, by x dof):
       * refused, naming @p entry, where one would fold an element of
       * @p moved_nodes (every rank's verdict); else the number of nodes
       * moved and the largest move (mm) of all ranks into @p report.
       * Collective.
       */
      void
      book_moves(const model::Model &model,
                 const std::map<types::global_dof_index,
                                std::array<types::global_dof_index, 3>> &nodes,
                 VectorType                                             &moved,
                 const std::string        &entry,
                 const std::string        &moved_nodes,
                 InitialPenetrationReport &report)
      {
        moved.update_ghost_values();
        durable_files::throw_if_any(model.comm,
                                    entry,
                                    refused_move(model, moved, moved_nodes));
        unsigned int n       = 0;
        double       largest = 0.;
        for (const auto &[x_dof, dofs] : nodes)
          {
            (void)x_dof;
            Tensor<1, 3> move;
            for (unsigned int d = 0; d < 3; ++d)
              move[d] = moved(dofs[d]);
            if (move.norm() > 0.)
              {
                ++n;
                largest = std::max(largest, move.norm());
              }
          }
        report.n_moved  = Utilities::MPI::sum(n, model.comm);
        report.max_move = Utilities::MPI::max(largest, model.comm);
      }

      /** The text of a report: the count, the largest and where. */
      std::string
      found(const InitialPenetrationReport &report,
            const std::string              &slave_nodes,
            const std::string              &master_surface)
      {
        return std::to_string(report.n_nodes) + " " + slave_nodes +
               " start inside " + master_surface + ", by up to " +
               parameter_tools::format_short(report.max_penetration) +
               " mm (at " + coordinates(report.where) + ")";
      }
    } // namespace



    namespace
    {
    // What an interaction's penetrations ask for: a report, or the
    // refusal.
    InitialPenetrationReport
    judged_report(const Penetrations      &found_nodes,
                  const std::string       &interaction,
                  const std::string       &entry,
                  const InitialPenetration action,
                  const std::string       &slave_nodes,
                  const std::string       &master_surface)
    {
      InitialPenetrationReport report;
      report.interaction     = interaction;
      report.entry           = entry;
      report.action          = action;
      report.n_nodes         = found_nodes.n_nodes;
      report.max_penetration = found_nodes.largest;
      report.where           = found_nodes.where;
      report.found           = found(report, slave_nodes, master_surface);
      if (action == InitialPenetration::refuse)
        throw InputError(
          entry,
          report.found +
            ": correct the mesh, or set this entry to 'move slave nodes "
            "out' (moves them onto the surface before the run) or "
            "'report' (runs with the overlap)");
      return report;
    }



    // A frictionless or Coulomb pair, with the mean gaps of its own mortar
    // integrals: its report into @p reports, its moves into @p u (owned
    // entries). Returns whether it moved nodes. Collective.
    bool
    resolve_pair(const model::Model                    &model,
                 const model::ContactPairDefinition    &definition,
                 const double                           tolerance,
                 VectorType                            &u,
                 std::vector<InitialPenetrationReport> &reports)
    {
      const MPI_Comm comm = model.comm;
      if (definition.type == model::ContactPairDefinition::Type::tied)
        return false;
      const std::string interaction = "Contact pairs/" + definition.name;
      const std::string entry       = interaction + "/Initial penetration";
      const std::string slave_nodes = "slave nodes",
                        master_surface = "the master surface";
      MortarContactPair pair(model, definition);
      const auto measure = [&](const std::vector<SlaveNodeGap> &gaps) {
        Penetrations p;
        for (const SlaveNodeGap &g : gaps)
          if (-g.gap > tolerance)
            p.add(-g.gap, g.x, tolerance);
        p.gather(comm, tolerance);
        return p;
      };
      std::vector<SlaveNodeGap> gaps        = pair.slave_node_gaps(u);
      Penetrations              penetrating = measure(gaps);
      if (penetrating.n_nodes == 0)
        return false;
      InitialPenetrationReport report =
        judged_report(penetrating,
                      interaction,
                      entry,
                      definition.initial_penetration,
                      slave_nodes,
                      master_surface);
      if (definition.initial_penetration ==
          InitialPenetration::move_slave_nodes_out)
        {
          // Both sides' nodes carry gaps in a two-pass or self-contact
          // pair: each moves half the way, and the next rounds close
          // what is left.
          const double share =
            definition.two_pass || definition.slave_boundary_ids ==
                                     definition.master_boundary_ids ?
              0.5 :
              1.;
          VectorType moved(model.partitioner);
          // This rank's moved nodes (by x dof).
          std::map<types::global_dof_index,
                   std::array<types::global_dof_index, 3>>
                       nodes;
          unsigned int round = 0;
          for (; penetrating.n_nodes > 0 && round < 100; ++round)
            {
              VectorType delta(model.partitioner);
              for (const SlaveNodeGap &g : gaps)
                if (-g.gap > tolerance)
                  {
                    for (unsigned int d = 0; d < 3; ++d)
                      delta(g.dofs[d]) += share * g.gap * g.normal[d];
                    nodes[g.dofs[0]] = {{g.dofs[0], g.dofs[1], g.dofs[2]}};
                  }
              delta.compress(VectorOperation::add);
              u += delta;
              moved += delta;
              gaps        = pair.slave_node_gaps(u);
              penetrating = measure(gaps);
            }
          if (penetrating.n_nodes > 0)
            throw InputError(entry,
                             "moving the slave nodes out left " +
                               std::to_string(penetrating.n_nodes) +
                               " of them inside the master surface after " +
                               std::to_string(round) + " moves, by up to " +
                               parameter_tools::format_short(
                                 penetrating.largest) +
                               " mm (at " + coordinates(penetrating.where) +
                               "): correct the mesh");
          book_moves(model, nodes, moved, entry, slave_nodes, report);
        }
      reports.push_back(report);
      return definition.initial_penetration ==
             InitialPenetration::move_slave_nodes_out;
    }



    // A rigid surface: the distance of each node of its boundary ids, at
    // the surface's position at t = 0 (as given); its report into
    // @p reports, its moves into @p u. Returns whether it moved nodes.
    // Collective.
    bool
    resolve_rigid_surface(const model::Model                    &model,
                          const model::RigidSurfaceDefinition   &definition,
                          const double                           tolerance,
                          VectorType                            &u,
                          std::vector<InitialPenetrationReport> &reports)
    {
      const MPI_Comm                       comm = model.comm;
      const FiniteElement<3>              &fe   = model.dof_handler.get_fe();
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      const std::string interaction = "Rigid surfaces/" + definition.name;
      const std::string entry       = "Contact/Initial penetration";
      const std::string slave_nodes = "nodes of its Boundary ids",
                        master_surface =
                          "the rigid surface '" + definition.name + "'";
      // This rank's nodes on the surface's faces (owned dofs), by x
      // dof: dofs and reference position.
      std::map<types::global_dof_index,
               std::pair<std::array<types::global_dof_index, 3>, Point<3>>>
        nodes;
      for (const auto &cell : model.dof_handler.active_cell_iterators())
        if (cell->is_locally_owned() || cell->is_ghost())
          {
            bool on_surface = false;
            for (const unsigned int f : cell->face_indices())
              on_surface = on_surface || (cell->at_boundary(f) &&
                                          definition.boundary_ids.count(
                                            cell->face(f)->boundary_id()));
            if (!on_surface)
              continue;
            cell->get_dof_indices(dofs);
            for (const unsigned int f : cell->face_indices())
              if (cell->at_boundary(f) && definition.boundary_ids.count(
                                            cell->face(f)->boundary_id()))
                for (const unsigned int k : cell->face(f)->vertex_indices())
                  {
                    const unsigned int v =
                      GeometryInfo<3>::face_to_cell_vertices(f, k);
                    std::array<types::global_dof_index, 3> node;
                    for (unsigned int d = 0; d < 3; ++d)
                      node[d] = dofs[fe.component_to_system_index(d, v)];
                    if (model.partitioner->in_local_range(node[0]))
                      nodes[node[0]] = {node, cell->vertex(v)};
                  }
          }
      const auto gap_of =
        [&](const std::array<types::global_dof_index, 3> &node,
            const Point<3>                               &X,
            Point<3>                                     &x,
            double                                       &gap,
            Tensor<1, 3>                                 &normal) {
          x = X;
          for (unsigned int d = 0; d < 3; ++d)
            x[d] += u(node[d]);
          RigidSurfaceContact::gap_and_normal(definition.surface,
                                              x,
                                              gap,
                                              normal);
        };
      Penetrations penetrating;
      for (const auto &[x_dof, node] : nodes)
        {
          (void)x_dof;
          Point<3>     x;
          double       gap;
          Tensor<1, 3> normal;
          gap_of(node.first, node.second, x, gap, normal);
          if (-gap > tolerance)
            penetrating.add(-gap, x, tolerance);
        }
      penetrating.gather(comm, tolerance);
      if (penetrating.n_nodes == 0)
        return false;
      InitialPenetrationReport report =
        judged_report(penetrating,
                      interaction,
                      entry,
                      definition.initial_penetration,
                      slave_nodes,
                      master_surface);
      if (definition.initial_penetration ==
          InitialPenetration::move_slave_nodes_out)
        {
          // Onto the surface along its normal (into the solid): exact
          // in one move, the surfaces being analytic.
          VectorType moved(model.partitioner);
          std::map<types::global_dof_index,
                   std::array<types::global_dof_index, 3>>
            moved_nodes;
          for (const auto &[x_dof, node] : nodes)
            {
              Point<3>     x;
              double       gap;
              Tensor<1, 3> normal;
              gap_of(node.first, node.second, x, gap, normal);
              if (-gap > tolerance)
                {
                  for (unsigned int d = 0; d < 3; ++d)
                    moved(node.first[d]) = -gap * normal[d];
                  moved_nodes[x_dof] = node.first;
                }
            }
          u += moved;
          book_moves(model,
                     moved_nodes,
                     moved,
                     entry + " (rigid surface '" + definition.name + "')",
                     "the rigid surface's Boundary ids",
                     report);
        }
      reports.push_back(report);
      return definition.initial_penetration ==
             InitialPenetration::move_slave_nodes_out;
    }



    // The moves into the mesh: every vertex of this rank's cells (owned
    // and ghost) once; @p u ghosted.
    void
    move_vertices(model::Model &model, const VectorType &u)
    {
      const FiniteElement<3>              &fe = model.dof_handler.get_fe();
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      std::vector<bool> done(model.triangulation.n_vertices(), false);
      for (const auto &cell : model.dof_handler.active_cell_iterators())
        if (cell->is_locally_owned() || cell->is_ghost())
          {
            cell->get_dof_indices(dofs);
            for (const unsigned int v : cell->vertex_indices())
              {
                if (done[cell->vertex_index(v)])
                  continue;
                done[cell->vertex_index(v)] = true;
                for (unsigned int d = 0; d < 3; ++d)
                  cell->vertex(v)[d] +=
                    u(dofs[fe.component_to_system_index(d, v)]);
              }
          }
    }
    } // namespace



    void
    resolve_initial_penetrations(model::Model &model)
    {
      if (model.initial_penetrations)
        return;
      const double tolerance = 1e-9 * model_size(model);
      std::vector<InitialPenetrationReport> reports;
      // The moves of all interactions so far (owned entries).
      VectorType u(model.partitioner);
      bool       any_moved = false;
      for (const model::ContactPairDefinition &definition : model.contact_pairs)
        any_moved |= resolve_pair(model, definition, tolerance, u, reports);
      for (const model::RigidSurfaceDefinition &definition :
           model.rigid_surfaces)
        any_moved |=
          resolve_rigid_surface(model, definition, tolerance, u, reports);
      if (Utilities::MPI::logical_or(any_moved, model.comm))
        {
          u.update_ghost_values();
          move_vertices(model, u);
        }
      model.initial_penetrations = std::move(reports);
    }
  } // namespace contact
} // namespace rubberdyn
