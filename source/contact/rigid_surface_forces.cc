#include <rubberdyn/base/binary_io.h>
#include <rubberdyn/contact/rigid_surface_forces.h>

#include <algorithm>

namespace rubberdyn
{
  namespace contact
  {
    RigidSurfaceForces::RigidSurfaceForces(
      RigidSurfaceContact &            contact,
      const std::vector<unsigned int> &body_of_surface)
      : contact(contact)
      , body_of_surface(body_of_surface)
      , pose(body_of_surface.size())
    {}



    std::string
    RigidSurfaceForces::name() const
    {
      return "rigid-surface contact";
    }



    model::ForceContribution::Accumulation
    RigidSurfaceForces::accumulation() const
    {
      return Accumulation::external_owned;
    }



    std::vector<SurfacePose>
    RigidSurfaceForces::poses(const std::vector<model::RigidBody> &bodies) const
    {
      std::vector<SurfacePose> result(body_of_surface.size());
      for (unsigned int s = 0; s < body_of_surface.size(); ++s)
        {
          AssertIndexRange(body_of_surface[s], bodies.size());
          const model::RigidBody &body = bodies[body_of_surface[s]];
          result[s].displacement        = body.displacement;
          result[s].rotation            = body.rotation;
          result[s].centre              = body.reference_position;
          result[s].rotated             = body.rotates();
        }
      return result;
    }



    void
    RigidSurfaceForces::add_forces(const model::EvaluationPoint &point,
                                   VectorType &                  f,
                                   model::ContributionResults &  results)
    {
      pose = poses(point.bodies);
      contact.add_forces(point.displacement, pose, f, contact_result);
      results.contact_energy += contact_result.penalty_energy;
      results.friction_dissipation += contact_result.friction_dissipation;
      for (unsigned int s = 0; s < body_of_surface.size(); ++s)
        {
          results.force_on_body[body_of_surface[s]] +=
            contact_result.force_on_plane[s];
          results.moment_on_body[body_of_surface[s]] +=
            contact_result.moment_on_plane[s];
        }
      results.contact_time_step =
        std::min(results.contact_time_step,
                 contact.stable_time_step(point.mass));
    }



    bool
    RigidSurfaceForces::supports_implicit() const
    {
      return true;
    }



    bool
    RigidSurfaceForces::symmetric_tangent() const
    {
      return !contact.has_friction();
    }



    void
    RigidSurfaceForces::add_tangents(const model::EvaluationPoint &point,
                                     const TangentBlock           &add) const
    {
      const Utilities::MPI::Partitioner &partitioner =
        *point.displacement.get_partitioner();
      std::vector<types::global_dof_index> dofs(3);
      std::vector<double>                  K(9);
      contact.add_tangents(point.displacement,
                           poses(point.bodies),
                           [&](const unsigned int (&node_dofs)[3],
                               const unsigned int,
                               const Tensor<2, 3> &node_K) {
                             for (unsigned int i = 0; i < 3; ++i)
                               {
                                 dofs[i] =
                                   partitioner.local_to_global(node_dofs[i]);
                                 for (unsigned int j = 0; j < 3; ++j)
                                   K[3 * i + j] = node_K[i][j];
                               }
                             add(dofs, K);
                           });
    }



    void
    RigidSurfaceForces::add_body_motion_load(
      const model::EvaluationPoint        &point,
      const std::vector<model::RigidBody> &moved,
      VectorType                          &load) const
    {
      // The force depends on the node's position relative to the surface,
      // x - u_b: moving the surface by du_b at a fixed node changes the
      // resisting force by -K du_b, i.e. the load on the solid by K du_b.
      std::vector<Tensor<1, 3>> motion(body_of_surface.size());
      for (unsigned int s = 0; s < body_of_surface.size(); ++s)
        {
          const unsigned int b = body_of_surface[s];
          AssertThrow(!point.bodies[b].rotates() && !moved[b].rotates(),
                      ExcMessage("The linearised motion of a rotating rigid "
                                 "surface is not implemented"));
          motion[s] = moved[b].displacement - point.bodies[b].displacement;
        }
      contact.add_tangents(point.displacement,
                           poses(point.bodies),
                           [&](const unsigned int (&dofs)[3],
                               const unsigned int  surface,
                               const Tensor<2, 3> &K) {
                             const Tensor<1, 3> f = K * motion[surface];
                             for (unsigned int d = 0; d < 3; ++d)
                               load.local_element(dofs[d]) += f[d];
                           });
    }



    bool
    RigidSurfaceForces::follow_geometry()
    {
      contact.follow_geometry();
      return true;
    }



    void
    RigidSurfaceForces::accept_step()
    {
      contact.accept();
      accepted_friction_work += contact_result.friction_dissipation;
      contact_result.friction_dissipation = 0.;
    }



    double
    RigidSurfaceForces::contact_energy() const
    {
      return contact_result.penalty_energy;
    }



    double
    RigidSurfaceForces::friction_work() const
    {
      return accepted_friction_work + contact_result.friction_dissipation;
    }



    void
    RigidSurfaceForces::save(std::ostream &out) const
    {
      const std::vector<double> &state = contact.state();
      binary_io::write_doubles(out, state.data(), state.size());
      binary_io::write_doubles(out, &accepted_friction_work, 1);
      binary_io::write_doubles(out, &contact_result.penalty_energy, 1);
      contact.save_stiffness(out);
    }



    void
    RigidSurfaceForces::load(std::istream &in)
    {
      std::vector<double> &state = contact.state();
      binary_io::read_doubles(in, state.data(), state.size(), "contact state");
      binary_io::read_doubles(in, &accepted_friction_work, 1,
                              "friction work");
      binary_io::read_doubles(in, &contact_result.penalty_energy, 1,
                              "contact energy");
      contact.load_stiffness(in);
      contact_result.friction_dissipation = 0.;
    }
  } // namespace contact
} // namespace rubberdyn
