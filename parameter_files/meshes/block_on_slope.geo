// The frictional patch test (NAFEMS CGS-4 type): a block on a slope of
// tan(alpha) = 0.1 rising along +x, with non-matching meshes where they
// touch. In the slope's frame (x' = (cos alpha, 0, sin alpha) up the
// slope, y, z' = (-sin alpha, 0, cos alpha)): the base [0, 14] x [0, 10] x
// [0, 5] with 7 x 4 x 2 hexahedra (2 x 2.5 mm faces on top), the block
// [2, 12] x [0, 10] x [4.999, 9.999] with 4 x 5 x 2 (2.5 x 2 mm faces): it
// starts 1e-3 mm into the base, so that the contact holds it from the
// first load step.
//
// Physical volumes: 1 = base, 2 = block.
// Physical surfaces: 1 = the base's bottom, 2 = the base's top (the
// slope), 3 = the block's bottom, 4 = the block's top, 5 = the block's
// face at the lower end of the slope (x = 2 before turning: it is
// pushed), 6 = the other faces of both.
//
// Built by extrusion with Layers along the slope's axes (see bar.geo).
alpha = Atan(0.1);
c = Cos(alpha); s = Sin(alpha);
overlap = 1e-3;

Point(1) = {0., 0., 0.};
line1[] = Extrude {14 * c, 0., 14 * s} { Point{1}; Layers{7}; };
face1[] = Extrude {0., 10., 0.} { Curve{line1[1]}; Layers{4}; Recombine; };
base[] = Extrude {-5 * s, 0., 5 * c} { Surface{face1[1]}; Layers{2}; Recombine; };

Point(100) = {2 * c - (5 - overlap) * s, 0., 2 * s + (5 - overlap) * c};
line2[] = Extrude {10 * c, 0., 10 * s} { Point{100}; Layers{4}; };
face2[] = Extrude {0., 10., 0.} { Curve{line2[1]}; Layers{5}; Recombine; };
block[] = Extrude {-5 * s, 0., 5 * c} { Surface{face2[1]}; Layers{2}; Recombine; };

// An extruded volume's list: [0] the top, [1] the volume, then the sides
// y = 0, x' = end, y = 10, x' = start; its bottom is the source surface.
Physical Volume("base", 1) = {base[1]};
Physical Volume("block", 2) = {block[1]};
Physical Surface("base bottom", 1) = {face1[1]};
Physical Surface("slope", 2) = {base[0]};
Physical Surface("block bottom", 3) = {face2[1]};
Physical Surface("block top", 4) = {block[0]};
Physical Surface("block back", 5) = {block[5]};
Physical Surface("other faces", 6) = {base[2], base[3], base[4], base[5],
                                      block[2], block[3], block[4]};
