#ifndef rubberdyn_geometry_standing_cylinder_h
#define rubberdyn_geometry_standing_cylinder_h

namespace dealii
{
  template <int dim, int spacedim>
  class Triangulation;
}

namespace rubberdyn
{
  /**
   * Meshes of the studies' parts, with their boundary ids, independent of
   * any solver (so that peer codes can be fed the very same mesh).
   */
  namespace geometry
  {
    /** Boundary ids of make_standing_cylinder(). */
    namespace cylinder_boundary
    {
      constexpr unsigned int hull   = 0;
      constexpr unsigned int bottom = 1;
      constexpr unsigned int top    = 2;
    } // namespace cylinder_boundary

    /**
     * A solid cylinder of hexahedra standing on the plane z = 0 with its
     * axis along z: deal.II's subdivided_cylinder (5 cells per
     * cross-section, 2 along the axis), a cylindrical manifold on the hull,
     * refined @p refinement times globally. Boundary ids:
     * cylinder_boundary::hull, ::bottom (z = 0), ::top (z = height);
     * material id 0.
     *
     * @p triangulation may be serial or parallel::distributed; it must be
     * empty.
     *
     * @param diameter Cylinder diameter (mm).
     * @param height Cylinder height (mm).
     */
    void
    make_standing_cylinder(dealii::Triangulation<3, 3> &triangulation,
                           const double                 diameter,
                           const double                 height,
                           const unsigned int           refinement);
  } // namespace geometry
} // namespace rubberdyn

#endif
