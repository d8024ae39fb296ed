#include <deal.II/base/tensor.h>

#include <rubberdyn/contact/mortar_segment.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

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

      using mortar_segment_internal::BilinearMap;
      using mortar_segment_internal::PlanePoint;

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
                                     &b = p.vertex[i + 1 < p.n ? i + 1 : 0];
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
        // Each vertex's distance (times the edge's length) once, not once
        // as each of its two sides' ends.
        Number distance[16];
        int    side_of[16];
        for (unsigned int i = 0; i < subject.n; ++i)
          {
            distance[i] = cross(a, b, subject.vertex[i]);
            side_of[i]  = side(distance[i]);
          }
        result.n = 0;
        for (unsigned int i = 0; i < subject.n; ++i)
          {
            const unsigned int        j  = i + 1 < subject.n ? i + 1 : 0;
            const PlanePoint<Number> &p  = subject.vertex[i];
            const PlanePoint<Number> &q  = subject.vertex[j];
            const Number             &dp = distance[i];
            const Number             &dq = distance[j];
            const int                 sp = side_of[i], sq = side_of[j];
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
       * The bilinear map of the plane points @p corner: sum_a N_a x_a
       * regrouped by powers of xi and eta, and the inverse of its affine
       * part.
       */
      template <typename Number>
      void
      make_bilinear_map(const PlanePoint<Number> (&corner)[4],
                        BilinearMap<Number> &map)
      {
        for (unsigned int a = 0; a < 4; ++a)
          map.corner[a] = corner[a];
        const PlanePoint<Number> &x0 = corner[0], &x1 = corner[1],
                                 &x2 = corner[2], &x3 = corner[3];
        map.c[0]         = {0.25 * (x0.x + x1.x + x2.x + x3.x),
                            0.25 * (x0.y + x1.y + x2.y + x3.y)};
        map.c[1]         = {0.25 * (x1.x - x0.x + x2.x - x3.x),
                            0.25 * (x1.y - x0.y + x2.y - x3.y)};
        map.c[2]         = {0.25 * (x3.x - x0.x + x2.x - x1.x),
                            0.25 * (x3.y - x0.y + x2.y - x1.y)};
        map.c[3]         = {0.25 * (x0.x - x1.x + x2.x - x3.x),
                            0.25 * (x0.y - x1.y + x2.y - x3.y)};
        const double c1x = value_of(map.c[1].x), c1y = value_of(map.c[1].y),
                     c2x = value_of(map.c[2].x), c2y = value_of(map.c[2].y);
        const double det         = c1x * c2y - c2x * c1y;
        map.affine_inverse[0][0] = c2y / det;
        map.affine_inverse[0][1] = -c2x / det;
        map.affine_inverse[1][0] = -c1y / det;
        map.affine_inverse[1][1] = c1x / det;
      }

      /**
       * One Newton step towards the (xi, eta) at which @p map reaches
       * @p q, from (@p xi_0, @p eta_0): the residual F = x(xi_0, eta_0) - q
       * in the numbers of the map (with their derivatives), the Jacobian
       * J = [c_1 + c_3 eta_0, c_2 + c_3 xi_0] in its values.
       */
      template <typename Number>
      void
      newton_step(const BilinearMap<Number> &map,
                  const PlanePoint<Number>  &q,
                  const double               xi_0,
                  const double               eta_0,
                  Number                    &xi,
                  Number                    &eta)
      {
        const PlanePoint<Number>(&c)[4] = map.c;
        const double xi_eta             = xi_0 * eta_0;
        const Number fx =
          c[0].x - q.x + c[1].x * xi_0 + c[2].x * eta_0 + c[3].x * xi_eta;
        const Number fy =
          c[0].y - q.y + c[1].y * xi_0 + c[2].y * eta_0 + c[3].y * xi_eta;
        const double j00         = value_of(c[1].x) + value_of(c[3].x) * eta_0;
        const double j01         = value_of(c[2].x) + value_of(c[3].x) * xi_0;
        const double j10         = value_of(c[1].y) + value_of(c[3].y) * eta_0;
        const double j11         = value_of(c[2].y) + value_of(c[3].y) * xi_0;
        const double inverse_det = 1. / (j00 * j11 - j01 * j10);
        xi                       = xi_0 - (j11 * fx - j01 * fy) * inverse_det;
        eta                      = eta_0 - (-j10 * fx + j00 * fy) * inverse_det;
      }

      /** The number of points of the quadrature rule (below). */
      constexpr unsigned int n_rule_points = 7;

      /**
       * The (xi, eta) at which @p map reaches each of the points @p q (a
       * triangle's quadrature points): Newton's method from the centre,
       * whose first step lands on the solution of the affine part,
       * (xi, eta) = [c_1 c_2]^{-1} (q - c_0) (exact for a parallelogram),
       * taken here without evaluating the residual at the centre. Nor is
       * the residual evaluated to stop: the map is bilinear, so after a
       * Newton step (d_xi, d_eta) the residual is exactly F = c_3 d_xi d_eta
       * (F(xi + d) = F(xi) + J d + c_3 d_xi d_eta and J d = -F(xi)), and a
       * point stops where |F|_1 < @p tolerance (the same iterate as
       * evaluating F there, up to round-off; for a parallelogram no step at
       * all). The points are iterated side by side, each stopping on its
       * own: their independent divisions overlap in the processor's
       * pipeline, where one point at a time waits for each in turn.
       */
      void
      inverse_bilinear(const BilinearMap<double> &map,
                       const PlanePoint<double> (&q)[n_rule_points],
                       const double tolerance,
                       double (&xi)[n_rule_points],
                       double (&eta)[n_rule_points])
      {
        const double twist = std::abs(map.c[3].x) + std::abs(map.c[3].y);
        // The residual |F|_1 at each point's iterate.
        double residual[n_rule_points];
        for (unsigned int g = 0; g < n_rule_points; ++g)
          {
            const double rx = q[g].x - map.c[0].x, ry = q[g].y - map.c[0].y;
            xi[g] =
              map.affine_inverse[0][0] * rx + map.affine_inverse[0][1] * ry;
            eta[g] =
              map.affine_inverse[1][0] * rx + map.affine_inverse[1][1] * ry;
            residual[g] = twist * std::abs(xi[g] * eta[g]);
          }
        for (unsigned int iteration = 0; iteration < 30; ++iteration)
          {
            bool converged = true;
            for (unsigned int g = 0; g < n_rule_points; ++g)
              converged &= residual[g] < tolerance;
            if (converged)
              return;
            for (unsigned int g = 0; g < n_rule_points; ++g)
              {
                double next_xi, next_eta;
                newton_step(map, q[g], xi[g], eta[g], next_xi, next_eta);
                // (A point that has converged keeps its iterate.)
                const bool done = residual[g] < tolerance;
                residual[g] =
                  done ?
                    residual[g] :
                    twist * std::abs((next_xi - xi[g]) * (next_eta - eta[g]));
                xi[g]  = done ? xi[g] : next_xi;
                eta[g] = done ? eta[g] : next_eta;
              }
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
      inverse_bilinear(const BilinearMap<ADNumber> &map,
                       const PlanePoint<ADNumber> (&q)[n_rule_points],
                       const double tolerance,
                       ADNumber (&xi)[n_rule_points],
                       ADNumber (&eta)[n_rule_points])
      {
        BilinearMap<double> value;
        for (unsigned int a = 0; a < 4; ++a)
          value.c[a] = {map.c[a].x.val(), map.c[a].y.val()};
        for (unsigned int i = 0; i < 2; ++i)
          for (unsigned int j = 0; j < 2; ++j)
            value.affine_inverse[i][j] = map.affine_inverse[i][j];
        PlanePoint<double> q_value[n_rule_points];
        for (unsigned int g = 0; g < n_rule_points; ++g)
          q_value[g] = {q[g].x.val(), q[g].y.val()};
        double xi_0[n_rule_points], eta_0[n_rule_points];
        inverse_bilinear(value, q_value, tolerance, xi_0, eta_0);
        for (unsigned int g = 0; g < n_rule_points; ++g)
          newton_step(map, q[g], xi_0[g], eta_0[g], xi[g], eta[g]);
      }

      /**
       * The inverse Jacobian of a facet's projected bilinear @p map at
       * (@p xi, @p eta), J = [c_1 + c_3 eta, c_2 + c_3 xi]: with it the
       * gradient along the plane of f = sum_a N_a f_a is
       * (df/dxi, df/deta) J^{-1}.
       */
      template <typename Number>
      struct InverseJacobian
      {
        InverseJacobian(const BilinearMap<Number> &map,
                        const Number              &xi,
                        const Number              &eta)
        {
          const PlanePoint<Number>(&c)[4] = map.c;
          const Number j00                = c[1].x + c[3].x * eta;
          const Number j01                = c[2].x + c[3].x * xi;
          const Number j10                = c[1].y + c[3].y * eta;
          const Number j11                = c[2].y + c[3].y * xi;
          const Number inverse_det        = 1. / (j00 * j11 - j01 * j10);
          // (J^{-1})_{ij} = d xi_i / d P_j.
          inverse[0][0] = j11 * inverse_det;
          inverse[0][1] = -j01 * inverse_det;
          inverse[1][0] = -j10 * inverse_det;
          inverse[1][1] = j00 * inverse_det;
        }

        /** The gradient along the plane from (df/dxi, df/deta). */
        PlanePoint<Number>
        gradient(const Number &df_dxi, const Number &df_deta) const
        {
          return {df_dxi * inverse[0][0] + df_deta * inverse[1][0],
                  df_dxi * inverse[0][1] + df_deta * inverse[1][1]};
        }

        Number inverse[2][2];
      };

      /**
       * The master face's slope along the plane at a point of a segment,
       * matched at (@p xi, @p eta) on the master facet (its projected
       * bilinear @p map, its corners' heights @p height above the plane)
       * (MortarSegmentOf::slope).
       */
      template <typename Number>
      PlanePoint<Number>
      master_face_slope(const BilinearMap<Number> &map,
                        const Number (&height)[4],
                        const Number &xi,
                        const Number &eta)
      {
        Number dh_dxi = 0., dh_deta = 0.;
        for (unsigned int k = 0; k < 4; ++k)
          {
            // dN_k/dxi = xi_k (1 + eta_k eta) / 4, and so on.
            dh_dxi +=
              0.25 * corner_xi[k] * (1. + corner_eta[k] * eta) * height[k];
            dh_deta +=
              0.25 * corner_eta[k] * (1. + corner_xi[k] * xi) * height[k];
          }
        return InverseJacobian<Number>(map, xi, eta).gradient(dh_dxi, dh_deta);
      }

      /** Dunavant's 7-point rule: barycentric points, weights (sum 1). */
      constexpr double rule_a1 = 0.059715871789770, rule_b1 = 0.470142064105115,
                       rule_w1 = 0.132394152788506;
      constexpr double rule_a2 = 0.797426985353087, rule_b2 = 0.101286507323456,
                       rule_w2                      = 0.125939180544827;
      constexpr double rule_point[n_rule_points][3] = {
        {1. / 3., 1. / 3., 1. / 3.},
        {rule_a1, rule_b1, rule_b1},
        {rule_b1, rule_a1, rule_b1},
        {rule_b1, rule_b1, rule_a1},
        {rule_a2, rule_b2, rule_b2},
        {rule_b2, rule_a2, rule_b2},
        {rule_b2, rule_b2, rule_a2}};
      constexpr double rule_weight[n_rule_points] =
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
    MortarSlaveFacetOf<Number>::MortarSlaveFacetOf(
      const FacetCornersOf<Number> &slave)
    {
      using Vector = Tensor<1, 3, Number>;
      // The auxiliary plane: through the slave corners' mean, normal to
      // the slave facet's diagonals' cross product.
      for (const Point<3, Number> &x : slave)
        centre += 0.25 * x;
      normal      = cross_product_3d(slave[2] - slave[0], slave[3] - slave[1]);
      normal_norm = normal.norm();
      degenerate  = !(value_of(normal_norm) > 0.);
      top         = 0.;
      if (degenerate)
        return;
      normal /= normal_norm;
      // In-plane axes: e1 along the first edge's projection.
      e1 = slave[1] - slave[0];
      e1 -= (e1 * normal) * normal;
      e1 /= e1.norm();
      e2 = cross_product_3d(normal, e1);

      PlanePoint<Number> corner[4];
      for (unsigned int a = 0; a < 4; ++a)
        {
          const Vector r = slave[a] - centre;
          corner[a]      = {r * e1, r * e2};
        }
      make_bilinear_map(corner, map);
      for (unsigned int d = 0; d < 2; ++d)
        {
          lower[d] = std::numeric_limits<double>::max();
          upper[d] = -std::numeric_limits<double>::max();
        }
      for (const PlanePoint<Number> &x : corner)
        {
          lower[0] = std::min(lower[0], value_of(x.x));
          upper[0] = std::max(upper[0], value_of(x.x));
          lower[1] = std::min(lower[1], value_of(x.y));
          upper[1] = std::max(upper[1], value_of(x.y));
        }
      top = -std::numeric_limits<double>::max();
      for (const Point<3, Number> &x : slave)
        top = std::max(top, value_of((x - centre) * normal));
    }



    MasterFacetBounds
    master_facet_bounds(const FacetCornersOf<double> &master)
    {
      MasterFacetBounds bounds;
      // The same expression as may_overlap()'s facing test.
      bounds.diagonal_normal =
        cross_product_3d(master[2] - master[0], master[3] - master[1]);
      for (const Point<3> &x : master)
        bounds.centre += 0.25 * x;
      for (const Point<3> &x : master)
        bounds.radius = std::max(bounds.radius, x.distance(bounds.centre));
      return bounds;
    }



    template <typename Number>
    bool
    MortarSlaveFacetOf<Number>::may_overlap(
      const FacetCornersOf<Number> &master,
      PlanePoint<Number> (&master_corner)[4],
      const MasterFacetBounds *bounds) const
    {
      if (degenerate)
        return false;
      if (bounds != nullptr)
        {
          double facing = 0.;
          for (unsigned int d = 0; d < 3; ++d)
            facing += bounds->diagonal_normal[d] * value_of(normal[d]);
          if (!(facing < 0.))
            return false;
          // Each corner's coordinate along an in-plane axis lies within
          // the radius of the centre's: apart from the box (below) by more
          // than the margin that the box test takes for the widest master
          // facet in the ball, the box test rejects it too. (The radius
          // grown by 1e-10 of the lengths involved covers the round-off
          // of the two ways of computing the coordinates.)
          Tensor<1, 3> r;
          for (unsigned int d = 0; d < 3; ++d)
            r[d] = bounds->centre[d] - value_of(centre[d]);
          const double radius =
            bounds->radius + 1e-10 * (bounds->radius + r.norm());
          const Tensor<1, 3, Number> *const axis[2] = {&e1, &e2};
          for (unsigned int d = 0; d < 2; ++d)
            {
              double along = 0.;
              for (unsigned int k = 0; k < 3; ++k)
                along += r[k] * value_of((*axis[d])[k]);
              const double margin = 1e-8 * (upper[d] - lower[d] + 2. * radius);
              if (along + radius < lower[d] - margin ||
                  along - radius > upper[d] + margin)
                return false;
            }
        }
      else
        {
          const Tensor<1, 3, Number> master_normal =
            cross_product_3d(master[2] - master[0], master[3] - master[1]);
          if (!(value_of(master_normal * normal) < 0.))
            return false;
        }

      for (unsigned int k = 0; k < 4; ++k)
        {
          const Tensor<1, 3, Number> r = master[k] - centre;
          master_corner[k]             = {r * e1, r * e2};
        }
      double master_lower[2] = {value_of(master_corner[0].x),
                                value_of(master_corner[0].y)};
      double master_upper[2] = {master_lower[0], master_lower[1]};
      for (unsigned int k = 1; k < 4; ++k)
        {
          const double x  = value_of(master_corner[k].x),
                       y  = value_of(master_corner[k].y);
          master_lower[0] = std::min(master_lower[0], x);
          master_upper[0] = std::max(master_upper[0], x);
          master_lower[1] = std::min(master_lower[1], y);
          master_upper[1] = std::max(master_upper[1], y);
        }
      // Most candidates of a slave facet (those within the capture margin
      // of its bounding box) do not overlap it in the plane: those whose
      // bounding box is apart from the slave's by more than a margin far
      // above the clipping's tolerance (1e-10 of an edge's length) are
      // dropped before clipping; clipping would leave no area.
      for (unsigned int d = 0; d < 2; ++d)
        {
          const double margin =
            1e-8 * (upper[d] - lower[d] + master_upper[d] - master_lower[d]);
          if (master_upper[d] < lower[d] - margin ||
              master_lower[d] > upper[d] + margin)
            return false;
        }
      return true;
    }



    template <typename Number>
    bool
    MortarSlaveFacetOf<Number>::clearly_open(
      const FacetCornersOf<Number> &master,
      const double                  clearance,
      const MasterFacetBounds      *bounds) const
    {
      PlanePoint<Number> master_corner[4];
      if (!may_overlap(master, master_corner, bounds))
        return true;
      for (const Point<3, Number> &x : master)
        if (!(value_of((x - centre) * normal) > top + clearance))
          return false;
      return true;
    }



    template <typename Number>
    bool
    MortarSlaveFacetOf<Number>::integrate(const FacetCornersOf<Number> &master,
                                          MortarSegmentOf<Number>      &segment,
                                          const unsigned int            row,
                                          const MasterFacetBounds *bounds) const
    {
      PlanePoint<Number> master_corner[4];
      if (!may_overlap(master, master_corner, bounds))
        return false;

      // The slave quadrilateral clipped by each edge of the master one,
      // which runs clockwise in the slave's plane (it faces the other way).
      Polygon<Number>  polygons[2];
      Polygon<Number> *overlap = &polygons[0], *scratch = &polygons[1];
      overlap->n = 4;
      for (unsigned int a = 0; a < 4; ++a)
        overlap->vertex[a] = map.corner[a];
      for (unsigned int k = 0; k < 4 && overlap->n > 0; ++k)
        {
          // Counter-clockwise master edge: from corner k+1 to corner k.
          clip(*overlap,
               master_corner[(k + 1) % 4],
               master_corner[k],
               *scratch);
          std::swap(overlap, scratch);
        }
      if (overlap->n < 3)
        return false;
      // Area of the projected slave quadrilateral.
      const double slave_area = 0.5 * value_of(normal_norm);
      const Number area       = signed_area(*overlap);
      if (!(value_of(area) > 1e-12 * slave_area))
        return false;

      BilinearMap<Number> master_map;
      make_bilinear_map(master_corner, master_map);
      for (unsigned int a = 0; a < 4; ++a)
        for (unsigned int b = 0; b < 4; ++b)
          segment.D[a][b] = segment.M[a][b] = 0.;
      segment.area   = area;
      segment.normal = normal;
      // The master face's slope, summed over the fan's triangles times
      // their areas.
      PlanePoint<Number> slope_sum = {Number(0.), Number(0.)};
      Number             fan_area  = 0.;
      Number             master_height[4];
      for (unsigned int k = 0; k < 4; ++k)
        master_height[k] = (master[k] - centre) * normal;
      const double tolerance = 1e-14 * std::sqrt(slave_area);
      // D is symmetric: with all rows, its upper triangle only, mirrored
      // below at the end.
      const bool all_rows = row >= 4;
      // The convex overlap as a fan of triangles from its first vertex.
      const PlanePoint<Number> &apex = overlap->vertex[0];
      for (unsigned int i = 1; i + 1 < overlap->n; ++i)
        {
          const PlanePoint<Number> &p             = overlap->vertex[i];
          const PlanePoint<Number> &q             = overlap->vertex[i + 1];
          const Number              triangle_area = 0.5 * cross(apex, p, q);
          if (value_of(triangle_area) <= 0.)
            continue;
          PlanePoint<Number> x[n_rule_points];
          for (unsigned int g = 0; g < n_rule_points; ++g)
            x[g] = {rule_point[g][0] * apex.x + rule_point[g][1] * p.x +
                      rule_point[g][2] * q.x,
                    rule_point[g][0] * apex.y + rule_point[g][1] * p.y +
                      rule_point[g][2] * q.y};
          Number xi[n_rule_points], eta[n_rule_points];
          Number master_xi[n_rule_points], master_eta[n_rule_points];
          inverse_bilinear(map, x, tolerance, xi, eta);
          inverse_bilinear(master_map, x, tolerance, master_xi, master_eta);
          for (unsigned int g = 0; g < n_rule_points; ++g)
            {
              Number N[4], N_master[4];
              facet_shape_values(xi[g], eta[g], N);
              facet_shape_values(master_xi[g], master_eta[g], N_master);
              const Number w = triangle_area * rule_weight[g];
              // (Two loops with fixed bounds, which the compiler unrolls.)
              if (all_rows)
                for (unsigned int a = 0; a < 4; ++a)
                  {
                    const Number w_a = w * N[a];
                    for (unsigned int b = a; b < 4; ++b)
                      segment.D[a][b] += w_a * N[b];
                    for (unsigned int b = 0; b < 4; ++b)
                      segment.M[a][b] += w_a * N_master[b];
                  }
              else
                {
                  const Number w_a = w * N[row];
                  for (unsigned int b = 0; b < 4; ++b)
                    {
                      segment.D[row][b] += w_a * N[b];
                      segment.M[row][b] += w_a * N_master[b];
                    }
                }
            }
          // The master face's slope at the triangle's centroid (the rule's
          // first point).
          const PlanePoint<Number> grad_h = master_face_slope(master_map,
                                                              master_height,
                                                              master_xi[0],
                                                              master_eta[0]);
          slope_sum.x += triangle_area * grad_h.x;
          slope_sum.y += triangle_area * grad_h.y;
          fan_area += triangle_area;
        }
      if (all_rows)
        for (unsigned int a = 1; a < 4; ++a)
          for (unsigned int b = 0; b < a; ++b)
            segment.D[a][b] = segment.D[b][a];
      segment.slope = Number(slope_sum.x / fan_area) * e1 +
                      Number(slope_sum.y / fan_area) * e2;
      // Limited to max_mortar_slope: a master facet nearly edge-on to the
      // slave's plane (the wall of a hole under a sleeve's end) projects
      // to a sliver with an unbounded slope, and the traction along n - grad
      // h would make a tangential stiffness of eps A |grad h|^2 that no
      // stable step of the penalty bounds (bushing test 2: a sleeve end
      // went 4.7 mm into the brace and the pair made 476 J by 7.9 ms).
      const Number slope_norm = segment.slope.norm();
      if (value_of(slope_norm) > max_mortar_slope)
        segment.slope *= Number(max_mortar_slope / slope_norm);
      return true;
    }



    template <typename Number>
    bool
    integrate_mortar_segment(const FacetCornersOf<Number> &slave,
                             const FacetCornersOf<Number> &master,
                             MortarSegmentOf<Number>      &segment,
                             const unsigned int            row)
    {
      return MortarSlaveFacetOf<Number>(slave).integrate(master, segment, row);
    }



    template <typename Number>
    Number
    mortar_segment_weight(const FacetCornersOf<Number>  &slave,
                          const FacetCornersOf<Number>  &master,
                          const MortarSegmentOf<Number> &segment,
                          const double                   margin,
                          Tensor<1, 3, Number> (&weighted)[4],
                          Tensor<1, 3, Number> &weight_gradient)
    {
      for (unsigned int a = 0; a < 4; ++a)
        {
          weighted[a] = Tensor<1, 3, Number>();
          for (unsigned int b = 0; b < 4; ++b)
            weighted[a] +=
              segment.D[a][b] * slave[b] - segment.M[a][b] * master[b];
        }
      weight_gradient = Tensor<1, 3, Number>();
      Tensor<1, 3, Number> normal =
        cross_product_3d(slave[2] - slave[0], slave[3] - slave[1]);
      normal /= normal.norm();
      Tensor<1, 3, Number> total;
      for (unsigned int a = 0; a < 4; ++a)
        total += weighted[a];
      const Number mean_gap = Number(normal * total) / segment.area;
      // r = |gbar| / margin; the blend in t = 2 r - 1 from 0 to 1.
      const double sign = value_of(mean_gap) < 0. ? -1. : 1.;
      const Number r    = sign * mean_gap / margin;
      if (!(value_of(r) > 0.5))
        return Number(1.);
      if (!(value_of(r) < 1.))
        return Number(0.);
      const Number t = 2. * r - 1.;
      // w = 1 - (3 t^2 - 2 t^3), dw/dr = -12 t (1 - t).
      const Number slope = -12. * t * (1. - t) * sign / margin;
      weight_gradient    = Number(slope / segment.area) * normal;
      return 1. - t * t * (3. - 2. * t);
    }



    template void
    facet_shape_values(const double &, const double &, double (&)[4]);
    template class MortarSlaveFacetOf<double>;
    template class MortarSlaveFacetOf<ADNumber>;
    template bool
    integrate_mortar_segment(const FacetCornersOf<double> &,
                             const FacetCornersOf<double> &,
                             MortarSegmentOf<double> &,
                             const unsigned int);
    template double
    mortar_segment_weight(const FacetCornersOf<double> &,
                          const FacetCornersOf<double> &,
                          const MortarSegmentOf<double> &,
                          const double,
                          Tensor<1, 3, double> (&)[4],
                          Tensor<1, 3, double> &);
    template ADNumber
    mortar_segment_weight(const FacetCornersOf<ADNumber> &,
                          const FacetCornersOf<ADNumber> &,
                          const MortarSegmentOf<ADNumber> &,
                          const double,
                          Tensor<1, 3, ADNumber> (&)[4],
                          Tensor<1, 3, ADNumber> &);
    template bool
    integrate_mortar_segment(const FacetCornersOf<ADNumber> &,
                             const FacetCornersOf<ADNumber> &,
                             MortarSegmentOf<ADNumber> &,
                             const unsigned int);
  } // namespace contact
} // namespace rubberdyn
