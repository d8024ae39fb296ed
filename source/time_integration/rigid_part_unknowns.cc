#include "rigid_part_unknowns.h"

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe.h>
#include <deal.II/fe/mapping_q1.h>


namespace rubberdyn
{
  namespace time_integration
  {
    RigidPartUnknowns::RigidPartUnknowns(
      const DoFHandler<3, 3>                                   &dof_handler,
      const std::shared_ptr<const Utilities::MPI::Partitioner> &partitioner,
      const std::vector<RigidPartInEquilibrium>                &definitions,
      const MPI_Comm                                            comm)
      : partitioner(partitioner)
      , comm(comm)
    {
      const unsigned int n_local =
        partitioner->locally_owned_size() + partitioner->n_ghost_indices();
      part_of_dof.assign(n_local, -1);
      node_of_dof.assign(n_local, 0);
      component_of_dof.assign(n_local, 0);

      // (The support points of the parts' cells only, not a map of the
      // whole model's.)
      const MappingQ1<3>                   mapping;
      const FiniteElement<3, 3>           &fe       = dof_handler.get_fe();
      const unsigned int                   n_points = fe.n_dofs_per_cell() / 3;
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      std::string                          conflict;
      for (unsigned int p = 0; p < definitions.size(); ++p)
        {
          const RigidPartInEquilibrium &definition = definitions[p];
          PartNodes                     nodes;
          nodes.name = definition.name;
          for (const auto &cell : dof_handler.active_cell_iterators())
            if ((cell->is_locally_owned() || cell->is_ghost()) &&
                definition.material_ids.count(cell->material_id()) > 0)
              {
                cell->get_dof_indices(dofs);
                for (unsigned int k = 0; k < n_points; ++k)
                  {
                    std::array<unsigned int, 3> local;
                    for (unsigned int d = 0; d < 3; ++d)
                      local[d] = partitioner->global_to_local(
                        dofs[fe.component_to_system_index(d, k)]);
                    if (part_of_dof[local[0]] == int(p))
                      continue;
                    if (part_of_dof[local[0]] >= 0 && conflict.empty())
                      conflict = "the rigid parts '" +
                                 definitions[part_of_dof[local[0]]].name +
                                 "' and '" + definition.name + "' share a node";
                    for (unsigned int d = 0; d < 3; ++d)
                      {
                        part_of_dof[local[d]]      = p;
                        node_of_dof[local[d]]      = nodes.dofs.size();
                        component_of_dof[local[d]] = d;
                      }
                    nodes.dofs.push_back(local);
                    nodes.X.push_back(mapping.transform_unit_to_real_cell(
                      cell, fe.base_element(0).unit_support_point(k)));
                    nodes.owned.push_back(partitioner->in_local_range(
                      dofs[fe.component_to_system_index(0, k)]));
                  }
              }
          nodes.centre     = definition.centre;
          double spread[2] = {0., 0.};
          for (unsigned int n = 0; n < nodes.X.size(); ++n)
            if (nodes.owned[n])
              {
                spread[0] += (nodes.X[n] - nodes.centre).norm_square();
                spread[1] += 1.;
              }
          Utilities::MPI::sum(ArrayView<const double>(spread, 2),
                              comm,
                              ArrayView<double>(spread, 2));
          nodes.length = spread[0] > 0. ? std::sqrt(spread[0] / spread[1]) : 1.;
          nodes.x      = nodes.X;
          nodes.c      = nodes.centre;

          std::vector<unsigned int> own;
          for (unsigned int direction = 0; direction < 6; ++direction)
            if (definition.free[direction])
              {
                own.push_back(unknowns.size());
                unknowns.push_back({p, direction});
              }
          unknowns_of_part.push_back(own);
          parts.push_back(std::move(nodes));
        }
      for (const std::string &message :
           Utilities::MPI::all_gather(comm, conflict))
        AssertThrow(message.empty(), ExcMessage(message));
    }



    std::vector<model::RigidBody>
    RigidPartUnknowns::reference_poses() const
    {
      std::vector<model::RigidBody> poses(parts.size());
      for (unsigned int p = 0; p < parts.size(); ++p)
        {
          poses[p].name               = parts[p].name;
          poses[p].reference_position = parts[p].centre;
        }
      return poses;
    }



    std::string
    RigidPartUnknowns::describe(const unsigned int j) const
    {
      return "the rigid part '" + parts[unknowns[j].part].name +
             "' in its free direction " +
             model::rigid_direction_names[unknowns[j].direction];
    }



    void
    RigidPartUnknowns::place_nodes(const std::vector<model::RigidBody> &poses,
                                   VectorType                          &u) const
    {
      for (unsigned int p = 0; p < parts.size(); ++p)
        {
          const PartNodes        &nodes = parts[p];
          const model::RigidBody &pose  = poses[p];
          const Point<3>          c     = pose.current_reference_position();
          for (unsigned int n = 0; n < nodes.dofs.size(); ++n)
            if (nodes.owned[n])
              {
                const Point<3> x =
                  c + pose.rotation * (nodes.X[n] - pose.reference_position);
                for (unsigned int d = 0; d < 3; ++d)
                  u.local_element(nodes.dofs[n][d]) = x[d] - nodes.X[n][d];
              }
        }
    }



    void
    RigidPartUnknowns::advance(std::vector<model::RigidBody> &poses,
                               const std::vector<double>     &dq,
                               const double                   alpha) const
    {
      std::vector<Tensor<1, 3>> turn(parts.size());
      for (unsigned int j = 0; j < unknowns.size(); ++j)
        {
          const Unknown &unknown = unknowns[j];
          if (unknown.direction < 3)
            poses[unknown.part].displacement[unknown.direction] +=
              alpha * dq[j];
          else
            turn[unknown.part][unknown.direction - 3] = alpha * dq[j];
        }
      for (unsigned int p = 0; p < parts.size(); ++p)
        if (turn[p].norm() != 0.)
          poses[p].rotation =
            model::rotation_of_vector(turn[p]) * poses[p].rotation;
    }



    void
    RigidPartUnknowns::set_linearisation_point(
      const VectorType                    &u,
      const std::vector<model::RigidBody> &poses)
    {
      for (unsigned int p = 0; p < parts.size(); ++p)
        {
          PartNodes &nodes = parts[p];
          nodes.c          = poses[p].current_reference_position();
          for (unsigned int n = 0; n < nodes.dofs.size(); ++n)
            for (unsigned int d = 0; d < 3; ++d)
              nodes.x[n][d] = nodes.X[n][d] + u.local_element(nodes.dofs[n][d]);
        }
    }



    Tensor<1, 3>
    RigidPartUnknowns::mode(const unsigned int j, const unsigned int n) const
    {
      const Unknown &unknown = unknowns[j];
      Tensor<1, 3>   axis;
      axis[unknown.direction % 3] = 1.;
      if (unknown.direction < 3)
        return axis;
      const PartNodes &nodes = parts[unknown.part];
      return cross_product_3d(axis, nodes.x[n] - nodes.c);
    }



    void
    RigidPartUnknowns::add_block(const unsigned int      *dofs,
                                 const unsigned int       n,
                                 const double            *K,
                                 std::vector<VectorType> &column,
                                 std::vector<VectorType> &row)
    {
      // Most blocks touch no rigid part: one pass to find out.
      bool touched = false;
      for (unsigned int i = 0; i < n && !touched; ++i)
        touched = part_of_dof[dofs[i]] >= 0;
      if (!touched)
        return;
      blocks.push_back({std::vector<unsigned int>(dofs, dofs + n),
                        std::vector<double>(K, K + n * n)});
      std::vector<double> g(n);
      for (unsigned int p = 0; p < parts.size(); ++p)
        for (const unsigned int j : unknowns_of_part[p])
          {
            bool any = false;
            for (unsigned int b = 0; b < n; ++b)
              {
                const unsigned int i = dofs[b];
                g[b]                 = part_of_dof[i] == int(p) ?
                                         mode(j, node_of_dof[i])[component_of_dof[i]] :
                                         0.;
                any                  = any || g[b] != 0.;
              }
            if (!any)
              continue;
            for (unsigned int a = 0; a < n; ++a)
              {
                double Kg = 0., KTg = 0.;
                for (unsigned int b = 0; b < n; ++b)
                  if (g[b] != 0.)
                    {
                      Kg += K[n * a + b] * g[b];
                      KTg += K[n * b + a] * g[b];
                    }
                column[j].local_element(dofs[a]) += Kg;
                row[j].local_element(dofs[a]) += KTg;
              }
          }
    }



    template <typename Action>
    void
    RigidPartUnknowns::for_each_owned_entry(const unsigned int j,
                                            const Action      &action) const
    {
      const PartNodes &nodes = parts[unknowns[j].part];
      for (unsigned int n = 0; n < nodes.dofs.size(); ++n)
        if (nodes.owned[n])
          {
            const Tensor<1, 3> g = mode(j, n);
            for (unsigned int d = 0; d < 3; ++d)
              action(nodes.dofs[n][d], g[d]);
          }
    }



    std::vector<double>
    RigidPartUnknowns::project(const VectorType &v) const
    {
      std::vector<double> result(unknowns.size(), 0.);
      for (unsigned int j = 0; j < unknowns.size(); ++j)
        for_each_owned_entry(j, [&](const unsigned int i, const double g) {
          result[j] += g * v.local_element(i);
        });
      Utilities::MPI::sum(ArrayView<const double>(result),
                          comm,
                          ArrayView<double>(result));
      return result;
    }



    void
    RigidPartUnknowns::add_geometric_stiffness(const VectorType   &r,
                                               FullMatrix<double> &block) const
    {
      // d/d(theta_l) of e_k . sum_i a_i x r_i at fixed r: the lever arms
      // turn, delta a_i = delta theta x a_i, and
      // (delta theta x a) x r = a (delta theta . r) - delta theta (a . r).
      const unsigned int  m = unknowns.size();
      std::vector<double> geometric(m * m, 0.);
      for (unsigned int p = 0; p < parts.size(); ++p)
        {
          const PartNodes &nodes = parts[p];
          Tensor<2, 3>     sum;
          for (unsigned int n = 0; n < nodes.dofs.size(); ++n)
            if (nodes.owned[n])
              {
                const Tensor<1, 3> a = nodes.x[n] - nodes.c;
                Tensor<1, 3>       force;
                for (unsigned int d = 0; d < 3; ++d)
                  force[d] = r.local_element(nodes.dofs[n][d]);
                const double a_dot_r = a * force;
                for (unsigned int k = 0; k < 3; ++k)
                  for (unsigned int l = 0; l < 3; ++l)
                    sum[k][l] += a[k] * force[l] - (k == l ? a_dot_r : 0.);
              }
          for (const unsigned int j : unknowns_of_part[p])
            for (const unsigned int i : unknowns_of_part[p])
              if (unknowns[i].direction >= 3 && unknowns[j].direction >= 3)
                geometric[i * m + j] =
                  sum[unknowns[i].direction - 3][unknowns[j].direction - 3];
        }
      Utilities::MPI::sum(ArrayView<const double>(geometric),
                          comm,
                          ArrayView<double>(geometric));
      for (unsigned int i = 0; i < m; ++i)
        for (unsigned int j = 0; j < m; ++j)
          block(i, j) += geometric[i * m + j];
    }



    void
    RigidPartUnknowns::add_curvature_force(
      const std::vector<model::RigidBody> &poses,
      const std::vector<double>           &dq,
      VectorType                          &force) const
    {
      std::vector<model::RigidBody> moved = poses;
      advance(moved, dq, 1.);
      // e at every local node of the parts (owned and ghost: the kept
      // blocks reach both).
      std::vector<double> e(part_of_dof.size(), 0.);
      for (unsigned int p = 0; p < parts.size(); ++p)
        {
          const PartNodes &nodes = parts[p];
          const Point<3>   c     = moved[p].current_reference_position();
          for (unsigned int n = 0; n < nodes.dofs.size(); ++n)
            {
              Tensor<1, 3> linear;
              for (const unsigned int j : unknowns_of_part[p])
                linear += dq[j] * mode(j, n);
              const Point<3> x =
                c +
                moved[p].rotation * (nodes.X[n] - moved[p].reference_position);
              const Tensor<1, 3> miss = (x - nodes.x[n]) - linear;
              for (unsigned int d = 0; d < 3; ++d)
                e[nodes.dofs[n][d]] = miss[d];
            }
        }
      for (const Block &block : blocks)
        {
          const unsigned int n = block.dofs.size();
          for (unsigned int a = 0; a < n; ++a)
            {
              double Ke = 0.;
              for (unsigned int b = 0; b < n; ++b)
                Ke += block.K[n * a + b] * e[block.dofs[b]];
              force.local_element(block.dofs[a]) += Ke;
            }
        }
    }



    void
    RigidPartUnknowns::add_linear_motion(const std::vector<double> &dq,
                                         VectorType                &du) const
    {
      for (unsigned int j = 0; j < unknowns.size(); ++j)
        for_each_owned_entry(j, [&](const unsigned int i, const double g) {
          du.local_element(i) += g * dq[j];
        });
    }
  } // namespace time_integration
} // namespace rubberdyn
