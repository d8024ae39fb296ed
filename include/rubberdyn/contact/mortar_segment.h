#ifndef rubberdyn_contact_mortar_segment_h
#define rubberdyn_contact_mortar_segment_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <array>

namespace rubberdyn
{
  namespace contact
  {
    using namespace dealii;

    /**
     * The four corners of a bilinear contact facet (a hexahedron's boundary
     * face) in cyclic order, counter-clockwise seen from outside the body:
     * the facet's outward normal is along (x_2 - x_0) x (x_3 - x_1). Corner
     * a sits at (xi, eta) = (-1, -1), (1, -1), (1, 1), (-1, 1) and has the
     * shape function N_a = (1 + xi_a xi)(1 + eta_a eta)/4.
     */
    template <typename Number>
    using FacetCornersOf = std::array<Point<3, Number>, 4>;

    /** The corners of a facet in double precision. */
    using FacetCorners = FacetCornersOf<double>;

    /**
     * The mortar integrals of one slave facet against one master facet over
     * their overlap (the mortar segment):
     * @f[ D_{ab} = \int N_a N_b \,dA, \qquad
     *     M_{ak} = \int N_a \hat N_k \,dA, @f]
     * with N the slave and $\hat N$ the master facet's shape functions.
     * Their sum over segments gives the weighted gap vector of a slave node,
     * $\tilde{\mathbf g}_a = \sum_b D_{ab}\mathbf x_b - \sum_k M_{ak}\hat{
     * \mathbf x}_k = \int N_a (\mathbf x - \hat{\mathbf x})\,dA$ (Puso &
     * Laursen, Comput. Methods Appl. Mech. Engrg. 193 (2004) 601, eq. 17).
     */
    template <typename Number>
    struct MortarSegmentOf
    {
      Number D[4][4];
      Number M[4][4];
      /** Area of the overlap (mm^2): the sum of all D_ab (or of all M_ak). */
      Number area;
      /**
       * The master face's mean slope over the overlap (dimensionless, a
       * vector along the auxiliary plane, whose unit normal is @p normal):
       * with h the master face's height above the plane at the master
       * point matched to each slave point, the area-weighted mean of its
       * gradient along the plane, grad h at each fan triangle's centroid
       * (exact for a flat master facet, whose slope is one constant),
       * limited in length to max_mortar_slope. When
       * the slave slides along a master face that is not parallel to it,
       * the gap G between matched points changes by the slope: the
       * weighted normal gap's variation is (doc/theory.md, section 15.2)
       * @f[ \delta \int N_a G\,dA = \sum_b D_{ab}(\mathbf n - \nabla h)
       *     \cdot\delta\mathbf x_b - \sum_k M_{ak}(\mathbf n - \nabla h)
       *     \cdot\delta\hat{\mathbf x}_k @f]
       * at motions that keep the plane's normal and the slave facet's
       * shape (terms of the order of the gap over the facet's size, and
       * the turning plane's, left out).
       */
      Tensor<1, 3, Number> slope;
      /** The auxiliary plane's unit normal (the slave facet's). */
      Tensor<1, 3, Number> normal;
    };

    /**
     * The largest master face slope the mortar traction follows
     * (MortarSegmentOf::slope; tan 26.6 degrees): steeper mean slopes are
     * scaled down to it, which keeps the traction's tangential stiffness
     * within a quarter of its normal one.
     */
    constexpr double max_mortar_slope = 0.5;

    /** The mortar integrals in double precision. */
    using MortarSegment = MortarSegmentOf<double>;

    /**
     * Integrate the mortar segment of @p slave and @p master (Puso &
     * Laursen 2004, sect. 3.2): both facets are projected along the slave
     * facet's central normal onto its auxiliary plane (through the mean of
     * its corners); the projected master quadrilateral clips the slave one
     * (Sutherland-Hodgman, both convex); the overlap polygon is cut into
     * a fan of triangles from its first vertex, each integrated by the
     * 7-point degree-5 rule (Dunavant 1985) at points mapped back to each
     * facet's (xi, eta) by Newton's method on the projected bilinear map,
     * started from the inverse of its affine part (exact for a
     * parallelogram: no Newton step there). Exact for flat parallelogram
     * facets, whose products N_a N_b are quartic in the plane's
     * coordinates.
     *
     * The master facet must face the slave one (its outward normal
     * against the slave's); a master facet seen from behind, or no overlap,
     * gives false and leaves @p segment undefined.
     *
     * With the integrals, the master face's mean slope over the overlap
     * (MortarSegmentOf::slope, from the master's inverse map's Jacobian at
     * each fan triangle's centroid).
     *
     * With @p row < 4 only that row of D and M is integrated (the others
     * are zero): all a slave node's forces need, a quarter of the work.
     *
     * Instantiated for double and for Sacado's forward-mode number
     * Sacado::Fad::DFad<double> (the contact tangent differentiates the
     * integrals with respect to the corners: the clipping and the inverse
     * maps are differentiated along with their values; the decisions,
     * which vertices the overlap has, are taken on the values).
     */
    template <typename Number>
    bool
    integrate_mortar_segment(const FacetCornersOf<Number> &slave,
                             const FacetCornersOf<Number> &master,
                             MortarSegmentOf<Number>      &segment,
                             const unsigned int            row = 4);

    /**
     * The weight in [0, 1] with which a segment enters its slave nodes'
     * covered areas, weighted gaps and forces, from its mean gap along the
     * slave facet's central normal, gbar = n . sum_a weighted_a / area (mm;
     * the segment's weighted gap vectors @p weighted[a] = sum_b D_ab x_b -
     * M_ab x^_b (mm^3), with x_b the @p slave and x^_b the @p master
     * corners, are computed here and returned: the forces and the tangent
     * use them): 1 while |gbar| is at
     * most half the capture @p margin (mm), 0 from the margin on (farther
     * apart is not the contact's: the back of a thin part, a fold, a face
     * tilted away from its partner), and a C1 cubic between. A segment that
     * left at the margin with weight 1 would change its nodes' mean gaps by
     * a jump: where a node's segment sees the partner nearly 3 mm away while
     * its others press into it (the nut's edge tilted over a dished washer),
     * the node's gap jumped from -0.05 to -0.4 mm and its spring's energy
     * by 23 J within one step, without work (bushing test 4, `nut_washer`).
     *
     * Also gives @p weight_gradient = (dw/dgbar) n / area (1/mm^3): with
     * the derivatives of D, M, n and the area left out, as in the pair's
     * forces, dw/dx_b = weight_gradient sum_a D_ab at a slave corner and
     * -weight_gradient sum_a M_ab at a master corner; zero while the weight
     * is 1. Instantiated for double and Sacado::Fad::DFad<double> (the
     * contact tangent).
     */
    template <typename Number>
    Number
    mortar_segment_weight(const FacetCornersOf<Number>  &slave,
                          const FacetCornersOf<Number>  &master,
                          const MortarSegmentOf<Number> &segment,
                          const double                   margin,
                          Tensor<1, 3, Number> (&weighted)[4],
                          Tensor<1, 3, Number> &weight_gradient);

    namespace mortar_segment_internal
    {
      /** A point of a slave facet's auxiliary plane in its coordinates. */
      template <typename Number>
      struct PlanePoint
      {
        Number x, y;
      };

      /**
       * A facet's bilinear map projected onto the auxiliary plane, written
       * as x(xi, eta) = c_0 + c_1 xi + c_2 eta + c_3 xi eta (c_3 = 0 for a
       * parallelogram), with the inverse of its affine part [c_1 c_2] (of
       * the values): what the inverse map needs at every quadrature point,
       * computed once per facet.
       */
      template <typename Number>
      struct BilinearMap
      {
        /** The corners (FacetCorners' order). */
        PlanePoint<Number> corner[4];
        /** c_0, c_1, c_2, c_3. */
        PlanePoint<Number> c[4];
        /** [c_1 c_2]^{-1}. */
        double affine_inverse[2][2];
      };
    } // namespace mortar_segment_internal

    /**
     * What every slave facet's overlap test asks of a master facet at the
     * current positions, computed once per evaluation for all its slave
     * facets (MortarContactPair) instead of once per candidate pair: the
     * cross product of its diagonals (the facing test) and a ball about
     * its corners' mean that holds them (a first in-plane test without
     * projecting the corners). Tests with it decide as those without, to
     * the last bit: it only rejects earlier.
     */
    struct MasterFacetBounds
    {
      /** The diagonals' cross product (not normalised). */
      Tensor<1, 3> diagonal_normal;
      /** The corners' mean (mm). */
      Point<3> centre;
      /** The corners' largest distance from it (mm). */
      double radius = 0.;
    };

    /** The bounds of @p master at its corners' positions. */
    MasterFacetBounds
    master_facet_bounds(const FacetCornersOf<double> &master);

    /**
     * A slave facet prepared for integrate_mortar_segment() against each
     * of its candidate master facets: its auxiliary plane, its projected
     * corners and bilinear map, computed once instead of once per
     * candidate. integrate() gives what integrate_mortar_segment() gives,
     * to the last bit.
     */
    template <typename Number>
    class MortarSlaveFacetOf
    {
    public:
      explicit MortarSlaveFacetOf(const FacetCornersOf<Number> &slave);

      /** integrate_mortar_segment(slave, @p master, @p segment, @p row);
       * @p bounds, if given, are @p master's (values only). */
      bool
      integrate(const FacetCornersOf<Number> &master,
                MortarSegmentOf<Number>      &segment,
                const unsigned int            row    = 4,
                const MasterFacetBounds      *bounds = nullptr) const;

      /**
       * Whether @p master adds nothing but open gap to this facet's nodes:
       * integrate() would find no segment with it (it faces the same way,
       * or it is apart in the plane: the same cheap tests), or its lowest
       * corner along the normal lies above this facet's highest corner by
       * more than @p clearance (mm). Bilinear facets lie between their
       * corners' heights and the segment's points are matched along the
       * normal, so every matched master point then lies above its slave
       * point: the segment adds a positive multiple of the normal to the
       * weighted gap vectors.
       */
      bool
      clearly_open(const FacetCornersOf<Number> &master,
                   const double                  clearance,
                   const MasterFacetBounds      *bounds = nullptr) const;

      /**
       * The unit normal of the auxiliary plane (the diagonals' cross
       * product, normalised; zero for a facet without area).
       */
      const Tensor<1, 3, Number> &
      unit_normal() const
      {
        return normal;
      }

    private:
      /**
       * The cheap tests of integrate(): whether @p master faces this facet
       * and its corners in the plane (@p master_corner, written) have a
       * bounding box that meets this facet's. With @p bounds (@p master's)
       * the facing test takes their normal, and a master facet whose ball
       * lies apart from the box in the plane is rejected before its
       * corners are projected.
       */
      bool
      may_overlap(
        const FacetCornersOf<Number> &master,
        mortar_segment_internal::PlanePoint<Number> (&master_corner)[4],
        const MasterFacetBounds *bounds = nullptr) const;

      /** True for a facet without area (no segment then). */
      bool degenerate;
      /** The auxiliary plane: centre, unit normal and in-plane axes. */
      Tensor<1, 3, Number> centre, normal, e1, e2;
      /** The length of the diagonals' cross product: twice the area. */
      Number normal_norm;
      /** The facet in the plane. */
      mortar_segment_internal::BilinearMap<Number> map;
      /** Its bounding box in the plane (values). */
      double lower[2], upper[2];
      /** The highest corner's height above the plane (value, mm). */
      double top;
    };

    /** The slave facet prepared in double precision. */
    using MortarSlaveFacet = MortarSlaveFacetOf<double>;

    /** The facet's shape functions at (xi, eta) (FacetCorners). */
    template <typename Number>
    void
    facet_shape_values(const Number &xi, const Number &eta, Number (&N)[4]);
  } // namespace contact
} // namespace rubberdyn

#endif
