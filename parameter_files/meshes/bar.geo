// A straight bar 100 x 10 x 10 mm along x, 20 x 2 x 2 hexahedra.
//
// Physical volume 1: the bar.
// Physical surfaces: 1 = end x = 0, 2 = end x = 100, 3 = the four sides.
//
// Built by extruding a point, a line and a square with Layers: Gmsh places
// extruded nodes at exact fractions of the length, while its 1D mesher
// (Transfinite Curve) places them by numerical integration, up to 2e-10 mm
// off on a 100 mm line (Gmsh 4.8.4).
lx = 100.; ly = 10.; lz = 10.;
nx = 20; ny = 2; nz = 2;
eps = 1e-6 * lx; // for selecting the boundary surfaces by bounding box

Point(1) = {0., 0., 0.};
line[] = Extrude {lx, 0., 0.} { Point{1}; Layers{nx}; };
face[] = Extrude {0., ly, 0.} { Curve{line[1]}; Layers{ny}; Recombine; };
body[] = Extrude {0., 0., lz} { Surface{face[1]}; Layers{nz}; Recombine; };

x_min[] = Surface In BoundingBox {-eps, -eps, -eps, eps, ly + eps, lz + eps};
x_max[] = Surface In BoundingBox {lx - eps, -eps, -eps,
                                  lx + eps, ly + eps, lz + eps};
sides[] = Abs(Boundary{ Volume{body[1]}; });
sides[] -= {x_min[], x_max[]};

Physical Volume("bar", 1) = {body[1]};
Physical Surface("end x = 0", 1) = {x_min[]};
Physical Surface("end x = 100", 2) = {x_max[]};
Physical Surface("sides", 3) = {sides[]};
