// A two-material part: a rubber block 20 x 20 x 10 mm (z from 0 to 10,
// 8 x 8 x 4 hexahedra) bonded to a steel plate 20 x 20 x 2 mm on top
// (z from 10 to 12, 8 x 8 x 1 hexahedra). One conforming mesh: the two
// share their nodes at z = 10.
//
// Physical volumes: 1 = rubber, 2 = steel.
// Physical surfaces: 1 = bottom of the rubber (z = 0), 2 = top of the steel
// (z = 12), 3 = the sides of both. The bonded interface is not a boundary.
//
// Built by extrusion with Layers (exact node positions; see bar.geo); the
// plate is extruded from the top of the rubber, so the nodes are shared.
lx = 20.; ly = 20.; lz = 10.; lz_steel = 2.;
nx = 8; ny = 8; nz = 4; nz_steel = 1;
eps = 1e-6 * lx;

Point(1) = {0., 0., 0.};
line[] = Extrude {lx, 0., 0.} { Point{1}; Layers{nx}; };
face[] = Extrude {0., ly, 0.} { Curve{line[1]}; Layers{ny}; Recombine; };
rubber[] = Extrude {0., 0., lz} { Surface{face[1]}; Layers{nz}; Recombine; };
steel[] = Extrude {0., 0., lz_steel} {
  Surface{rubber[0]}; Layers{nz_steel}; Recombine;
};

bottom[] = Surface In BoundingBox {-eps, -eps, -eps, lx + eps, ly + eps, eps};
top[] = Surface In BoundingBox {-eps, -eps, lz + lz_steel - eps,
                                lx + eps, ly + eps, lz + lz_steel + eps};
sides[] = Abs(CombinedBoundary{ Volume{rubber[1], steel[1]}; });
sides[] -= {bottom[], top[]};

Physical Volume("rubber", 1) = {rubber[1]};
Physical Volume("steel", 2) = {steel[1]};
Physical Surface("rubber bottom", 1) = {bottom[]};
Physical Surface("steel top", 2) = {top[]};
Physical Surface("sides", 3) = {sides[]};
