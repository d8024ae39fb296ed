// A rubber block 20 x 20 x 10 mm (z up), 8 x 8 x 4 hexahedra.
//
// Physical volume 1: rubber.
// Physical surfaces: 1 = bottom z = 0, 2 = top z = 10, 3 = the four sides.
//
// Built by extrusion with Layers (exact node positions; see bar.geo).
lx = 20.; ly = 20.; lz = 10.;
nx = 8; ny = 8; nz = 4;
eps = 1e-6 * lx;

Point(1) = {0., 0., 0.};
line[] = Extrude {lx, 0., 0.} { Point{1}; Layers{nx}; };
face[] = Extrude {0., ly, 0.} { Curve{line[1]}; Layers{ny}; Recombine; };
body[] = Extrude {0., 0., lz} { Surface{face[1]}; Layers{nz}; Recombine; };

bottom[] = Surface In BoundingBox {-eps, -eps, -eps, lx + eps, ly + eps, eps};
top[] = Surface In BoundingBox {-eps, -eps, lz - eps,
                                lx + eps, ly + eps, lz + eps};
sides[] = Abs(Boundary{ Volume{body[1]}; });
sides[] -= {bottom[], top[]};

Physical Volume("rubber", 1) = {body[1]};
Physical Surface("bottom", 1) = {bottom[]};
Physical Surface("top", 2) = {top[]};
Physical Surface("sides", 3) = {sides[]};
