#include <deal.II/base/tensor.h>

#include <rubberdyn/contact/mortar_segment.h>

#include <cmath>

#include "ad_number.h"

namespace rubberdyn
{
  namespace contact
  {
    namespace
    {
      /** Corners of the reference square, in FacetCorners' order. */
      constexpr double corner_xi[4]  = {-1., 1., 1., -1.};
      constexpr double corner_eta[4] = {-1., -1., 1., 1.};

      /** A point of the auxiliary plane in its own coordinates. */
      template <typename Number>
      struct PlanePoint
      {
        Number x, y;
      };

      /** At most 8 vertices: a quadrilateral clipped by another. */
      template <typename Number>
      struct Polygon
      {
        PlanePoint<Number> vertex[16];
        unsigned int       n = 0;
      };

      template <typename Number>
      Number
      cross(const PlanePoint<Number> &a,
            const PlanePoint<Number> &b,
            const PlanePoint<Number> &c)
      {
        return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
      }

      template <typename Number>
      Number
      signed_area(const Polygon<Number> &p)
      {
        Number area = 0.;
        for (unsigned int i = 0; i < p.n; ++i)
          {
            const PlanePoint<Number> &a = p.vertex[i],
                                     &b = p.vertex[(i + 1) % p.n];
            area += a.x * b.y - b.x * a.y;
          }
        return 0.5 * area;
      }

      /**
       * Clip @p subject by the half-plane left of the directed edge a -> b
       * (Sutherland-Hodgman). A vertex within 1e-10 of the edge's length
       * of its line counts as on it: it is kept and no intersection is
       * made next to it. Edges of the two facets that lie on one line
       * (the common sides of stacked blocks) would otherwise cut each
       * other at points that round-off places, harmless for the values
       * but with derivatives of the order of one over the round-off: the
       * tangent needs intersections only where the sides cross.
       */
      template <typename Number>
      void
      clip(const Polygon<Number>    &subject,
           const PlanePoint<Number> &a,
           const PlanePoint<Number> &b,
           Polygon<Number>          &result)
      {
        const double edge_x = value_of(b.x - a.x), edge_y = value_of(b.y - a.y);
        const double tolerance = 1e-10 * (edge_x * edge_x + edge_y * edge_y);
        // -1 outside, 0 on the line, 1 inside.
        const auto side = [&](const Number &d) {
          return value_of(d) > tolerance  ? 1 :
                 value_of(d) < -tolerance ? -1 :
                                            0;
        };
        result.n = 0;
        for (unsigned int i = 0; i < subject.n; ++i)
          {
            const PlanePoint<Number> &p  = subject.vertex[i];
            const PlanePoint<Number> &q  = subject.vertex[(i + 1) % subject.n];
            const Number              dp = cross(a, b, p);
            const Number              dq = cross(a, b, q);
            const int                 sp = side(dp), sq = side(dq);
            if (sp >= 0)
              result.vertex[result.n++] = p;
            if (sp * sq < 0)
              {
                const Number s            = dp / (dp - dq);
                result.vertex[result.n++] = {p.x + s * (q.x - p.x),
                                             p.y + s * (q.y - p.y)};
              }
          }
      }

      /**
       * One Newton step towards the (xi, eta) at which the bilinear map of
       * the plane points @p corner reaches @p q, from (@p xi_0, @p eta_0):
       * the residual F = x(xi_0, eta_0) - q in the numbers of the corners
       * (with their derivatives), the Jacobian in their values. Returns
       * |F| (of the values).
       */
      template <typename Number>
      double
      newton_step(const PlanePoint<Number> (&corner)[4],
                  const PlanePoint<Number> &q,
                  const double              xi_0,
                  const double              eta_0,
                  Number                   &xi,
                  Number                   &eta)
      {
        Number fx = -q.x, fy = -q.y;
        double j00 = 0., j01 = 0., j10 = 0., j11 = 0.;
        for (unsigned int a = 0; a < 4; ++a)
          {
            const double N =
              0.25 * (1. + corner_xi[a] * xi_0) * (1. + corner_eta[a] * eta_0);
            const double dxi =
              0.25 * corner_xi[a] * (1. + corner_eta[a] * eta_0);
            const double deta =
              0.25 * corner_eta[a] * (1. + corner_xi[a] * xi_0);
            fx += N * corner[a].x;
            fy += N * corner[a].y;
            j00 += dxi * value_of(corner[a].x);
            j01 += deta * value_of(corner[a].x);
            j10 += dxi * value_of(corner[a].y);
            j11 += deta * value_of(corner[a].y);
          }
        const double det = j00 * j11 - j01 * j10;
        xi               = xi_0 - (j11 * fx - j01 * fy) / det;
        eta              = eta_0 - (-j10 * fx + j00 * fy) / det;
        return std::abs(value_of(fx)) + std::abs(value_of(fy));
      }

      /**
       * The (xi, eta) at which the bilinear map of the plane points
       * @p corner reaches @p q (Newton's method from the centre).
       */
      void
      inverse_bilinear(const PlanePoint<double> (&corner)[4],
                       const PlanePoint<double> &q,
                       const double              tolerance,
                       double                   &xi,
                       double                   &eta)
      {
        xi  = 0.;
        eta = 0.;
        for (unsigned int iteration = 0; iteration < 30; ++iteration)
          {
            double next_xi, next_eta;
            if (newton_step(corner, q, xi, eta, next_xi, next_eta) < tolerance)
              return;
            xi  = next_xi;
            eta = next_eta;
          }
      }

      /**
       * The same with derivatives: Newton's method on the values, then one
       * step with the numbers from the converged point, xi = xi_0 - J^{-1}
       * F(xi_0): its value stays (F(xi_0) ~ 0) and its derivative is that
       * of the implicit function, -J^{-1} dF (a fifth of the work of
       * iterating with the numbers).
       */
      void
      inverse_bilinear(const PlanePoint<ADNumber> (&corner)[4],
                       const PlanePoint<ADNumber> &q,
                       const double                tolerance,
                       ADNumber                   &xi,
                       ADNumber                   &eta)
      {
        PlanePoint<double> corner_value[4];
        for (unsigned int a = 0; a < 4; ++a)
          corner_value[a] = {corner[a].x.val(), corner[a].y.val()};
        double xi_0, eta_0;
        inverse_bilinear(corner_value,
                         {q.x.val(), q.y.val()},
                         tolerance,
                         xi_0,
                         eta_0);
        newton_step(corner, q, xi_0, eta_0, xi, eta);
      }

      /** Dunavant's 7-point rule: barycentric points, weights (sum 1). */
      constexpr double rule_a1 = 0.059715871789770, rule_b1 = 0.470142064105115,
                       rule_w1 = 0.132394152788506;
      constexpr double rule_a2 = 0.797426985353087, rule_b2 = 0.101286507323456,
                       rule_w2          = 0.125939180544827;
      constexpr double rule_point[7][3] = {{1. / 3., 1. / 3., 1. / 3.},
                                           {rule_a1, rule_b1, rule_b1},
                                           {rule_b1, rule_a1, rule_b1},
                                           {rule_b1, rule_b1, rule_a1},
                                           {rule_a2, rule_b2, rule_b2},
                                           {rule_b2, rule_a2, rule_b2},
                                           {rule_b2, rule_b2, rule_a2}};
      constexpr double rule_weight[7] =
        {0.225, rule_w1, rule_w1, rule_w1, rule_w2, rule_w2, rule_w2};
    } // namespace



    template <typename Number>
    void
    facet_shape_values(const Number &xi, const Number &eta, Number (&N)[4])
    {
      for (unsigned int a = 0; a < 4; ++a)
        N[a] = 0.25 * (1. + corner_xi[a] * xi) * (1. + corner_eta[a] * eta);
    }



    template <typename Number>
    bool
    integrate_mortar_segment(const FacetCornersOf<Number> &slave,
                             const FacetCornersOf<Number> &master,
                             MortarSegmentOf<Number>      &segment,
                             const unsigned int            row)
    {
      const unsigned int first_row = row < 4 ? row : 0;
      const unsigned int end_row   = row < 4 ? row + 1 : 4;
      using Vector                 = Tensor<1, 3, Number>;
      // The auxiliary plane: through the slave corners' mean, normal to
      // the slave facet's diagonals' cross product.
      Vector centre;
      for (const Point<3, Number> &x : slave)
        centre += 0.25 * x;
      Vector normal =
        cross_product_3d(slave[2] - slave[0], slave[3] - slave[1]);
      const Number normal_norm = normal.norm();
      if (!(value_of(normal_norm) > 0.))
        return false;
      normal /= normal_norm;
      const Vector master_normal =
        cross_product_3d(master[2] - master[0], master[3] - master[1]);
      if (!(value_of(master_normal * normal) < 0.))
        return false;
      // In-plane axes: e1 along the first edge's projection.
      Vector e1 = slave[1] - slave[0];
      e1 -= (e1 * normal) * normal;
      e1 /= e1.norm();
      const Vector e2 = cross_product_3d(normal, e1);

      PlanePoint<Number> slave_corner[4], master_corner[4];
      for (unsigned int a = 0; a < 4; ++a)
        {
          slave_corner[a]  = {(slave[a] - centre) * e1,
                              (slave[a] - centre) * e2};
          master_corner[a] = {(master[a] - centre) * e1,
                              (master[a] - centre) * e2};
        }

      // The slave quadrilateral clipped by each edge of the master one,
      // which runs clockwise in the slave's plane (it faces the other way).
      Polygon<Number> overlap, scratch;
      overlap.n = 4;
      for (unsigned int a = 0; a < 4; ++a)
        overlap.vertex[a] = slave_corner[a];
      for (unsigned int k = 0; k < 4 && overlap.n > 0; ++k)
        {
          // Counter-clockwise master edge: from corner k+1 to corner k.
          clip(overlap, master_corner[(k + 1) % 4], master_corner[k], scratch);
          overlap = scratch;
        }
      if (overlap.n < 3)
        return false;
      // Area of the projected slave quadrilateral.
      const double slave_area = 0.5 * value_of(normal_norm);
      const Number area       = signed_area(overlap);
      if (!(value_of(area) > 1e-12 * slave_area))
        return false;

      for (unsigned int a = 0; a < 4; ++a)
        for (unsigned int b = 0; b < 4; ++b)
          segment.D[a][b] = segment.M[a][b] = 0.;
      segment.area           = area;
      const double tolerance = 1e-14 * std::sqrt(slave_area);
      // The convex overlap as a fan of triangles from its first vertex.
      const PlanePoint<Number> &apex = overlap.vertex[0];
      for (unsigned int i = 1; i + 1 < overlap.n; ++i)
        {
          const PlanePoint<Number> &p             = overlap.vertex[i];
          const PlanePoint<Number> &q             = overlap.vertex[i + 1];
          const Number              triangle_area = 0.5 * cross(apex, p, q);
          if (value_of(triangle_area) <= 0.)
            continue;
          for (unsigned int g = 0; g < 7; ++g)
            {
              const PlanePoint<Number> x = {rule_point[g][0] * apex.x +
                                              rule_point[g][1] * p.x +
                                              rule_point[g][2] * q.x,
                                            rule_point[g][0] * apex.y +
                                              rule_point[g][1] * p.y +
                                              rule_point[g][2] * q.y};
              Number                   xi, eta, N[4], N_master[4];
              inverse_bilinear(slave_corner, x, tolerance, xi, eta);
              facet_shape_values(xi, eta, N);
              inverse_bilinear(master_corner, x, tolerance, xi, eta);
              facet_shape_values(xi, eta, N_master);
              const Number w = triangle_area * rule_weight[g];
              for (unsigned int a = first_row; a < end_row; ++a)
                {
                  const Number w_a = w * N[a];
                  for (unsigned int b = 0; b < 4; ++b)
                    {
                      segment.D[a][b] += w_a * N[b];
                      segment.M[a][b] += w_a * N_master[b];
                    }
                }
            }
        }
      return true;
    }



    template void
    facet_shape_values(const double &, const double &, double (&)[4]);
    template bool
    integrate_mortar_segment(const FacetCornersOf<double> &,
                             const FacetCornersOf<double> &,
                             MortarSegmentOf<double> &,
                             const unsigned int);
    template bool
    integrate_mortar_segment(const FacetCornersOf<ADNumber> &,
                             const FacetCornersOf<ADNumber> &,
                             MortarSegmentOf<ADNumber> &,
                             const unsigned int);
  } // namespace contact
} // namespace rubberdyn
