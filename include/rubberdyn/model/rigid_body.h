#ifndef rubberdyn_model_rigid_body_h
#define rubberdyn_model_rigid_body_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <functional>
#include <string>

namespace rubberdyn
{
  namespace model
  {
    using namespace dealii;

    /**
     * A rigid body: the carrier of a rigid surface (a plate, an impactor, a
     * pin), or a rigid part of the mesh (LS-DYNA's MAT_RIGID), whose nodes
     * move with it.
     *
     * Translation: with a positive mass it moves under the forces of the
     * solid and gravity in its free directions; with mass 0, or in a held
     * direction, it follows its prescribed velocity (zero if none is
     * given), and the work it does on the solid is external work.
     *
     * Rotation (rigid parts only): about its centre of mass, in the free
     * rotation directions: the angular momentum L advances with the
     * moment, $\dot L = M$, the angular velocity is $\omega = I^{-1} L$
     * with $I = R I_0 R^T$, and $\dot R = [\omega]_\times R$ (exactly
     * orthogonal, by Rodrigues' formula per step). A body whose rotations
     * are all held keeps R = 1.
     *
     * The current position of a material point X of the body is
     * $x = C + u + R (X - C)$, C the reference position (the centre of
     * mass of a rigid part), u the displacement.
     */
    struct RigidBody
    {
      /** Name, for the time history columns `<name>_position_x` etc. */
      std::string name;
      /** Mass (kg); 0: moves as prescribed. */
      double mass = 0.;
      /** Free translation per direction (with mass > 0). */
      bool free[3] = {false, false, false};
      /** Free rotation about the axes x, y, z (rigid parts, mass > 0). */
      bool free_rotation[3] = {false, false, false};
      /**
       * Velocity (mm/ms) as a function of time (ms) in the directions that
       * are not free; empty: zero there.
       */
      std::function<Tensor<1, 3>(double)> prescribed_velocity;
      /**
       * Position of the body's reference point at t = 0 (mm): for a rigid
       * part its centre of mass, about which it rotates.
       */
      Point<3> reference_position;
      /**
       * Rotational inertia about the reference point at t = 0 (kg mm^2).
       */
      Tensor<2, 3> inertia;
      /**
       * Whether the body is a rigid part: its weight is in the nodal forces
       * of its nodes (weight below), and so is the work of gravity on it.
       */
      bool carries_nodes = false;
      /** The gravity force on a rigid part's nodes (kN), for its update. */
      Tensor<1, 3> weight;

      /** Displacement (mm) at t_n and velocity at t_{n-1/2} (mm/ms). */
      Tensor<1, 3> displacement, velocity;
      /** Rotation at t_n (orthogonal) and angular velocity at t_{n-1/2} (1/ms). */
      Tensor<2, 3> rotation = unit_tensor();
      Tensor<1, 3> angular_velocity;
      /** Angular momentum about the reference point at t_{n-1/2} (kg mm^2/ms). */
      Tensor<1, 3> angular_momentum;
      /**
       * Force of the solid on the body at the last evaluation (kN), and its
       * moment about the body's current reference point (kN mm).
       */
      Tensor<1, 3> contact_force, contact_moment;

      /** Whether the body moves under forces in direction @p d. */
      bool
      moves_freely(const unsigned int d) const
      {
        return mass > 0. && free[d];
      }

      /** Whether the body may rotate at all. */
      bool
      rotates() const
      {
        return mass > 0. &&
               (free_rotation[0] || free_rotation[1] || free_rotation[2]);
      }

      /**
       * The rotation after a step @p step (ms) with the current angular
       * velocity: exp(step [w]x) R, or R for a body that does not rotate.
       */
      Tensor<2, 3>
      rotation_after(const double step) const;

      /**
       * Where the body is at pseudo-time @p t of a quasi-static load path
       * (no inertia): in the directions it does not move freely, the
       * integral of its prescribed velocity from 0 to t (mm; the Velocity
       * function read as mm per unit pseudo-time), in its free directions
       * zero (statics cannot place a free body that nothing loads).
       * Adaptive Simpson quadrature to 1e-12 of the travel.
       */
      Tensor<1, 3>
      displacement_on_load_path(const double t) const;

      /** The current position of the reference point (mm). */
      Point<3>
      current_reference_position() const
      {
        return reference_position + displacement;
      }

      /** The 3 x 3 identity. */
      static Tensor<2, 3>
      unit_tensor()
      {
        Tensor<2, 3> one;
        for (unsigned int d = 0; d < 3; ++d)
          one[d][d] = 1.;
        return one;
      }
    };

    /**
     * The names of a rigid body's six directions, as `Rigid motion` lists
     * them: translations x, y, z, then rotations rx, ry, rz about axes
     * through its centre of mass.
     */
    inline constexpr const char *rigid_direction_names[6] = {
      "x", "y", "z", "rx", "ry", "rz"};

    /**
     * The rotation $\exp([\theta]_\times)$ of the rotation vector
     * @p theta (Rodrigues' formula; exact, orthogonal to round-off).
     */
    Tensor<2, 3>
    rotation_of_vector(const Tensor<1, 3> &theta);

    /** The rotation vector of the rotation @p R (the inverse of the above). */
    Tensor<1, 3>
    rotation_vector(const Tensor<2, 3> &R);
  } // namespace model
} // namespace rubberdyn

#endif
