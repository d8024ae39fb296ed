#ifndef rubberdyn_contact_mortar_segment_h
#define rubberdyn_contact_mortar_segment_h

#include <deal.II/base/point.h>

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
    using FacetCorners = std::array<Point<3>, 4>;

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
    struct MortarSegment
    {
      double D[4][4];
      double M[4][4];
      /** Area of the overlap (mm^2): the sum of all D_ab (or of all M_ak). */
      double area;
    };

    /**
     * Integrate the mortar segment of @p slave and @p master (Puso &
     * Laursen 2004, sect. 3.2): both facets are projected along the slave
     * facet's central normal onto its auxiliary plane (through the mean of
     * its corners); the projected master quadrilateral clips the slave one
     * (Sutherland-Hodgman, both convex); the overlap polygon is cut into
     * a fan of triangles from its first vertex, each integrated by the
     * 7-point degree-5
     * rule (Dunavant 1985) at points mapped back to each facet's (xi, eta)
     * by Newton's method on the projected bilinear map. Exact for flat
     * parallelogram facets, whose products N_a N_b are quartic in the
     * plane's coordinates.
     *
     * The master facet must face the slave one (its outward normal
     * against the slave's); a master facet seen from behind, or no overlap,
     * gives false and leaves @p segment undefined.
     */
    bool
    integrate_mortar_segment(const FacetCorners &slave,
                             const FacetCorners &master,
                             MortarSegment      &segment);

    /** The facet's shape functions at (xi, eta) (FacetCorners). */
    void
    facet_shape_values(const double xi, const double eta, double (&N)[4]);
  } // namespace contact
} // namespace rubberdyn

#endif
