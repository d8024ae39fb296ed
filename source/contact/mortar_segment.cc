#include <deal.II/base/tensor.h>

#include <rubberdyn/contact/mortar_segment.h>

#include <cmath>

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
      struct PlanePoint
      {
        double x, y;
      };

      /** At most 8 vertices: a quadrilateral clipped by another. */
      struct Polygon
      {
        PlanePoint   vertex[16];
        unsigned int n = 0;
      };

      double
      cross(const PlanePoint &a, const PlanePoint &b, const PlanePoint &c)
      {
        return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
      }

      double
      signed_area(const Polygon &p)
      {
        double area = 0.;
        for (unsigned int i = 0; i < p.n; ++i)
          {
            const PlanePoint &a = p.vertex[i], &b = p.vertex[(i + 1) % p.n];
            area += a.x * b.y - b.x * a.y;
          }
        return 0.5 * area;
      }

      /**
       * Clip @p subject by the half-plane left of the directed edge a -> b
       * (Sutherland-Hodgman).
       */
      void
      clip(const Polygon    &subject,
           const PlanePoint &a,
           const PlanePoint &b,
           Polygon          &result)
      {
        result.n = 0;
        for (unsigned int i = 0; i < subject.n; ++i)
          {
            const PlanePoint &p  = subject.vertex[i];
            const PlanePoint &q  = subject.vertex[(i + 1) % subject.n];
            const double      dp = cross(a, b, p);
            const double      dq = cross(a, b, q);
            if (dp >= 0.)
              result.vertex[result.n++] = p;
            if ((dp >= 0.) != (dq >= 0.))
              {
                const double s            = dp / (dp - dq);
                result.vertex[result.n++] = {p.x + s * (q.x - p.x),
                                             p.y + s * (q.y - p.y)};
              }
          }
      }

      /**
       * The (xi, eta) at which the bilinear map of the plane points
       * @p corner reaches @p q (Newton's method from the centre).
       */
      void
      inverse_bilinear(const PlanePoint (&corner)[4],
                       const PlanePoint &q,
                       const double      tolerance,
                       double           &xi,
                       double           &eta)
      {
        xi  = 0.;
        eta = 0.;
        for (unsigned int iteration = 0; iteration < 30; ++iteration)
          {
            double fx = -q.x, fy = -q.y, j00 = 0., j01 = 0., j10 = 0., j11 = 0.;
            for (unsigned int a = 0; a < 4; ++a)
              {
                const double N =
                  0.25 * (1. + corner_xi[a] * xi) * (1. + corner_eta[a] * eta);
                const double dxi =
                  0.25 * corner_xi[a] * (1. + corner_eta[a] * eta);
                const double deta =
                  0.25 * corner_eta[a] * (1. + corner_xi[a] * xi);
                fx += N * corner[a].x;
                fy += N * corner[a].y;
                j00 += dxi * corner[a].x;
                j01 += deta * corner[a].x;
                j10 += dxi * corner[a].y;
                j11 += deta * corner[a].y;
              }
            if (std::abs(fx) + std::abs(fy) < tolerance)
              return;
            const double det = j00 * j11 - j01 * j10;
            xi -= (j11 * fx - j01 * fy) / det;
            eta -= (-j10 * fx + j00 * fy) / det;
          }
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



    void
    facet_shape_values(const double xi, const double eta, double (&N)[4])
    {
      for (unsigned int a = 0; a < 4; ++a)
        N[a] = 0.25 * (1. + corner_xi[a] * xi) * (1. + corner_eta[a] * eta);
    }



    bool
    integrate_mortar_segment(const FacetCorners &slave,
                             const FacetCorners &master,
                             MortarSegment      &segment)
    {
      // The auxiliary plane: through the slave corners' mean, normal to
      // the slave facet's diagonals' cross product.
      Point<3> centre;
      for (const Point<3> &x : slave)
        centre += 0.25 * x;
      Tensor<1, 3> normal =
        cross_product_3d(slave[2] - slave[0], slave[3] - slave[1]);
      const double normal_norm = normal.norm();
      if (!(normal_norm > 0.))
        return false;
      normal /= normal_norm;
      const Tensor<1, 3> master_normal =
        cross_product_3d(master[2] - master[0], master[3] - master[1]);
      if (!(master_normal * normal < 0.))
        return false;
      // In-plane axes: e1 along the first edge's projection.
      Tensor<1, 3> e1 = slave[1] - slave[0];
      e1 -= (e1 * normal) * normal;
      e1 /= e1.norm();
      const Tensor<1, 3> e2 = cross_product_3d(normal, e1);

      PlanePoint slave_corner[4], master_corner[4];
      for (unsigned int a = 0; a < 4; ++a)
        {
          slave_corner[a]  = {(slave[a] - centre) * e1,
                              (slave[a] - centre) * e2};
          master_corner[a] = {(master[a] - centre) * e1,
                              (master[a] - centre) * e2};
        }

      // The slave quadrilateral clipped by each edge of the master one,
      // which runs clockwise in the slave's plane (it faces the other way).
      Polygon overlap, scratch;
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
      const double slave_area =
        0.5 * normal_norm; // area of the projected slave quadrilateral
      const double area = signed_area(overlap);
      if (!(area > 1e-12 * slave_area))
        return false;

      for (unsigned int a = 0; a < 4; ++a)
        for (unsigned int b = 0; b < 4; ++b)
          segment.D[a][b] = segment.M[a][b] = 0.;
      segment.area           = area;
      const double tolerance = 1e-14 * std::sqrt(slave_area);
      // The convex overlap as a fan of triangles from its first vertex.
      const PlanePoint &apex = overlap.vertex[0];
      for (unsigned int i = 1; i + 1 < overlap.n; ++i)
        {
          const PlanePoint &p             = overlap.vertex[i];
          const PlanePoint &q             = overlap.vertex[i + 1];
          const double      triangle_area = 0.5 * cross(apex, p, q);
          if (triangle_area <= 0.)
            continue;
          for (unsigned int g = 0; g < 7; ++g)
            {
              const PlanePoint x = {rule_point[g][0] * apex.x +
                                      rule_point[g][1] * p.x +
                                      rule_point[g][2] * q.x,
                                    rule_point[g][0] * apex.y +
                                      rule_point[g][1] * p.y +
                                      rule_point[g][2] * q.y};
              double           xi, eta, N[4], N_master[4];
              inverse_bilinear(slave_corner, x, tolerance, xi, eta);
              facet_shape_values(xi, eta, N);
              inverse_bilinear(master_corner, x, tolerance, xi, eta);
              facet_shape_values(xi, eta, N_master);
              const double w = triangle_area * rule_weight[g];
              for (unsigned int a = 0; a < 4; ++a)
                for (unsigned int b = 0; b < 4; ++b)
                  {
                    segment.D[a][b] += w * N[a] * N[b];
                    segment.M[a][b] += w * N[a] * N_master[b];
                  }
            }
        }
      return true;
    }
  } // namespace contact
} // namespace rubberdyn
