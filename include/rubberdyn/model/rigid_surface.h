#ifndef rubberdyn_model_rigid_surface_h
#define rubberdyn_model_rigid_surface_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

namespace rubberdyn
{
  namespace model
  {
    using namespace dealii;

    /**
     * A rigid surface that moves with a rigid body (translation only):
     * a plane, or a circular cylinder (a rigid pin with the solid outside, or
     * a rigid tube/hole with the solid inside), with a Coulomb friction
     * coefficient towards the solid.
     */
    struct RigidSurface
    {
      enum class Shape
      {
        /** Points with normal . (x - point) >= 0 are outside the body. */
        plane,
        /** Points farther than radius from the axis are outside the body. */
        cylinder_solid_outside,
        /** Points closer than radius to the axis are outside the body. */
        cylinder_solid_inside
      };
      /**
       * Plane: a point of it; cylinder: a point of its axis (mm, reference
       * configuration).
       */
      Point<3> point;
      /**
       * Plane: unit normal pointing away from the rigid body, into the
       * solid; cylinder: unit axis direction.
       */
      Tensor<1, 3> normal;
      /** Coulomb friction coefficient (-), 0: frictionless. */
      double friction_coefficient = 0.;
      /** Cylinder radius (mm); unused for a plane. */
      double radius = 0.;
      Shape  shape = Shape::plane;
    };

    /**
     * Where a rigid surface is: its body's displacement, and, for a
     * rotating body, its rotation about a centre. A point given in the
     * reference configuration, X, is now at centre + displacement +
     * rotation (X - centre).
     */
    struct SurfacePose
    {
      /** Displacement of the body (mm). */
      Tensor<1, 3> displacement;
      /** Rotation of the body (orthogonal; used if rotated). */
      Tensor<2, 3> rotation;
      /** The point the body rotates about, reference configuration (mm). */
      Point<3> centre;
      /** Whether the body has a rotation (false: a translation only). */
      bool rotated = false;
    };

  } // namespace model
} // namespace rubberdyn

#endif
