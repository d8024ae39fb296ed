// Uniaxial compression block for the quasi-static solver: one octant of a
// cube, 10 x 10 x 10 mm (x, y, z from 0 to 10), 3 x 3 x 3 hexahedra, with
// the three symmetry planes tagged, the top loaded and the outer sides free
// (parameter_files/uniaxial_compression_quasi_static.prm).
//
// Physical volume: 1 = rubber.
// Physical surfaces: 1 = x = 0, 2 = y = 0, 3 = z = 0 (symmetry planes),
// 4 = top z = 10 (prescribed displacement), 5 = the free sides x = 10 and
// y = 10.
//
// Built by extrusion with Layers (exact node positions; see bar.geo).
l = 10.; n = 3;
eps = 1e-6 * l;

Point(1) = {0., 0., 0.};
line[] = Extrude {l, 0., 0.} { Point{1}; Layers{n}; };
face[] = Extrude {0., l, 0.} { Curve{line[1]}; Layers{n}; Recombine; };
block[] = Extrude {0., 0., l} { Surface{face[1]}; Layers{n}; Recombine; };

x0[] = Surface In BoundingBox {-eps, -eps, -eps, eps, l + eps, l + eps};
y0[] = Surface In BoundingBox {-eps, -eps, -eps, l + eps, eps, l + eps};
z0[] = Surface In BoundingBox {-eps, -eps, -eps, l + eps, l + eps, eps};
top[] = Surface In BoundingBox {-eps, -eps, l - eps, l + eps, l + eps, l + eps};
x1[] = Surface In BoundingBox {l - eps, -eps, -eps, l + eps, l + eps, l + eps};
y1[] = Surface In BoundingBox {-eps, l - eps, -eps, l + eps, l + eps, l + eps};

Physical Volume("rubber", 1) = {block[1]};
Physical Surface("symmetry x", 1) = {x0[]};
Physical Surface("symmetry y", 2) = {y0[]};
Physical Surface("symmetry z", 3) = {z0[]};
Physical Surface("top", 4) = {top[]};
Physical Surface("free sides", 5) = {x1[], y1[]};
