#include <deal.II/dofs/dof_handler.h>
#include <deal.II/base/geometry_info.h>
#include <deal.II/fe/fe.h>

#include <rubberdyn/base/binary_io.h>
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
      // The contact faces of the owned cells, and the nodes' stiffness in
      // the reference configuration summed over the z dofs.
      const FiniteElement<3> &fe = dof_handler.get_fe();
      std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
      faces.clear();
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            cell->get_dof_indices(dof_indices);
            for (const unsigned int face : cell->face_indices())
              if (cell->at_boundary(face) &&
                  boundary_ids.count(cell->face(face)->boundary_id()))
                {
                  Face f;
                  for (unsigned int a = 0; a < 8; ++a)
                    {
                      for (unsigned int d = 0; d < 3; ++d)
                        f.dofs[a][d] = partitioner->global_to_local(
                          dof_indices[fe.component_to_system_index(d, a)]);
                      f.X[a] = cell->vertex(a);
                    }
                  // deal.II numbers a face's vertices lexicographically:
                  // 0, 1, 3, 2 go round it.
                  const unsigned int cyclic[4] = {0, 1, 3, 2};
                  for (unsigned int v = 0; v < 4; ++v)
                    f.corner[v] =
                      GeometryInfo<3>::face_to_cell_vertices(face, cyclic[v]);
                  f.scaled_bulk_modulus =
                    penalty_scale *
                    bulk_modulus_by_material.at(cell->material_id());
                  faces.push_back(f);
                }
          }
      stiffness_sum.reinit(partitioner);
      {
        VectorType zero(partitioner);
        compute_stiffness(zero);
      }

      nodes.clear();
      for (unsigned int i = 0; i < partitioner->locally_owned_size(); ++i)
        if (stiffness_sum.local_element(i) > 0.)
          {
            // i is a z dof; its x and y dofs belong to the same vertex.
            Node node;
            node.stiffness = stiffness_sum.local_element(i);
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
      accepted_state.assign(nodes.size() * surfaces.size() * 6,
                            std::numeric_limits<double>::quiet_NaN());
      for (unsigned int n = 0; n < nodes.size() * surfaces.size(); ++n)
        for (unsigned int d = 0; d < 3; ++d)
          accepted_state[n * 6 + d] = 0.;
      trial_state   = accepted_state;
      trial_pending = false;
      accepted_stiffness.clear();
      accepted_stiffness_energy = trial_stiffness_energy = 0.;
      follow_pending                                     = false;
    }



    void
    RigidSurfaceContact::compute_stiffness(const VectorType &u)
    {
      stiffness_sum = 0.;
      for (const Face &face : faces)
        {
          Point<3> x[8];
          for (unsigned int a = 0; a < 8; ++a)
            {
              x[a] = face.X[a];
              for (unsigned int d = 0; d < 3; ++d)
                x[a][d] += u.local_element(face.dofs[a][d]);
            }
          // The face's area: half the cross product of its diagonals (the
          // area of a plane quadrilateral, of a warped one's projection).
          const double area =
            0.5 * cross_product_3d(x[face.corner[2]] - x[face.corner[0]],
                                   x[face.corner[3]] - x[face.corner[1]])
                    .norm();
          // The cell's volume: the Jacobian of the trilinear map at the
          // centre (exact for a parallelepiped; a measure of size is all the
          // penalty needs). Its columns are the mean edge vectors in each
          // reference direction (vertex a at bits (i, j, k) of a).
          Tensor<2, 3> J;
          for (unsigned int a = 0; a < 8; ++a)
            for (unsigned int r = 0; r < 3; ++r)
              {
                const double sign = (a >> r) & 1 ? 0.25 : -0.25;
                for (unsigned int d = 0; d < 3; ++d)
                  J[d][r] += sign * x[a][d];
              }
          const double volume = determinant(J);
          // An inverted cell is the elements' failure to report; its face
          // keeps a positive stiffness meanwhile.
          const double k =
            face.scaled_bulk_modulus * area * area / std::abs(volume);
          for (unsigned int v = 0; v < 4; ++v)
            stiffness_sum.local_element(face.dofs[face.corner[v]][2]) +=
              0.25 * k;
        }
      stiffness_sum.compress(VectorOperation::add);
      for (Node &node : nodes)
        node.stiffness = stiffness_sum.local_element(node.dofs[2]);
    }



    void
    RigidSurfaceContact::follow_geometry()
    {
      follow_pending = true;
    }



    void
    RigidSurfaceContact::save_stiffness(std::ostream &out) const
    {
      const unsigned int n = accepted_stiffness.size();
      binary_io::write_doubles(out, &accepted_stiffness_energy, 1);
      const double n_stored = n;
      binary_io::write_doubles(out, &n_stored, 1);
      binary_io::write_doubles(out, accepted_stiffness.data(), n);
    }



    void
    RigidSurfaceContact::load_stiffness(std::istream &in)
    {
      binary_io::read_doubles(in,
                              &accepted_stiffness_energy,
                              1,
                              "contact stiffness energy");
      double n_stored = 0.;
      binary_io::read_doubles(in, &n_stored, 1, "contact stiffness count");
      AssertThrow(n_stored == 0. || n_stored == nodes.size(),
                  ExcMessage("The checkpoint's contact stiffness has " +
                             std::to_string(n_stored) + " nodes, the mesh " +
                             std::to_string(nodes.size())));
      accepted_stiffness.resize(static_cast<unsigned int>(n_stored));
      binary_io::read_doubles(in,
                              accepted_stiffness.data(),
                              accepted_stiffness.size(),
                              "contact stiffness");
      trial_stiffness_energy = 0.;
    }



    void
    RigidSurfaceContact::gap_and_normal(const RigidSurface &surface,
                                        const Point<3> &    x,
                                        double &            gap,
                                        Tensor<1, 3> &      normal,
                                        Tensor<2, 3> *      curvature)
    {
      const Tensor<1, 3> from_point = x - surface.point;
      if (curvature != nullptr)
        *curvature = 0.;
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
      const double sign =
        surface.shape == RigidSurface::Shape::cylinder_solid_outside ? 1. :
                                                                        -1.;
      gap    = sign * (distance - surface.radius);
      normal = sign * direction;
      // d(direction)/dx = (1 - a a - d d) / distance, a the axis.
      if (curvature != nullptr && distance > 0.)
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = 0; j < 3; ++j)
            (*curvature)[i][j] =
              sign *
              ((i == j ? 1. : 0.) - surface.normal[i] * surface.normal[j] -
               direction[i] * direction[j]) /
              distance;
    }



    Point<3>
    RigidSurfaceContact::relative_position(const SurfacePose &p,
                                           const Point<3>    &x)
    {
      // Relative to the surface's translation, and rotated back for a
      // rotating body (the friction state is kept in that frame, so it
      // turns with the body).
      return p.rotated ?
               p.centre + transpose(p.rotation) *
                            (x - p.centre - p.displacement) :
               x - p.displacement;
    }



    void
    RigidSurfaceContact::node_contact(const RigidSurface &surface,
                                      const double        stiffness,
                                      const Point<3>     &x,
                                      const double        gap,
                                      const Tensor<1, 3> &normal,
                                      const Tensor<2, 3> &curvature,
                                      const Tensor<1, 3> &accepted_force,
                                      const Tensor<1, 3> &accepted_position,
                                      NodeContact        &c,
                                      Tensor<2, 3>       *jacobian)
    {
      c.normal_force = -stiffness * gap; // > 0
      c.force        = c.normal_force * normal;
      c.slip         = false;
      c.old_force = c.increment = c.tangential_force = Tensor<1, 3>();
      Tensor<2, 3> one;
      for (unsigned int d = 0; d < 3; ++d)
        one[d][d] = 1.;
      // Normal: f = -k g n, df/dx = -k (n n + g dn/dx).
      if (jacobian != nullptr)
        *jacobian = -stiffness * (outer_product(normal, normal) +
                                  gap * curvature);
      if (surface.friction_coefficient == 0.)
        return;

      // Rotate the old force into the current tangent plane (keeping its
      // magnitude), then add the elastic increment of the tangential
      // relative motion.
      Tensor<1, 3> &tangential_force = c.tangential_force;
      tangential_force               = accepted_force;
      const double old_magnitude     = tangential_force.norm();
      tangential_force -= (tangential_force * normal) * normal;
      const double projected = tangential_force.norm();
      const Tensor<1, 3> turned = tangential_force;
      if (projected > 0.)
        tangential_force *= old_magnitude / projected;
      const bool   has_position = !std::isnan(accepted_position[0]);
      Tensor<1, 3> motion       = x - accepted_position;
      if (!has_position)
        motion = 0.;
      Tensor<1, 3> &increment = c.increment;
      increment               = motion;
      increment -= (increment * normal) * normal;
      c.old_force = tangential_force;
      tangential_force -= stiffness * increment;
      const double limit = surface.friction_coefficient * c.normal_force;
      const double trial = tangential_force.norm();
      const Tensor<1, 3> trial_force = tangential_force;
      // Slip only beyond the cone, with a tolerance for round-off: a node
      // that slipped in the accepted state sits on the cone, and must stick
      // when it does not move (the elastic predictor of a return mapping);
      // classified by round-off it could be either, and the quasi-static
      // solver would linearise about a sliding floor (zero stiffness along
      // the slip) at the start of every load step.
      if (trial > limit * (1. + 1e-12))
        {
          // Slip: back to the cone.
          tangential_force *= limit / trial;
          c.slip = true;
        }
      c.force += tangential_force;
      if (jacobian == nullptr)
        return;

      // The old force turned: t1 = t - (t.n) n, dt1/dx = -n (G t) - (t.n) G
      // with G = dn/dx (symmetric), then scaled to its old magnitude.
      const Tensor<1, 3> &t = accepted_force;
      Tensor<2, 3>        d_turned =
        -outer_product(normal, curvature * t) - (t * normal) * curvature;
      if (projected > 0.)
        {
          const Tensor<1, 3> e = turned / projected;
          d_turned = (old_magnitude / projected) *
                     ((one - outer_product(e, e)) * d_turned);
        }
      // The tangential increment: dt = m - (m.n) n, m = x - x_accepted.
      Tensor<2, 3> d_increment;
      if (has_position)
        d_increment = one - outer_product(normal, normal) -
                      outer_product(normal, curvature * motion) -
                      (motion * normal) * curvature;
      const Tensor<2, 3> d_trial = d_turned - stiffness * d_increment;
      if (!c.slip)
        *jacobian += d_trial;
      else
        {
          // f_t = L tau, L = mu k (-g) (dL/dx = -mu k n), tau = trial/|trial|.
          const Tensor<1, 3> tau = trial_force / trial;
          *jacobian +=
            outer_product(tau,
                          -surface.friction_coefficient * stiffness * normal) +
            (limit / trial) * ((one - outer_product(tau, tau)) * d_trial);
        }
    }



    namespace
    {
      /**
       * What the stiffness updates since the accepted state put into a
       * node's springs against @p surface (J), added to @p energy: the
       * node at @p x_relative (surface frame; gap @p gap, normal
       * @p normal) with the new @p stiffness, accepted at
       * @p last_position with the stiffness @p k_accepted and the
       * tangential force @p tangential_force.
       */
      void
      add_stiffness_update_energy(const RigidSurface &surface,
                                  const double        stiffness,
                                  const double        k_accepted,
                                  const double        gap,
                                  const Tensor<1, 3> &normal,
                                  const Point<3>     &x_relative,
                                  const Tensor<1, 3> &last_position,
                                  const Tensor<1, 3> &tangential_force,
                                  double             &energy)
      {
        // The normal spring: what it stores now beyond the
        // accepted state less the work the node did on it since
        // (trapezoidal rule, as the energy balance sees the
        // forces), i.e. what the stiffness updates put in.
        double       gap_accepted;
        Tensor<1, 3> normal_accepted;
        RigidSurfaceContact::gap_and_normal(surface,
                                            Point<3>(last_position),
                                            gap_accepted,
                                            normal_accepted);
        const double       pressed_now      = std::max(-gap, 0.);
        const double       pressed_accepted = std::max(-gap_accepted, 0.);
        const Tensor<1, 3> force_sum =
          stiffness * pressed_now * normal +
          k_accepted * pressed_accepted * normal_accepted;
        energy += 0.5 * stiffness * pressed_now * pressed_now -
                  0.5 * k_accepted * pressed_accepted * pressed_accepted +
                  0.5 * force_sum * (x_relative - last_position);
        // The tangential spring: its accepted force's energy
        // |f_t|^2 / 2k at the new stiffness.
        energy += 0.5 * tangential_force.norm_square() *
                  (1. / stiffness - 1. / k_accepted);
      }
    } // namespace



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
      if (follow_pending)
        {
          compute_stiffness(u);
          follow_pending = false;
        }
      // What the stiffness updates since the accepted state added to the
      // springs (none booked before the first accepted evaluation).
      const bool book_update = !accepted_stiffness.empty();
      trial_stiffness_energy = 0.;
      n_touched.resize(nodes.size());
      const Tensor<2, 3> no_curvature;
      NodeContact        c;
      for (unsigned int n = 0; n < nodes.size(); ++n)
        {
          n_touched[n] = 0;
          const Node  &node = nodes[n];
          const double k_accepted =
            book_update ? accepted_stiffness[n] : node.stiffness;
          Point<3>    x    = node.X;
          for (unsigned int d = 0; d < 3; ++d)
            x[d] += u.local_element(node.dofs[d]);
          for (unsigned int s = 0; s < n_surfaces; ++s)
            {
              const RigidSurface &surface    = surfaces[s];
              const SurfacePose  &p          = pose[s];
              const Point<3>      x_relative = relative_position(p, x);
              double              gap;
              Tensor<1, 3>        normal;
              gap_and_normal(surface, x_relative, gap, normal);

              // From the accepted state into the trial state.
              const double *const old =
                &accepted_state[(n * n_surfaces + s) * 6];
              double *const state = &trial_state[(n * n_surfaces + s) * 6];
              Tensor<1, 3>  tangential_force, last_position;
              for (unsigned int d = 0; d < 3; ++d)
                {
                  tangential_force[d] = old[d];
                  last_position[d]    = old[3 + d];
                  state[3 + d]        = x_relative[d];
                }
              if (book_update && !std::isnan(last_position[0]))
                add_stiffness_update_energy(surface,
                                            node.stiffness,
                                            k_accepted,
                                            gap,
                                            normal,
                                            x_relative,
                                            last_position,
                                            tangential_force,
                                            trial_stiffness_energy);
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
              node_contact(surface,
                           node.stiffness,
                           x_relative,
                           gap,
                           normal,
                           no_curvature,
                           tangential_force,
                           last_position,
                           c,
                           nullptr);
              result.penalty_energy += 0.5 * node.stiffness * gap * gap;
              if (surface.friction_coefficient > 0.)
                {
                  if (c.slip)
                    // Dissipated: the work the node did on the spring over
                    // the step (trapezoidal rule, as the energy balance
                    // sees it) minus what the spring now holds more. Steady
                    // slip at the limit gives limit |increment|; a limit
                    // that shrinks with no motion gives all the energy
                    // released, (trial^2 - limit^2) / 2k (the part (trial -
                    // limit)^2 / 2k of it went missing when only limit
                    // (trial - limit) / k was booked).
                    result.friction_dissipation +=
                      -0.5 * (c.old_force + c.tangential_force) *
                        c.increment -
                      0.5 *
                        (c.tangential_force.norm_square() -
                         c.old_force.norm_square()) /
                        node.stiffness;
                  result.penalty_energy += 0.5 *
                                           c.tangential_force.norm_square() /
                                           node.stiffness;
                }
              for (unsigned int d = 0; d < 3; ++d)
                state[d] = c.tangential_force[d];
              // Back to the spatial frame.
              const Tensor<1, 3> force =
                p.rotated ? Tensor<1, 3>(p.rotation * c.force) : c.force;
              for (unsigned int d = 0; d < 3; ++d)
                f.local_element(node.dofs[d]) += force[d];
              result.force_on_plane[s] -= force;
              result.moment_on_plane[s] -=
                cross_product_3d(x - p.centre - p.displacement, force);
            }
        }
      result.penalty_energy -=
        accepted_stiffness_energy + trial_stiffness_energy;
      trial_pending = true;
    }



    void
    RigidSurfaceContact::accept()
    {
      if (trial_pending)
        {
          accepted_state.swap(trial_state);
          accepted_stiffness_energy += trial_stiffness_energy;
          trial_stiffness_energy = 0.;
          accepted_stiffness.resize(nodes.size());
          for (unsigned int n = 0; n < nodes.size(); ++n)
            accepted_stiffness[n] = nodes[n].stiffness;
        }
      trial_pending = false;
    }



    bool
    RigidSurfaceContact::has_friction() const
    {
      for (const RigidSurface &surface : surfaces)
        if (surface.friction_coefficient > 0.)
          return true;
      return false;
    }



    void
    RigidSurfaceContact::add_tangents(const VectorType               &u,
                                      const std::vector<SurfacePose> &pose,
                                      const NodeTangent &add) const
    {
      const unsigned int n_surfaces = surfaces.size();
      AssertDimension(pose.size(), n_surfaces);
      NodeContact c;
      for (unsigned int n = 0; n < nodes.size(); ++n)
        {
          const Node &node = nodes[n];
          Point<3>    x    = node.X;
          for (unsigned int d = 0; d < 3; ++d)
            x[d] += u.local_element(node.dofs[d]);
          for (unsigned int s = 0; s < n_surfaces; ++s)
            {
              const SurfacePose &p          = pose[s];
              const Point<3>     x_relative = relative_position(p, x);
              double             gap;
              Tensor<1, 3>       normal;
              Tensor<2, 3>       curvature;
              gap_and_normal(surfaces[s], x_relative, gap, normal, &curvature);
              // A closed gap is active (the class documentation).
              if (gap > 0.)
                continue;
              const double *const old =
                &accepted_state[(n * n_surfaces + s) * 6];
              const Tensor<1, 3> accepted_force({old[0], old[1], old[2]});
              const Tensor<1, 3> accepted_position({old[3], old[4], old[5]});
              Tensor<2, 3>       jacobian;
              node_contact(surfaces[s],
                           node.stiffness,
                           x_relative,
                           gap,
                           normal,
                           curvature,
                           accepted_force,
                           accepted_position,
                           c,
                           &jacobian);
              // x_relative = R^T (x - ...), force = R f: dF/dx = R J R^T;
              // the resisting force is minus the contact force.
              const Tensor<2, 3> K =
                p.rotated ?
                  Tensor<2, 3>(-(p.rotation * jacobian *
                                 transpose(p.rotation))) :
                  Tensor<2, 3>(-jacobian);
              add(node.dofs, s, K);
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
      // (A caller may overwrite it: a pending trial state is stale then.)
      trial_pending = false;
      return accepted_state;
    }
  } // namespace contact
} // namespace rubberdyn
