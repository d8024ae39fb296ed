// Two straight bars 100 x 10 x 10 mm along x, end to end with a gap of
// 0.05 mm and non-matching cross-section meshes: the striker [0, 100] with
// 20 x 2 x 2 hexahedra, the target [100.05, 200.05] with 20 x 3 x 3.
//
// Physical volumes: 1 = striker, 2 = target.
// Physical surfaces: 1 = the striker's end x = 100, 2 = the target's end
// x = 100.05 (the contact pair), 3 = the striker's end x = 0, 4 = the
// target's end x = 200.05, 5 = the sides of both.
//
// Built by extrusion with Layers (exact node fractions, like bar.geo). The
// gap keeps the bars' geometry apart: Gmsh's built-in kernel merges
// coincident points and lines, and touching bars would share the edges of
// their end faces, which have different numbers of layers.
lx = 100.; ly = 10.; lz = 10.; gap = 0.05;
eps = 1e-6 * lx;

Point(1) = {0., 0., 0.};
line1[] = Extrude {lx, 0., 0.} { Point{1}; Layers{20}; };
face1[] = Extrude {0., ly, 0.} { Curve{line1[1]}; Layers{2}; Recombine; };
body1[] = Extrude {0., 0., lz} { Surface{face1[1]}; Layers{2}; Recombine; };

Point(100) = {lx + gap, 0., 0.};
line2[] = Extrude {lx, 0., 0.} { Point{100}; Layers{20}; };
face2[] = Extrude {0., ly, 0.} { Curve{line2[1]}; Layers{3}; Recombine; };
body2[] = Extrude {0., 0., lz} { Surface{face2[1]}; Layers{3}; Recombine; };

// The end faces of each bar: among its own boundary, by position.
striker_faces[] = Abs(Boundary{ Volume{body1[1]}; });
target_faces[] = Abs(Boundary{ Volume{body2[1]}; });
striker_end[] = Surface In BoundingBox {lx - eps, -eps, -eps,
                                        lx + eps, ly + eps, lz + eps};
target_end[] = Surface In BoundingBox {lx + gap - eps, -eps, -eps,
                                       lx + gap + eps, ly + eps, lz + eps};
at_0[] = Surface In BoundingBox {-eps, -eps, -eps, eps, ly + eps, lz + eps};
at_200[] = Surface In BoundingBox {2 * lx + gap - eps, -eps, -eps,
                                   2 * lx + gap + eps, ly + eps, lz + eps};
sides[] = {striker_faces[], target_faces[]};
sides[] -= {striker_end[], target_end[], at_0[], at_200[]};

Physical Volume("striker", 1) = {body1[1]};
Physical Volume("target", 2) = {body2[1]};
Physical Surface("striker end x = 100", 1) = {striker_end[]};
Physical Surface("target end x = 100.05", 2) = {target_end[]};
Physical Surface("striker end x = 0", 3) = {at_0[]};
Physical Surface("target end x = 200.05", 4) = {at_200[]};
Physical Surface("sides", 5) = {sides[]};
