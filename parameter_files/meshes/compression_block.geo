// The block of the uniaxial compression verification
// (doc/verification/reference_solutions.md): an eighth of a 20 x 20 x 20 mm cube, 10 x 10 x 10
// mm, with symmetry planes x = 0, y = 0, z = 0; the top z = 10 is pressed
// down.
//
// Parameter (gmsh -setnumber): n = elements along each edge (default 4);
// regenerate.sh writes compression_block_4 and compression_block_8.
//
// Physical volume 1: rubber.
// Physical surfaces: 1 = symmetry x = 0, 2 = symmetry y = 0, 3 = symmetry
// z = 0, 4 = the top z = 10 (loaded), 5 = the free sides x = 10 and y = 10.
//
// Built by extrusion with Layers (exact node positions; see bar.geo).
DefineConstant[ n = 4 ];
l = 10.;
eps = 1e-6 * l;

Point(1) = {0., 0., 0.};
line[] = Extrude {l, 0., 0.} { Point{1}; Layers{n}; };
face[] = Extrude {0., l, 0.} { Curve{line[1]}; Layers{n}; Recombine; };
body[] = Extrude {0., 0., l} { Surface{face[1]}; Layers{n}; Recombine; };

x0[] = Surface In BoundingBox {-eps, -eps, -eps, eps, l + eps, l + eps};
y0[] = Surface In BoundingBox {-eps, -eps, -eps, l + eps, eps, l + eps};
z0[] = Surface In BoundingBox {-eps, -eps, -eps, l + eps, l + eps, eps};
top[] = Surface In BoundingBox {-eps, -eps, l - eps,
                                l + eps, l + eps, l + eps};
sides[] = Abs(Boundary{ Volume{body[1]}; });
sides[] -= {x0[], y0[], z0[], top[]};

Physical Volume("rubber", 1) = {body[1]};
Physical Surface("symmetry x = 0", 1) = {x0[]};
Physical Surface("symmetry y = 0", 2) = {y0[]};
Physical Surface("symmetry z = 0", 3) = {z0[]};
Physical Surface("top z = 10", 4) = {top[]};
Physical Surface("free sides", 5) = {sides[]};
