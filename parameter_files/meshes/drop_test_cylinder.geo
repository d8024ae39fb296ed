// The rubber cylinder of the drop test (diameter 25 mm, height 24 mm,
// standing on z = 0 with its axis along z): the same 80 hexahedra as the
// built-in geometry::make_standing_cylinder(tria, 25., 24., 1), i.e.
// deal.II's GridGenerator::subdivided_cylinder (a cross-section of five
// blocks, a centre square and four curved blocks, two blocks along the
// axis), refined once with a CylindricalManifold on the hull. The test
// tests/io/gmsh_mesh.cc checks that every cell has the same eight vertices
// as a cell of the built-in mesh.
//
// Physical volume 1: rubber.
// Physical surfaces: 1 = hull, 2 = bottom (z = 0), 3 = top (z = 24). (The
// built-in mesh has the boundary ids 0, 1, 2; a Gmsh file cannot use 0.)
//
// How the nodes land where deal.II puts them. Refinement puts a new node
// at the middle of each edge (on the circle for the hull's arcs), at the
// transfinite (Coons) centre of each face, at the transfinite centre of
// each cell. Gmsh's transfinite surfaces place their interior nodes by the
// same Coons formula, but Gmsh's 1D mesher places the interior nodes of a
// curve by integrating its arc length numerically: a 90 degree arc of
// radius 12.5 with 3 nodes gets its middle node 3e-8 mm off the circle's
// middle and a 24 mm line with 5 nodes gets them 5e-11 mm off (Gmsh 4.8.4,
// whatever Mesh.LcIntegrationPrecision). So no curve here has an interior
// node: every curve ends at the middle of the corresponding deal.II edge
// (geometry points at the midpoints, the arcs split at 0, 90, 180 and 270
// degrees) and is one element long. The five cross-section surfaces are
// transfinite with 3 x 3 nodes (corners given explicitly: each side is two
// curves); their centres are Gmsh's Coons interpolation. The volume is
// extruded from them in 4 layers (Gmsh places extruded nodes at exact
// fractions of the height, where deal.II's midpoints are), instead of
// transfinite volumes, whose vertical edges would need 1D meshing. The
// largest vertex distance to the built-in mesh is printed by the test.
r = 12.5;
h = 24.;
d = r / Sqrt(2.);        // the outer corners (+-d, +-d), as deal.II
a = d / (1. + Sqrt(2.)); // the centre square's corners (+-a, +-a)
m = (a + d) / 2.;        // the middle of a radial edge

Point(1) = {0., 0., 0.};  // the axis
// The centre square, counter-clockwise from (-a, -a), and the middles of
// its sides.
Point(2) = {-a, -a, 0.};  Point(3) = {0., -a, 0.};
Point(4) = {a, -a, 0.};   Point(5) = {a, 0., 0.};
Point(6) = {a, a, 0.};    Point(7) = {0., a, 0.};
Point(8) = {-a, a, 0.};   Point(9) = {-a, 0., 0.};
// The hull's circle, counter-clockwise from (-d, -d), with the middles of
// its four arcs.
Point(10) = {-d, -d, 0.}; Point(11) = {0., -r, 0.};
Point(12) = {d, -d, 0.};  Point(13) = {r, 0., 0.};
Point(14) = {d, d, 0.};   Point(15) = {0., r, 0.};
Point(16) = {-d, d, 0.};  Point(17) = {-r, 0., 0.};
// The middles of the four radial edges.
Point(18) = {-m, -m, 0.}; Point(19) = {m, -m, 0.};
Point(20) = {m, m, 0.};   Point(21) = {-m, m, 0.};

// The centre square's sides, two lines each: 1-8.
For i In {0:7}
  Line(1 + i) = {2 + i, 2 + (i + 1) % 8};
EndFor
// The circle, two arcs per block: 9-16.
For i In {0:7}
  Circle(9 + i) = {10 + i, 1, 10 + (i + 1) % 8};
EndFor
// The radial edges, inner half 17-20 and outer half 21-24, at the corners
// (-,-), (+,-), (+,+), (-,+).
For k In {0:3}
  Line(17 + k) = {2 + 2 * k, 18 + k};
  Line(21 + k) = {18 + k, 10 + 2 * k};
EndFor
Transfinite Curve {1:24} = 2;

// The five blocks of the cross-section, each loop counter-clockwise seen
// from +z (so that the extruded hexahedra are positively oriented).
Curve Loop(1) = {1:8};
Plane Surface(1) = {1};
Transfinite Surface {1} = {2, 4, 6, 8};
// The curved block of corner k and k + 1: inner corner k, outer corner k,
// outer corner k + 1, inner corner k + 1.
For k In {0:3}
  Curve Loop(2 + k) = {17 + k, 21 + k, 9 + 2 * k, 10 + 2 * k,
                       -(21 + (k + 1) % 4), -(17 + (k + 1) % 4),
                       -(2 + 2 * k), -(1 + 2 * k)};
  Plane Surface(2 + k) = {2 + k};
  Transfinite Surface {2 + k} = {2 + 2 * k, 10 + 2 * k,
                                 10 + (2 * k + 2) % 8, 2 + (2 * k + 2) % 8};
EndFor
Recombine Surface {1:5};

// Extrude each block; Extrude returns the top surface, the volume and the
// lateral surfaces in the order of the block's curve loop, so the hull
// surfaces of a curved block are its entries 4 and 5 (its two arcs).
volumes[] = {};
tops[] = {};
hull[] = {};
For s In {1:5}
  out[] = Extrude {0., 0., h} { Surface{s}; Layers{4}; Recombine; };
  tops[] += out[0];
  volumes[] += out[1];
  If (s > 1)
    hull[] += {out[4], out[5]};
  EndIf
EndFor

Physical Volume("rubber", 1) = {volumes[]};
Physical Surface("hull", 1) = {hull[]};
Physical Surface("bottom", 2) = {1:5};
Physical Surface("top", 3) = {tops[]};
