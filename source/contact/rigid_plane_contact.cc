#include <deal.II/dofs/dof_handler.h>
#include <deal.II/base/geometry_info.h>
#include <deal.II/fe/fe.h>

#include <rubberdyn/contact/rigid_plane_contact.h>

#include <cmath>
#include <limits>
#include <map>

namespace rubberdyn
{
  namespace contact
  {
    void
    RigidPlaneContact::initialize(
      const DoFHandler<3, 3> &                                   dof_handler,
      const std::shared_ptr<const Utilities::MPI::Partitioner> &partitioner,
      const std::set<types::boundary_id> &                       boundary_ids,
      const std::vector<double> &bulk_modulus_by_material,
      const double               penalty_scale,
      const std::vector<RigidPlane> &planes_in)
    {
      planes = planes_in;
      // Stiffness per node, accumulated in a vector over the z dofs.
      VectorType stiffness(partitioner);
      const FiniteElement<3> &fe = dof_handler.get_fe();
      std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            cell->get_dof_indices(dof_indices);
            for (const unsigned int face : cell->face_indices())
              if (cell->at_boundary(face) &&
                  boundary_ids.count(cell->face(face)->boundary_id()))
                {
                  const double area = cell->face(face)->measure();
                  const double k = penalty_scale *
                                   bulk_modulus_by_material.at(
                                     cell->material_id()) *
                                   area * area / cell->measure();
                  for (unsigned int v = 0; v < 4; ++v)
                    {
                      // The set of a face's vertices does not depend on
                      // its orientation.
                      const unsigned int a =
                        GeometryInfo<3>::face_to_cell_vertices(face, v);
                      stiffness[dof_indices[fe.component_to_system_index(
                        2, a)]] += k / 4.;
                    }
                }
          }
      stiffness.compress(VectorOperation::add);

      nodes.clear();
      for (unsigned int i = 0; i < partitioner->locally_owned_size(); ++i)
        if (stiffness.local_element(i) > 0.)
          {
            // i is a z dof; its x and y dofs belong to the same vertex.
            Node node;
            node.stiffness = stiffness.local_element(i);
            node.dofs[2]   = i;
            node.dofs[0]   = node.dofs[1] = numbers::invalid_unsigned_int;
            nodes.push_back(node);
          }
      // The x and y dofs of each vertex: search the cells again.
      std::map<unsigned int, unsigned int> node_of_z_dof;
      for (unsigned int n = 0; n < nodes.size(); ++n)
        node_of_z_dof[nodes[n].dofs[2]] = n;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned() || cell->is_ghost())
          {
            cell->get_dof_indices(dof_indices);
            for (unsigned int a = 0; a < 8; ++a)
              {
                const types::global_dof_index z =
                  dof_indices[fe.component_to_system_index(2, a)];
                if (!partitioner->in_local_range(z))
                  continue;
                const auto it =
                  node_of_z_dof.find(partitioner->global_to_local(z));
                if (it == node_of_z_dof.end())
                  continue;
                Node &node = nodes[it->second];
                for (unsigned int d = 0; d < 2; ++d)
                  node.dofs[d] = partitioner->global_to_local(
                    dof_indices[fe.component_to_system_index(d, a)]);
                node.X = cell->vertex(a);
              }
          }
    }



    void
    RigidPlaneContact::add_forces(
      const VectorType &               u,
      const std::vector<Tensor<1, 3>> &plane_displacement,
      VectorType &                     f,
      ContactResult &                  result) const
    {
      result.force_on_plane.assign(planes.size(), Tensor<1, 3>());
      result.penalty_energy = 0.;
      for (const Node &node : nodes)
        {
          Point<3> x = node.X;
          for (unsigned int d = 0; d < 3; ++d)
            x[d] += u.local_element(node.dofs[d]);
          for (unsigned int p = 0; p < planes.size(); ++p)
            {
              const RigidPlane &plane = planes[p];
              const double      gap =
                plane.normal * (x - (plane.point + plane_displacement[p]));
              if (gap >= 0.)
                continue;
              const double force = -node.stiffness * gap;
              for (unsigned int d = 0; d < 3; ++d)
                f.local_element(node.dofs[d]) += force * plane.normal[d];
              result.force_on_plane[p] -= force * plane.normal;
              result.penalty_energy += 0.5 * node.stiffness * gap * gap;
            }
        }
    }



    double
    RigidPlaneContact::stable_time_step(const VectorType &mass) const
    {
      double step = std::numeric_limits<double>::max();
      for (const Node &node : nodes)
        step = std::min(step,
                        2. * std::sqrt(mass.local_element(node.dofs[2]) /
                                       node.stiffness));
      return step;
    }



    unsigned int
    RigidPlaneContact::n_nodes() const
    {
      return nodes.size();
    }
  } // namespace contact
} // namespace rubberdyn
