#include <deal.II/dofs/dof_handler.h>
#include <deal.II/base/geometry_info.h>
#include <deal.II/fe/fe.h>

#include <rubberdyn/contact/rigid_surface_contact.h>

#include <cmath>
#include <limits>
#include <map>

namespace rubberdyn
{
  namespace contact
  {
    void
    RigidSurfaceContact::initialize(
      const DoFHandler<3, 3> &                                   dof_handler,
      const std::shared_ptr<const Utilities::MPI::Partitioner> &partitioner,
      const std::set<types::boundary_id> &                       boundary_ids,
      const std::vector<double> &bulk_modulus_by_material,
      const double               penalty_scale,
      const std::vector<RigidSurface> &surfaces_in)
    {
      surfaces = surfaces_in;
      for (const RigidSurface &surface : surfaces)
        {
          AssertThrow(std::abs(surface.normal.norm() - 1.) < 1e-12,
                      ExcMessage("a rigid surface's normal or axis must be a "
                                 "unit vector"));
          AssertThrow(surface.friction_coefficient >= 0.,
                      ExcMessage("friction coefficients must not be negative"));
        }
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

      // Friction state: no tangential force; the last relative position is
      // unknown (NaN) until the first evaluation.
      friction_state.assign(nodes.size() * surfaces.size() * 6,
                            std::numeric_limits<double>::quiet_NaN());
      for (unsigned int n = 0; n < nodes.size() * surfaces.size(); ++n)
        for (unsigned int d = 0; d < 3; ++d)
          friction_state[n * 6 + d] = 0.;
    }



    void
    RigidSurfaceContact::gap_and_normal(const RigidSurface &surface,
                                        const Point<3> &    x,
                                        double &            gap,
                                        Tensor<1, 3> &      normal)
    {
      const Tensor<1, 3> from_point = x - surface.point;
      if (surface.shape == RigidSurface::Shape::plane)
        {
          normal = surface.normal;
          gap    = normal * from_point;
          return;
        }
      // Cylinder: radial vector from the axis.
      const Tensor<1, 3> radial =
        from_point - (from_point * surface.normal) * surface.normal;
      const double distance = radial.norm();
      // On the axis the direction is undefined (such a node is deep inside
      // a pin anyway): push it along any direction normal to the axis.
      Tensor<1, 3> direction;
      if (distance > 0.)
        direction = radial / distance;
      else
        {
          const Tensor<1, 3> trial =
            std::abs(surface.normal[0]) < 0.9 ? Tensor<1, 3>({1., 0., 0.}) :
                                                Tensor<1, 3>({0., 1., 0.});
          direction = cross_product_3d(surface.normal, trial);
          direction /= direction.norm();
        }
      if (surface.shape == RigidSurface::Shape::cylinder_solid_outside)
        {
          gap    = distance - surface.radius;
          normal = direction;
        }
      else
        {
          gap    = surface.radius - distance;
          normal = -direction;
        }
    }



    void
    RigidSurfaceContact::add_forces(
      const VectorType &              u,
      const std::vector<SurfacePose> &pose,
      VectorType &                    f,
      ContactResult &                 result)
    {
      const unsigned int n_surfaces = surfaces.size();
      AssertDimension(pose.size(), n_surfaces);
      result.force_on_plane.assign(n_surfaces, Tensor<1, 3>());
      result.moment_on_plane.assign(n_surfaces, Tensor<1, 3>());
      result.penalty_energy       = 0.;
      result.friction_dissipation = 0.;
      n_touched.resize(nodes.size());
      for (unsigned int n = 0; n < nodes.size(); ++n)
        {
          n_touched[n] = 0;
          const Node &node = nodes[n];
          Point<3>    x    = node.X;
          for (unsigned int d = 0; d < 3; ++d)
            x[d] += u.local_element(node.dofs[d]);
          for (unsigned int s = 0; s < n_surfaces; ++s)
            {
              const RigidSurface &surface = surfaces[s];
              // Position in the surface's reference frame: relative to its
              // translation, and rotated back for a rotating body (the
              // friction state is kept in that frame, so it turns with
              // the body).
              const SurfacePose &p          = pose[s];
              const Point<3>     x_relative =
                p.rotated ? p.centre + transpose(p.rotation) *
                                         (x - p.centre - p.displacement) :
                            x - p.displacement;
              double       gap;
              Tensor<1, 3> normal;
              gap_and_normal(surface, x_relative, gap, normal);

              double *const state = &friction_state[(n * n_surfaces + s) * 6];
              Tensor<1, 3>  tangential_force, last_position;
              for (unsigned int d = 0; d < 3; ++d)
                {
                  tangential_force[d] = state[d];
                  last_position[d]    = state[3 + d];
                  state[3 + d]        = x_relative[d];
                }
              if (gap >= 0.)
                {
                  // Separated: the tangential spring lets go. Dissipated, as
                  // in a slipping step with the new force zero: the
                  // trapezoidal work of the old force over this step's
                  // tangential motion plus the energy the spring held.
                  if (!std::isnan(last_position[0]) &&
                      tangential_force.norm_square() > 0.)
                    {
                      Tensor<1, 3> increment = x_relative - last_position;
                      increment -= (increment * normal) * normal;
                      result.friction_dissipation +=
                        -0.5 * tangential_force * increment +
                        0.5 * tangential_force.norm_square() /
                          node.stiffness;
                    }
                  for (unsigned int d = 0; d < 3; ++d)
                    state[d] = 0.;
                  continue;
                }

              ++n_touched[n];
              const double normal_force = -node.stiffness * gap; // > 0
              Tensor<1, 3> force        = normal_force * normal;
              result.penalty_energy += 0.5 * node.stiffness * gap * gap;

              if (surface.friction_coefficient > 0.)
                {
                  // Rotate the old force into the current tangent plane
                  // (keeping its magnitude), then add the elastic
                  // increment of the tangential relative motion.
                  const double old_magnitude = tangential_force.norm();
                  tangential_force -= (tangential_force * normal) * normal;
                  const double projected = tangential_force.norm();
                  if (projected > 0.)
                    tangential_force *= old_magnitude / projected;
                  Tensor<1, 3> increment = x_relative - last_position;
                  if (std::isnan(last_position[0]))
                    increment = 0.;
                  increment -= (increment * normal) * normal;
                  const Tensor<1, 3> old_force = tangential_force;
                  tangential_force -= node.stiffness * increment;
                  const double limit =
                    surface.friction_coefficient * normal_force;
                  const double trial = tangential_force.norm();
                  if (trial > limit)
                    {
                      // Slip: back to the cone. Dissipated: the work the
                      // node did on the spring over the step (trapezoidal
                      // rule, as the energy balance sees it) minus what the
                      // spring now holds more. Steady slip at the limit
                      // gives limit |increment|; a limit that shrinks with
                      // no motion gives all the energy released,
                      // (trial^2 - limit^2) / 2k (the part (trial -
                      // limit)^2 / 2k of it went missing when only
                      // limit (trial - limit) / k was booked).
                      tangential_force *= limit / trial;
                      result.friction_dissipation +=
                        -0.5 * (old_force + tangential_force) * increment -
                        0.5 *
                          (tangential_force.norm_square() -
                           old_force.norm_square()) /
                          node.stiffness;
                    }
                  result.penalty_energy += 0.5 *
                                           tangential_force.norm_square() /
                                           node.stiffness;
                  force += tangential_force;
                }
              for (unsigned int d = 0; d < 3; ++d)
                state[d] = tangential_force[d];
              // Back to the spatial frame.
              if (p.rotated)
                force = p.rotation * force;
              for (unsigned int d = 0; d < 3; ++d)
                f.local_element(node.dofs[d]) += force[d];
              result.force_on_plane[s] -= force;
              result.moment_on_plane[s] -=
                cross_product_3d(x - p.centre - p.displacement, force);
            }
        }
    }



    double
    RigidSurfaceContact::stable_time_step(const VectorType &mass) const
    {
      // A node pressed on several surfaces at once (a corner between two
      // plates) hangs on the sum of their springs.
      double step = std::numeric_limits<double>::max();
      for (unsigned int n = 0; n < nodes.size(); ++n)
        {
          const double springs =
            n < n_touched.size() ? std::max<double>(1., n_touched[n]) : 1.;
          step = std::min(step,
                          2. * std::sqrt(mass.local_element(nodes[n].dofs[2]) /
                                         (springs * nodes[n].stiffness)));
        }
      return step;
    }



    unsigned int
    RigidSurfaceContact::n_nodes() const
    {
      return nodes.size();
    }



    std::vector<double> &
    RigidSurfaceContact::state()
    {
      return friction_state;
    }
  } // namespace contact
} // namespace rubberdyn
