// A rubber block 20 x 20 x 10 mm on the floor (z from 0 to 10, 6 x 6 x 3
// hexahedra) and, 5 mm above it, a steel block 10 x 10 x 5 mm (z from 15 to
// 20, centred over the rubber, 2 x 2 x 1 hexahedra) meant to be a rigid
// part. The two bodies are separate meshes: they share no node.
//
// Physical volumes: 1 = rubber, 2 = steel (rigid).
// Physical surfaces: 1 = rubber bottom (z = 0), 2 = rubber top (z = 10),
// 3 = rigid block bottom (z = 15), 4 = all other outer faces (the rubber's
// sides, the rigid block's sides and top).
//
// Built by extrusion with Layers (exact node positions; see bar.geo).
lx = 20.; ly = 20.; lz = 10.;
nx = 6; ny = 6; nz = 3;
gap = 5.;
sx = 10.; sy = 10.; sz = 5.;
mx = 2; my = 2; mz = 1;
eps = 1e-6 * lx;

Point(1) = {0., 0., 0.};
line[] = Extrude {lx, 0., 0.} { Point{1}; Layers{nx}; };
face[] = Extrude {0., ly, 0.} { Curve{line[1]}; Layers{ny}; Recombine; };
rubber[] = Extrude {0., 0., lz} { Surface{face[1]}; Layers{nz}; Recombine; };

Point(100) = {(lx - sx) / 2., (ly - sy) / 2., lz + gap};
line2[] = Extrude {sx, 0., 0.} { Point{100}; Layers{mx}; };
face2[] = Extrude {0., sy, 0.} { Curve{line2[1]}; Layers{my}; Recombine; };
steel[] = Extrude {0., 0., sz} { Surface{face2[1]}; Layers{mz}; Recombine; };

rubber_bottom[] = Surface In BoundingBox {-eps, -eps, -eps,
                                          lx + eps, ly + eps, eps};
rubber_top[] = Surface In BoundingBox {-eps, -eps, lz - eps,
                                       lx + eps, ly + eps, lz + eps};
steel_bottom[] = Surface In BoundingBox {-eps, -eps, lz + gap - eps,
                                         lx + eps, ly + eps, lz + gap + eps};
others[] = Abs(Boundary{ Volume{rubber[1], steel[1]}; });
others[] -= {rubber_bottom[], rubber_top[], steel_bottom[]};

Physical Volume("rubber", 1) = {rubber[1]};
Physical Volume("steel", 2) = {steel[1]};
Physical Surface("rubber bottom", 1) = {rubber_bottom[]};
Physical Surface("rubber top", 2) = {rubber_top[]};
Physical Surface("rigid block bottom", 3) = {steel_bottom[]};
Physical Surface("other outer faces", 4) = {others[]};
