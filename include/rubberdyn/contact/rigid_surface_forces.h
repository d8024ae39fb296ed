#ifndef rubberdyn_contact_rigid_surface_forces_h
#define rubberdyn_contact_rigid_surface_forces_h

#include <rubberdyn/contact/rigid_surface_contact.h>
#include <rubberdyn/model/force_contribution.h>

#include <vector>

namespace rubberdyn
{
  namespace contact
  {
    /**
     * Node-to-surface penalty contact with rigid surfaces as a force
     * contribution: each surface moves with the translation of its rigid
     * body; the contact forces on the bodies, the penalty energy, the
     * friction dissipation, the penalty springs' stable step and the
     * friction state in checkpoints. In the quasi-static solver: the
     * exact tangent (RigidSurfaceContact::add_tangents()), the friction
     * state accepted with each converged load step.
     */
    class RigidSurfaceForces : public model::ForceContribution
    {
    public:
      /**
       * @param contact Initialised contact (kept by reference).
       * @param body_of_surface Index of the rigid body that carries each
       *   surface of @p contact.
       */
      RigidSurfaceForces(RigidSurfaceContact &            contact,
                         const std::vector<unsigned int> &body_of_surface);

      std::string
      name() const override;

      Accumulation
      accumulation() const override;

      void
      add_forces(const model::EvaluationPoint &point,
                 VectorType &                  f,
                 model::ContributionResults &  results) override;

      /** The penalty stiffness follows the current geometry. */
      bool
      follow_geometry() override;

      void
      accept_step() override;

      bool
      supports_implicit() const override;

      /** Frictionless contact only (Coulomb's return mapping is not). */
      bool
      symmetric_tangent() const override;

      void
      add_tangents(const model::EvaluationPoint &point,
                   const TangentBlock           &add) const override;

      /**
       * K_node times the translation of the node's surface, for every node
       * with a closed gap: the surfaces' motion at fixed nodes, linearised.
       * Bodies that rotate are not supported (ExcMessage).
       */
      void
      add_body_motion_load(const model::EvaluationPoint        &point,
                           const std::vector<model::RigidBody> &moved,
                           VectorType &load) const override;

      /**
       * Force of the solid on the surfaces at the last evaluation (kN),
       * this rank's nodes.
       */
      const ContactResult &
      last_result() const
      {
        return contact_result;
      }

      /**
       * Energy in this contact's penalty springs at the last evaluation
       * (J), this rank's nodes.
       */
      double
      contact_energy() const;

      /**
       * Energy its friction has dissipated up to the last evaluation (J),
       * this rank's nodes.
       */
      double
      friction_work() const;

      void
      save(std::ostream &out) const override;

      void
      load(std::istream &in) override;

    private:
      /** Where the surfaces are: with their bodies in @p bodies. */
      std::vector<SurfacePose>
      poses(const std::vector<model::RigidBody> &bodies) const;

      RigidSurfaceContact &     contact;
      std::vector<unsigned int> body_of_surface;
      std::vector<SurfacePose>  pose;
      ContactResult             contact_result;
      /** Friction work up to the last accepted step, this rank (J). */
      double accepted_friction_work = 0.;
    };
  } // namespace contact
} // namespace rubberdyn

#endif
