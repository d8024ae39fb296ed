// The bonded tube of the azimuthal-shear verification (doc/verification/reference_solutions.md):
// inner radius a = 10, outer radius b = 20, length L = 10 mm, the axis
// along z, a full annulus (a rotation of the outer surface is one
// displacement function of x and y, no cut to close).
//
// Parameters (gmsh -setnumber): n = elements through the wall (default 4),
// n_around = elements around (default 8 n: the cells are at most 1.6 : 1 in
// the cross-section), n_z = elements along the axis (default 1: the exact
// solution does not vary along z, and with the axial displacement zero on
// both ends every node is on an end, a plane-strain model; more layers
// cost without adding accuracy). regenerate.sh writes tube_4, tube_8 and
// tube_16.
//
// Physical volume 1: rubber.
// Physical surfaces: 1 = inner r = a, 2 = outer r = b, 3 = end z = 0,
// 4 = end z = L.
//
// The hull is a polygon of n_around flat facets (the reader attaches no
// manifold): the cross-section's area is (n_around / 2) sin(2 pi /
// n_around) (b^2 - a^2), short of pi (b^2 - a^2) by (2 pi / n_around)^2 / 6
// to leading order (0.64 %, 0.16 %, 0.04 % for 32, 64, 128 around), the
// same order h^2 as the discretisation error of Q1 elements.
//
// Built by extrusion with Layers: the radial line from a point (nodes at
// exact fractions of b - a), four rotations by 90 degrees about the axis
// (nodes at exact fractions of the angle, each a rotation of the radial
// line's nodes), the last radial line merged with the first (Gmsh's
// default Geometry.AutoCoherence already merges the coinciding points;
// Coherence makes it explicit; without either the annulus has a seam,
// which the reader refuses), then a translation along z.
DefineConstant[ n = 4 ];
DefineConstant[ n_around = 8 * n ];
DefineConstant[ n_z = 1 ];
a = 10.; b = 20.; L = 10.;
eps = 1e-6 * b;

If (n_around % 4 != 0)
  Error("tube.geo: n_around must be a multiple of 4");
EndIf

Point(1) = {a, 0., 0.};
radial[] = Extrude {b - a, 0., 0.} { Point{1}; Layers{n}; };
line = radial[1];
faces[] = {};
For quarter In {0:3}
  sector[] = Extrude {{0., 0., 1.}, {0., 0., 0.}, Pi / 2.} {
    Curve{line}; Layers{n_around / 4}; Recombine;
  };
  faces[] += sector[1];
  line = sector[0];
EndFor
Coherence;

bodies[] = {};
For i In {0:3}
  body[] = Extrude {0., 0., L} { Surface{faces[i]}; Layers{n_z}; Recombine; };
  bodies[] += body[1];
EndFor

big = b + eps;
start[] = Surface In BoundingBox {-big, -big, -eps, big, big, eps};
finish[] = Surface In BoundingBox {-big, -big, L - eps, big, big, L + eps};
// The inner hull lies in the box |x|, |y| <= a; no surface of the outer
// hull or of the ends does (the ends reach r = b).
inner[] = Surface In BoundingBox {-a - eps, -a - eps, -eps,
                                  a + eps, a + eps, L + eps};
outer[] = Abs(CombinedBoundary{ Volume{bodies[]}; });
outer[] -= {start[], finish[], inner[]};

Physical Volume("rubber", 1) = {bodies[]};
Physical Surface("inner", 1) = {inner[]};
Physical Surface("outer", 2) = {outer[]};
Physical Surface("end z = 0", 3) = {start[]};
Physical Surface("end z = L", 4) = {finish[]};
