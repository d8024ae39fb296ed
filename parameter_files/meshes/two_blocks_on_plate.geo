// Two rubber blocks 10 x 10 x 5 mm (5 x 5 x 3 hexahedra each) standing on
// one steel plate 40 x 20 x 2 mm (z from 0 to 2; 16 x 8 x 2 hexahedra):
// one master surface (the plate's top) shared by two slave surfaces (the
// blocks' bottoms), with non-matching meshes. Block A covers x, y in
// [5, 15] x [5, 15], block B [25, 35] x [5, 15], both from z = 2 to 7.
//
// Physical volumes: 1 = block A, 2 = block B, 3 = plate.
// Physical surfaces: 1 = A's bottom, 2 = B's bottom, 3 = the plate's top,
// 4 = A's top, 5 = B's top, 6 = the plate's bottom, 7 = the other faces.
//
// Built by extrusion with Layers (exact node positions; see bar.geo). The
// blocks' corners lie inside the plate's top face: nothing is merged.
// The plate has more than half of the cells (256 of 406), so that any
// partition on two ranks into contiguous halves of an ordering of the
// cells splits it between them.
eps = 1e-6;

Point(100) = {5., 5., 2.};
a_line[] = Extrude {10., 0., 0.} { Point{100}; Layers{5}; };
a_face[] = Extrude {0., 10., 0.} { Curve{a_line[1]}; Layers{5}; Recombine; };
a[] = Extrude {0., 0., 5.} { Surface{a_face[1]}; Layers{3}; Recombine; };

Point(1) = {0., 0., 0.};
plate_line[] = Extrude {40., 0., 0.} { Point{1}; Layers{16}; };
plate_face[] = Extrude {0., 20., 0.} { Curve{plate_line[1]}; Layers{8}; Recombine; };
plate[] = Extrude {0., 0., 2.} { Surface{plate_face[1]}; Layers{2}; Recombine; };

Point(200) = {25., 5., 2.};
b_line[] = Extrude {10., 0., 0.} { Point{200}; Layers{5}; };
b_face[] = Extrude {0., 10., 0.} { Curve{b_line[1]}; Layers{5}; Recombine; };
b[] = Extrude {0., 0., 5.} { Surface{b_face[1]}; Layers{3}; Recombine; };

a_bottom[] = Surface In BoundingBox {5. - eps, 5. - eps, 2. - eps,
                                     15. + eps, 15. + eps, 2. + eps};
b_bottom[] = Surface In BoundingBox {25. - eps, 5. - eps, 2. - eps,
                                     35. + eps, 15. + eps, 2. + eps};
plate_top[] = Surface In BoundingBox {-eps, -eps, 2. - eps,
                                      40. + eps, 20. + eps, 2. + eps};
plate_top[] -= {a_bottom[], b_bottom[]};
a_top[] = Surface In BoundingBox {5. - eps, 5. - eps, 7. - eps,
                                  15. + eps, 15. + eps, 7. + eps};
b_top[] = Surface In BoundingBox {25. - eps, 5. - eps, 7. - eps,
                                  35. + eps, 15. + eps, 7. + eps};
plate_bottom[] = Surface In BoundingBox {-eps, -eps, -eps,
                                         40. + eps, 20. + eps, eps};
others[] = Abs(Boundary{ Volume{plate[1]}; });
others[] += Abs(Boundary{ Volume{a[1]}; });
others[] += Abs(Boundary{ Volume{b[1]}; });
others[] -= {a_bottom[], b_bottom[], plate_top[], a_top[], b_top[],
             plate_bottom[]};

Physical Volume("block A", 1) = {a[1]};
Physical Volume("block B", 2) = {b[1]};
Physical Volume("plate", 3) = {plate[1]};
Physical Surface("A bottom", 1) = {a_bottom[]};
Physical Surface("B bottom", 2) = {b_bottom[]};
Physical Surface("plate top", 3) = {plate_top[]};
Physical Surface("A top", 4) = {a_top[]};
Physical Surface("B top", 5) = {b_top[]};
Physical Surface("plate bottom", 6) = {plate_bottom[]};
Physical Surface("other faces", 7) = {others[]};
