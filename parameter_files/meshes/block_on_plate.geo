// A rubber block 10 x 10 x 5 mm (x, y from 5 to 15, z from 2 to 7;
// 5 x 5 x 3 hexahedra) standing on a steel plate 20 x 20 x 2 mm (z from 0
// to 2; 4 x 4 x 1 hexahedra): separate nodes, non-matching meshes where
// they touch.
//
// Physical volumes: 1 = rubber block, 2 = steel plate.
// Physical surfaces: 1 = the block's bottom (z = 2), 2 = the plate's top
// (z = 2), 3 = the block's top (z = 7), 4 = the plate's bottom (z = 0),
// 5 = the other faces of both.
//
// Built by extrusion with Layers (exact node positions; see bar.geo). The
// block's corners lie inside the plate's top face, so Gmsh's built-in
// kernel merges nothing.
eps = 1e-6;

Point(1) = {0., 0., 0.};
plate_line[] = Extrude {20., 0., 0.} { Point{1}; Layers{4}; };
plate_face[] = Extrude {0., 20., 0.} { Curve{plate_line[1]}; Layers{4}; Recombine; };
plate[] = Extrude {0., 0., 2.} { Surface{plate_face[1]}; Layers{1}; Recombine; };

Point(100) = {5., 5., 2.};
block_line[] = Extrude {10., 0., 0.} { Point{100}; Layers{5}; };
block_face[] = Extrude {0., 10., 0.} { Curve{block_line[1]}; Layers{5}; Recombine; };
block[] = Extrude {0., 0., 5.} { Surface{block_face[1]}; Layers{3}; Recombine; };

block_bottom[] = Surface In BoundingBox {5. - eps, 5. - eps, 2. - eps,
                                         15. + eps, 15. + eps, 2. + eps};
plate_top[] = Surface In BoundingBox {-eps, -eps, 2. - eps,
                                      20. + eps, 20. + eps, 2. + eps};
plate_top[] -= {block_bottom[]};
block_top[] = Surface In BoundingBox {5. - eps, 5. - eps, 7. - eps,
                                      15. + eps, 15. + eps, 7. + eps};
plate_bottom[] = Surface In BoundingBox {-eps, -eps, -eps,
                                         20. + eps, 20. + eps, eps};
others[] = Abs(Boundary{ Volume{plate[1]}; });
others[] += Abs(Boundary{ Volume{block[1]}; });
others[] -= {block_bottom[], plate_top[], block_top[], plate_bottom[]};

Physical Volume("rubber block", 1) = {block[1]};
Physical Volume("steel plate", 2) = {plate[1]};
Physical Surface("block bottom", 1) = {block_bottom[]};
Physical Surface("plate top", 2) = {plate_top[]};
Physical Surface("block top", 3) = {block_top[]};
Physical Surface("plate bottom", 4) = {plate_bottom[]};
Physical Surface("other faces", 5) = {others[]};
