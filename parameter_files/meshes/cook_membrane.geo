// Cook's membrane (doc/verification/reference_solutions.md): the trapezoid with the corners
// (0, 0), (48, 44), (48, 60), (0, 44) mm, one element thick in z with unit
// thickness (z from 0 to 1), clamped on x = 0 and loaded by a shear on
// x = 48.
//
// Parameter (gmsh -setnumber): n = elements on each side (default 16);
// regenerate.sh writes cook_membrane_2 ... cook_membrane_64 (powers of two:
// each mesh is the previous one refined in the plane, so that the tip
// displacement converges monotonically in the usual way).
//
// Physical volume 1: the membrane.
// Physical surfaces: 1 = the clamped edge x = 0, 2 = the loaded edge
// x = 48, 3 = the face z = 0, 4 = the face z = 1, 5 = the two free edges
// (bottom, from (0, 0) to (48, 44), and top, from (0, 44) to (48, 60)).
//
// A structured (transfinite) mesh: the nodes of each side are spaced
// evenly, the interior nodes are the bilinear (Coons) interpolation of the
// sides, so each cell is a plane quadrilateral with straight sides and
// together they cover the trapezoid exactly (area 1440 mm^2). Gmsh places
// the nodes of a Transfinite Curve by integrating its length numerically,
// which moves them along their side by up to about 1e-10 mm; they stay on
// the side up to rounding, so the areas are exact. The tip (48, 60) and
// the middle of the loaded edge (48, 52) are nodes of every mesh.
DefineConstant[ n = 16 ];
thickness = 1.;

Point(1) = {0., 0., 0.};
Point(2) = {48., 44., 0.};
Point(3) = {48., 60., 0.};
Point(4) = {0., 44., 0.};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; // counter-clockwise seen from +z
Plane Surface(1) = {1};
Transfinite Curve {1:4} = n + 1;
Transfinite Surface {1} = {1, 2, 3, 4};
Recombine Surface {1};

body[] = Extrude {0., 0., thickness} { Surface{1}; Layers{1}; Recombine; };
// body[0] = the face z = 1, body[1] = the volume, body[2 + i] = the
// surface extruded from Line(1 + i).
Physical Volume("membrane", 1) = {body[1]};
Physical Surface("clamped x = 0", 1) = {body[5]};
Physical Surface("loaded x = 48", 2) = {body[3]};
Physical Surface("z = 0", 3) = {1};
Physical Surface("z = 1", 4) = {body[0]};
Physical Surface("free edges", 5) = {body[2], body[4]};
