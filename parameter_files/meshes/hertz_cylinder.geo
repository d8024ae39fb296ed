// Hertz line contact (plane strain): an elastic cylinder of radius R = 10
// mm, axis along z, pressed down (-y) onto an elastic block. One slice of
// thickness t = 0.1 mm (one element) with symmetry faces z = 0 and z = t,
// and the symmetry plane x = 0 through the line of first contact: the
// cylinder is the quarter disc x >= 0 below its centre (0, R + g0), the
// block the square [0, 10] x [-10, 0] (20 times the half-width b = 0.5 mm of
// parameter_files/hertz_cylinder.prm). Separate nodes: the cylinder's lowest
// line lies g0 = 0.001 mm above the block (Gmsh's built-in kernel would
// merge a touching point), non-matching meshes where they touch.
//
// Both bodies are O-grids around the point of first contact: a uniform
// square of c x c at the contact and two shells around it whose elements grow
// geometrically away from it (the first radial element as large as the
// square's), so the elements stay near square from h at the contact to ~1-2
// mm at the far faces.
// - Block: square [0, 0.7] x [-0.7, 0] of 24 x 24 (h = 0.029 mm, b / h =
//   17), shells of 20 elements radially (growth 1.24-1.27).
// - Cylinder: the region within an arc length 0.7 of the lowest line along
//   the hull and 0.7 above it, 30 x 30 (h = 0.023 mm along the hull), shells
//   of 24 elements radially (growth 1.20-1.23) to the hull's quarter circle
//   and the top y = R + g0 (split at x = 5).
// Block 24 x 24 + 2 x 24 x 20 = 1536, cylinder 30 x 30 + 2 x 30 x 24 =
// 2340: 3876 hexahedra in one layer (8060 nodes).
//
// Physical volumes: 1 = cylinder, 2 = block.
// Physical surfaces: 1 = the cylinder's hull within arc length 0.7 of the
// lowest line (the contact pair's slave side), 2 = the block's top within
// x <= 0.7 (master side), 3 = the cylinder's top y = R + g0 (displaced),
// 4 = the block's bottom y = -10, 5 = the symmetry plane x = 0 (both), 6 =
// the face z = 0 (both), 7 = the face z = t (both), 8 = the other faces
// (the rest of the hull, the block's top x > 0.7 and its side x = 10).
R = 10.;      // cylinder radius
g0 = 0.001;   // initial gap at x = 0
t = 0.1;      // slice thickness along z
L = 10.;      // block: x in [0, L], y in [-L, 0]
c = 0.7;      // the block's uniform square [0, c] x [-c, 0]
n = 24;       // its elements per side
m = 20;       // the block's shells: elements radially
cs = 0.7;     // the cylinder's uniform region: arc length and height
ns = 30;      // its elements per side
ms = 24;      // the cylinder's shells: elements radially
q = 5.;       // where the cylinder's two shells meet on its top
eps = 1e-6;

// The growth ratio r_ of a graded curve of length len_ with m_ elements, the
// first of size h_: h_ (r_^m_ - 1) / (r_ - 1) = len_, by fixed-point
// iteration (converges for len_ > m_ h_).
Macro GrowthRatio
  r_ = 1.1;
  For i_ In {1:200}
    r_ = (1. + len_ * (r_ - 1.) / h_)^(1. / m_);
  EndFor
Return

// ---- Block, z = 0 cross-section.
Point(1) = {0., 0., 0.};
Point(2) = {c, 0., 0.};
Point(3) = {c, -c, 0.};
Point(4) = {0., -c, 0.};
Point(5) = {L, 0., 0.};
Point(6) = {L, -L, 0.};
Point(7) = {0., -L, 0.};
Line(1) = {1, 2};   // top of the square (contact)
Line(2) = {2, 3};
Line(3) = {4, 3};
Line(4) = {1, 4};   // x = 0
Line(5) = {2, 5};   // radial, away from the square
Line(6) = {3, 6};
Line(7) = {4, 7};
Line(8) = {5, 6};   // side x = L
Line(9) = {7, 6};   // bottom y = -L
Transfinite Curve{1, 2, 3, 4, 8, 9} = n + 1;
h_ = c / n; m_ = m;
len_ = L - c; Call GrowthRatio;
Transfinite Curve{5, 7} = m + 1 Using Progression r_;
len_ = Sqrt(2.) * (L - c); Call GrowthRatio;
Transfinite Curve{6} = m + 1 Using Progression r_;
Curve Loop(1) = {1, 2, -3, -4};
Plane Surface(1) = {1};
Curve Loop(2) = {5, 8, -6, -2};
Plane Surface(2) = {2};
Curve Loop(3) = {3, 6, -9, -7};
Plane Surface(3) = {3};
Transfinite Surface{1} = {1, 2, 3, 4};
Transfinite Surface{2} = {2, 5, 6, 3};
Transfinite Surface{3} = {4, 3, 6, 7};
Recombine Surface{1, 2, 3};

// ---- Cylinder, z = 0 cross-section: centre (0, yc), lowest point (0, g0).
yc = R + g0;
theta = cs / R;  // the angle of the uniform region's arc
xa = R * Sin(theta);
Point(11) = {0., g0, 0.};                        // S, lowest point
Point(12) = {xa, yc - R * Cos(theta), 0.};       // A, on the hull
Point(13) = {xa, g0 + cs, 0.};                   // At
Point(14) = {0., g0 + cs, 0.};                   // St
Point(15) = {R, yc, 0.};                         // E, end of the hull
Point(16) = {q, yc, 0.};                         // Q, on the top
Point(17) = {0., yc, 0.};                        // C, centre
Circle(11) = {11, 17, 12};  // hull near the contact
Line(12) = {12, 13};
Line(13) = {14, 13};
Line(14) = {11, 14};        // x = 0
Circle(15) = {12, 17, 15};  // radial: the rest of the hull
Line(16) = {13, 16};        // radial
Line(17) = {14, 17};        // radial, x = 0
Line(18) = {15, 16};        // top
Line(19) = {16, 17};        // top
Transfinite Curve{11, 12, 13, 14, 18, 19} = ns + 1;
h_ = cs / ns; m_ = ms;
len_ = R * (Pi / 2. - theta); Call GrowthRatio;
Transfinite Curve{15} = ms + 1 Using Progression r_;
len_ = Sqrt((q - xa)^2 + (yc - g0 - cs)^2); Call GrowthRatio;
Transfinite Curve{16} = ms + 1 Using Progression r_;
len_ = yc - g0 - cs; Call GrowthRatio;
Transfinite Curve{17} = ms + 1 Using Progression r_;
Curve Loop(11) = {11, 12, -13, -14};
Plane Surface(11) = {11};
Curve Loop(12) = {15, 18, -16, -12};
Plane Surface(12) = {12};
Curve Loop(13) = {13, 16, 19, -17};
Plane Surface(13) = {13};
Transfinite Surface{11} = {11, 12, 13, 14};
Transfinite Surface{12} = {12, 15, 16, 13};
Transfinite Surface{13} = {14, 13, 16, 17};
Recombine Surface{11, 12, 13};

// ---- One layer along z.
block[] = Extrude {0., 0., t} { Surface{1, 2, 3}; Layers{1}; Recombine; };
cylinder[] = Extrude {0., 0., t} { Surface{11, 12, 13}; Layers{1}; Recombine; };
// The volumes are the second entry of each surface's group of 6 (top,
// volume, 4 sides).
block_volumes[] = {block[1], block[7], block[13]};
cylinder_volumes[] = {cylinder[1], cylinder[7], cylinder[13]};

// ---- Boundary faces, by position.
slave[] = Surface In BoundingBox {-eps, g0 - eps, -eps,
                                  xa + eps, yc - R * Cos(theta) + eps, t + eps};
master[] = Surface In BoundingBox {-eps, -eps, -eps, c + eps, eps, t + eps};
top[] = Surface In BoundingBox {-eps, yc - eps, -eps, R + eps, yc + eps, t + eps};
bottom[] = Surface In BoundingBox {-eps, -L - eps, -eps,
                                   L + eps, -L + eps, t + eps};
symmetry_x[] = Surface In BoundingBox {-eps, -L - eps, -eps,
                                       eps, yc + eps, t + eps};
front[] = Surface In BoundingBox {-eps, -L - eps, -eps,
                                  L + R + eps, yc + eps, eps};
back[] = Surface In BoundingBox {-eps, -L - eps, t - eps,
                                 L + R + eps, yc + eps, t + eps};
others[] = Abs(CombinedBoundary{ Volume{block_volumes[]}; });
others[] += Abs(CombinedBoundary{ Volume{cylinder_volumes[]}; });
others[] -= {slave[], master[], top[], bottom[], symmetry_x[], front[],
             back[]};

Physical Volume("cylinder", 1) = {cylinder_volumes[]};
Physical Volume("block", 2) = {block_volumes[]};
Physical Surface("cylinder contact surface", 1) = {slave[]};
Physical Surface("block contact surface", 2) = {master[]};
Physical Surface("cylinder top", 3) = {top[]};
Physical Surface("block bottom", 4) = {bottom[]};
Physical Surface("symmetry x = 0", 5) = {symmetry_x[]};
Physical Surface("face z = 0", 6) = {front[]};
Physical Surface("face z = t", 7) = {back[]};
Physical Surface("other faces", 8) = {others[]};
