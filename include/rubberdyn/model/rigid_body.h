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
     * A rigid body that translates: the carrier of a rigid surface (a
     * plate, an impactor, a pin). With a positive mass it moves under the
     * contact forces and gravity in its free directions; with mass 0, or
     * in a held direction, it follows its prescribed velocity (zero if none
     * is given), and the work it does on the solid is external work.
     */
    struct RigidBody
    {
      /** Name, for the time history columns `<name>_position_x` etc. */
      std::string name;
      /** Mass (kg); 0: moves as prescribed. */
      double mass = 0.;
      /** Free translation per direction (with mass > 0). */
      bool free[3] = {false, false, false};
      /**
       * Velocity (mm/ms) as a function of time (ms) in the directions that
       * are not free; empty: zero there.
       */
      std::function<Tensor<1, 3>(double)> prescribed_velocity;
      /** Position of the body's reference point at t = 0 (mm). */
      Point<3> reference_position;

      /** Displacement (mm) at t_n and velocity at t_{n-1/2} (mm/ms). */
      Tensor<1, 3> displacement, velocity;
      /** Force of the solid on the body at the last evaluation (kN). */
      Tensor<1, 3> contact_force;

      /** Whether the body moves under forces in direction @p d. */
      bool
      moves_freely(const unsigned int d) const
      {
        return mass > 0. && free[d];
      }
    };
  } // namespace model
} // namespace rubberdyn

#endif
