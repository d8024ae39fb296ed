#include <deal.II/base/tensor.h>

#include <rubberdyn/model/rigid_body.h>

#include <algorithm>
#include <cmath>
#include <functional>

namespace rubberdyn
{
  namespace model
  {
    Tensor<1, 3>
    RigidBody::displacement_on_load_path(const double t) const
    {
      Tensor<1, 3> travel;
      if (!prescribed_velocity || t == 0.)
        return travel;
      // Adaptive Simpson on [a, b] with the whole vector's error.
      const std::function<Tensor<1, 3>(double,
                                       double,
                                       const Tensor<1, 3> &,
                                       const Tensor<1, 3> &,
                                       const Tensor<1, 3> &,
                                       const Tensor<1, 3> &,
                                       double,
                                       unsigned int)>
        simpson = [&](const double        a,
                      const double        b,
                      const Tensor<1, 3> &fa,
                      const Tensor<1, 3> &fm,
                      const Tensor<1, 3> &fb,
                      const Tensor<1, 3> &whole,
                      const double        tolerance,
                      const unsigned int  depth) -> Tensor<1, 3> {
        const double       m     = 0.5 * (a + b);
        const Tensor<1, 3> flm   = prescribed_velocity(0.5 * (a + m));
        const Tensor<1, 3> frm   = prescribed_velocity(0.5 * (m + b));
        const Tensor<1, 3> left  = (m - a) / 6. * (fa + 4. * flm + fm);
        const Tensor<1, 3> right = (b - m) / 6. * (fm + 4. * frm + fb);
        const Tensor<1, 3> error = left + right - whole;
        if (depth == 0 || error.norm() <= 15. * tolerance)
          return left + right + error / 15.;
        return simpson(a, m, fa, flm, fm, left, 0.5 * tolerance, depth - 1) +
               simpson(m, b, fm, frm, fb, right, 0.5 * tolerance, depth - 1);
      };
      const Tensor<1, 3> f0 = prescribed_velocity(0.), f1 = prescribed_velocity(t),
                         fm = prescribed_velocity(0.5 * t);
      const Tensor<1, 3> coarse = t / 6. * (f0 + 4. * fm + f1);
      // The tolerance from the size of the travel (a first estimate of it:
      // the largest speed over the interval's three points times t).
      const double scale =
        std::max({f0.norm(), fm.norm(), f1.norm(), 1e-300}) * std::abs(t);
      travel = simpson(0., t, f0, fm, f1, coarse, 1e-12 * scale, 40);
      for (unsigned int d = 0; d < 3; ++d)
        if (moves_freely(d))
          travel[d] = 0.;
      return travel;
    }



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
