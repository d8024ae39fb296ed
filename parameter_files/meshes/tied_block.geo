// The bonded block of bonded_block.geo with non-matching meshes at the
// bond, for tied contact: a rubber block 20 x 20 x 10 mm (z from 0 to 10,
// 8 x 8 x 4 hexahedra) under a steel plate 20 x 20 x 2 mm (z from 10.05 to
// 12.05, 5 x 5 x 1 hexahedra), 0.05 mm above it with nodes of its own.
//
// Physical volumes: 1 = rubber, 2 = steel.
// Physical surfaces: 1 = bottom of the rubber (z = 0), 2 = top of the steel
// (z = 12.05), 3 = the sides of both, 4 = top of the rubber (z = 10), 5 =
// bottom of the steel (z = 10.05).
//
// Built by extrusion with Layers (exact node positions; see bar.geo). The
// gap keeps the two bodies' geometry apart (Gmsh's built-in kernel merges
// coincident points and lines); a tied pair keeps it as an offset.
lx = 20.; ly = 20.; lz = 10.; lz_steel = 2.; gap = 0.05;
eps = 1e-6 * lx;

Point(1) = {0., 0., 0.};
line[] = Extrude {lx, 0., 0.} { Point{1}; Layers{8}; };
face[] = Extrude {0., ly, 0.} { Curve{line[1]}; Layers{8}; Recombine; };
rubber[] = Extrude {0., 0., lz} { Surface{face[1]}; Layers{4}; Recombine; };

Point(100) = {0., 0., lz + gap};
steel_line[] = Extrude {lx, 0., 0.} { Point{100}; Layers{5}; };
steel_face[] = Extrude {0., ly, 0.} { Curve{steel_line[1]}; Layers{5}; Recombine; };
steel[] = Extrude {0., 0., lz_steel} { Surface{steel_face[1]}; Layers{1}; Recombine; };

bottom[] = Surface In BoundingBox {-eps, -eps, -eps, lx + eps, ly + eps, eps};
rubber_top[] = Surface In BoundingBox {-eps, -eps, lz - eps,
                                       lx + eps, ly + eps, lz + eps};
steel_bottom[] = Surface In BoundingBox {-eps, -eps, lz + gap - eps,
                                         lx + eps, ly + eps, lz + gap + eps};
top[] = Surface In BoundingBox {-eps, -eps, lz + gap + lz_steel - eps,
                                lx + eps, ly + eps, lz + gap + lz_steel + eps};
sides[] = Abs(Boundary{ Volume{rubber[1]}; });
sides[] += Abs(Boundary{ Volume{steel[1]}; });
sides[] -= {bottom[], rubber_top[], steel_bottom[], top[]};

Physical Volume("rubber", 1) = {rubber[1]};
Physical Volume("steel", 2) = {steel[1]};
Physical Surface("bottom of the rubber", 1) = {bottom[]};
Physical Surface("top of the steel", 2) = {top[]};
Physical Surface("sides", 3) = {sides[]};
Physical Surface("top of the rubber", 4) = {rubber_top[]};
Physical Surface("bottom of the steel", 5) = {steel_bottom[]};
