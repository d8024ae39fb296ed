// deal.II step-44's indentation problem in rubberdyn's units: the unit cube
// [0, 1]^3 mm (step-44: the same cube scaled by 1e-3 m), y vertical, one
// quarter of the full problem on the symmetry planes x = 0 and z = 0; the
// patch x < 0.5, z < 0.5 of the top y = 1 is loaded. A structured mesh of
// n^3 hexahedra (n even): n = 2^r is step-44's Global refinement r.
//
// Parameter (gmsh -setnumber): n = elements along each edge (default 4).
//
// Physical volume 1: the cube.
// Physical surfaces: 1 = x = 0 (symmetry), 2 = the bottom y = 0 (u_y = 0),
// 3 = z = 0 (symmetry), 4 = the top y = 1 outside the patch (u_x = u_z =
// 0), 5 = the loaded patch (u_x = u_z = 0 and the load), 6 = the free sides
// x = 1 and z = 1.
//
// Built by extrusion with Layers (exact node positions), each extrusion of
// several entities in one command, so that the shared edges are one.
DefineConstant[ n = 4 ];
h = Round(n / 2);
eps = 1e-6;

Point(1) = {0, 0, 0};
a[] = Extrude {0.5, 0, 0} { Point{1}; Layers{h}; };
b[] = Extrude {0.5, 0, 0} { Point{a[0]}; Layers{h}; };
c[] = Extrude {0, 0, 0.5} { Curve{a[1], b[1]}; Layers{h}; Recombine; };
d[] = Extrude {0, 0, 0.5} { Curve{c[0], c[4]}; Layers{h}; Recombine; };
base[] = Surface In BoundingBox {-eps, -eps, -eps, 1 + eps, eps, 1 + eps};
body[] = Extrude {0, 1, 0} { Surface{base[]}; Layers{2 * h}; Recombine; };

x0[] = Surface In BoundingBox {-eps, -eps, -eps, eps, 1 + eps, 1 + eps};
y0[] = Surface In BoundingBox {-eps, -eps, -eps, 1 + eps, eps, 1 + eps};
z0[] = Surface In BoundingBox {-eps, -eps, -eps, 1 + eps, 1 + eps, eps};
patch[] = Surface In BoundingBox {-eps, 1 - eps, -eps, 0.5 + eps, 1 + eps, 0.5 + eps};
top[] = Surface In BoundingBox {-eps, 1 - eps, -eps, 1 + eps, 1 + eps, 1 + eps};
top[] -= {patch[]};
x1[] = Surface In BoundingBox {1 - eps, -eps, -eps, 1 + eps, 1 + eps, 1 + eps};
z1[] = Surface In BoundingBox {-eps, -eps, 1 - eps, 1 + eps, 1 + eps, 1 + eps};
cube[] = Volume In BoundingBox {-eps, -eps, -eps, 1 + eps, 1 + eps, 1 + eps};

Physical Volume("cube", 1) = {cube[]};
Physical Surface("symmetry x = 0", 1) = {x0[]};
Physical Surface("bottom y = 0", 2) = {y0[]};
Physical Surface("symmetry z = 0", 3) = {z0[]};
Physical Surface("top outside the patch", 4) = {top[]};
Physical Surface("loaded patch", 5) = {patch[]};
Physical Surface("free sides x = 1, z = 1", 6) = {x1[], z1[]};
