// Two blocks 10 x 10 x 5 mm stacked along z with non-matching meshes where
// they touch, for the quasi-static contact patch test: the lower block
// [0, 10]^2 x [0, 5] with 4 x 4 x 2 hexahedra, the upper block
// [0, 10]^2 x [5.05, 10.05] with 5 x 5 x 3, 0.05 mm above it.
//
// Physical volumes: 1 = lower block, 2 = upper block.
// Physical surfaces: 1 = the lower block's bottom (z = 0), 2 = its top
// (z = 5), 3 = the upper block's bottom (z = 5.05), 4 = its top
// (z = 10.05); of both blocks: 5 = the faces x = 0, 6 = y = 0, 7 = x = 10,
// 8 = y = 10.
//
// Built by extrusion with Layers (exact node positions; see bar.geo). The
// gap keeps the blocks' geometry apart (Gmsh's built-in kernel merges
// coincident points and lines); the contact closes it.
l = 10.; h = 5.; gap = 0.05;
eps = 1e-6 * l;

Point(1) = {0., 0., 0.};
line1[] = Extrude {l, 0., 0.} { Point{1}; Layers{4}; };
face1[] = Extrude {0., l, 0.} { Curve{line1[1]}; Layers{4}; Recombine; };
lower[] = Extrude {0., 0., h} { Surface{face1[1]}; Layers{2}; Recombine; };

Point(100) = {0., 0., h + gap};
line2[] = Extrude {l, 0., 0.} { Point{100}; Layers{5}; };
face2[] = Extrude {0., l, 0.} { Curve{line2[1]}; Layers{5}; Recombine; };
upper[] = Extrude {0., 0., h} { Surface{face2[1]}; Layers{3}; Recombine; };

// z = const faces by position; the sides by position, from both blocks.
at_z0[] = Surface In BoundingBox {-eps, -eps, -eps, l + eps, l + eps, eps};
at_z1[] = Surface In BoundingBox {-eps, -eps, h - eps, l + eps, l + eps, h + eps};
at_z2[] = Surface In BoundingBox {-eps, -eps, h + gap - eps,
                                  l + eps, l + eps, h + gap + eps};
at_z3[] = Surface In BoundingBox {-eps, -eps, 2 * h + gap - eps,
                                  l + eps, l + eps, 2 * h + gap + eps};
at_x0[] = Surface In BoundingBox {-eps, -eps, -eps, eps, l + eps, 2 * h + gap + eps};
at_y0[] = Surface In BoundingBox {-eps, -eps, -eps, l + eps, eps, 2 * h + gap + eps};
at_x1[] = Surface In BoundingBox {l - eps, -eps, -eps,
                                  l + eps, l + eps, 2 * h + gap + eps};
at_y1[] = Surface In BoundingBox {-eps, l - eps, -eps,
                                  l + eps, l + eps, 2 * h + gap + eps};

Physical Volume("lower block", 1) = {lower[1]};
Physical Volume("upper block", 2) = {upper[1]};
Physical Surface("lower bottom z = 0", 1) = {at_z0[]};
Physical Surface("lower top z = 5", 2) = {at_z1[]};
Physical Surface("upper bottom z = 5.05", 3) = {at_z2[]};
Physical Surface("upper top z = 10.05", 4) = {at_z3[]};
Physical Surface("x = 0", 5) = {at_x0[]};
Physical Surface("y = 0", 6) = {at_y0[]};
Physical Surface("x = 10", 7) = {at_x1[]};
Physical Surface("y = 10", 8) = {at_y1[]};
