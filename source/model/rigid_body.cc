#include <deal.II/base/tensor.h>

#include <rubberdyn/model/rigid_body.h>

#include <cmath>

namespace rubberdyn
{
  namespace model
  {
    Tensor<2, 3>
    rotation_of_vector(const Tensor<1, 3> &theta)
    {
      // R = 1 + a [t]x + b [t]x^2 with a = sin|t|/|t|, b = (1 - cos|t|)/|t|^2;
      // near |t| = 0 their Taylor series (the closed forms lose digits).
      const double angle2 = theta.norm_square();
      const double angle  = std::sqrt(angle2);
      double       a, b;
      if (angle < 1e-4)
        {
          a = 1. - angle2 / 6. + angle2 * angle2 / 120.;
          b = 0.5 - angle2 / 24. + angle2 * angle2 / 720.;
        }
      else
        {
          a = std::sin(angle) / angle;
          b = (1. - std::cos(angle)) / angle2;
        }
      Tensor<2, 3> skew;
      skew[0][1] = -theta[2];
      skew[0][2] = theta[1];
      skew[1][0] = theta[2];
      skew[1][2] = -theta[0];
      skew[2][0] = -theta[1];
      skew[2][1] = theta[0];
      return RigidBody::unit_tensor() + a * skew + b * skew * skew;
    }



    Tensor<2, 3>
    RigidBody::rotation_after(const double step) const
    {
      return rotates() ? rotation_of_vector(step * angular_velocity) * rotation :
                         rotation;
    }



    Tensor<1, 3>
    rotation_vector(const Tensor<2, 3> &R)
    {
      const double cosine =
        std::max(-1., std::min(1., 0.5 * (trace(R) - 1.)));
      const double angle = std::acos(cosine);
      Tensor<1, 3> axis;
      axis[0] = R[2][1] - R[1][2];
      axis[1] = R[0][2] - R[2][0];
      axis[2] = R[1][0] - R[0][1];
      // axis = 2 sin(angle) n; near 0 sin(angle)/angle -> 1.
      const double sine = std::sin(angle);
      if (sine < 1e-8)
        return 0.5 * axis;
      return (0.5 * angle / sine) * axis;
    }
  } // namespace model
} // namespace rubberdyn
