// Hertz point contact: an elastic sphere of radius R = 10 mm pressed down
// (-z) onto an elastic block, a quarter model on the symmetry planes x = 0
// and y = 0 through the point of first contact. The sphere is its octant
// x, y >= 0 below its centre (0, 0, R + g0) (a quarter of the lower
// hemisphere, the flat top z = R + g0 loaded); the block the quarter
// [0, 6] x [0, 6] x [-6, 0] (12 times the contact radius a = 0.5 mm of
// parameter_files/hertz_sphere.prm). Separate nodes: the sphere's lowest
// point lies g0 = 0.001 mm above the block (Gmsh's built-in kernel would
// merge a touching point), non-matching meshes where they touch.
//
// Both bodies are O-grids around the point of first contact: a "cube" at
// the contact, uniform along the surface, its layers growing away from the
// surface, and three shells around it (towards +x, +y and away from the
// surface) whose elements grow geometrically away from it.
// - Block: the cube [0, 0.65]^2 x [-0.65, 0] of 12 x 12 elements along the
//   top (h = 0.054 mm, a / h = 9.2) and 6 layers (the first h thick);
//   shells of 8 elements radially, all radial edges with the same growth
//   (the shells are frustums of pyramids with their apex at the contact
//   point: their layers are scaled copies of the cube's faces).
//   12 x 12 x 6 + 2 x 12 x 6 x 8 + 12 x 12 x 8 = 3168 hexahedra.
// - Sphere: the cube's bottom is the square [0, xa]^2 (xa = R sin(0.065),
//   0.6495 mm) projected vertically onto the sphere, 14 x 14 elements
//   (h = 0.046 mm along the hull), 6 layers up to z = g0 + 0.65 (the first
//   h thick); shells of 9 elements radially to the equator and the top
//   (the shell above the cube ends in the square [0, 4.5]^2 of the top).
//   14 x 14 x 6 + 2 x 14 x 6 x 9 + 14 x 14 x 9 = 4452 hexahedra.
// 7620 hexahedra in all (a quasi-static run of two load steps takes ~20
// Newton iterations of a direct solve of 26 700 dofs).
//
// Physical volumes: 1 = sphere, 2 = block.
// Physical surfaces: 1 = the sphere's hull over the square [0, xa]^2 (the
// contact pair's slave side), 2 = the block's top over [0, 0.65]^2 (master
// side), 3 = the sphere's top z = R + g0 (displaced), 4 = the block's
// bottom z = -6, 5 = the symmetry plane x = 0 (both), 6 = the symmetry
// plane y = 0 (both), 7 = the other faces (the rest of the hull, the rest
// of the block's top, its sides x = 6 and y = 6).
R = 10.;      // sphere radius
g0 = 0.001;   // initial gap at the lowest point
L = 6.;       // block: [0, L] x [0, L] x [-L, 0]
c = 0.65;     // the block's cube [0, c]^2 x [-c, 0]
n = 12;       // its elements along x and y
k = 6;        // its layers along z
m = 8;        // the block's shells: elements radially
cs = 0.65;    // the sphere's cube: arc length of its bottom's sides along
              // the hull from the lowest point, and height
ns = 14;      // its elements along x and y
ks = 6;       // its layers along z
ms = 9;       // the sphere's shells: elements radially
q = 4.5;      // the sphere's shells meet on its top along the square
              // [0, q]^2
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

// ---- Block.
Point(1) = {0., 0., 0.};   // O, the point of first contact
Point(2) = {c, 0., 0.};
Point(3) = {c, c, 0.};
Point(4) = {0., c, 0.};
Point(5) = {0., 0., -c};
Point(6) = {c, 0., -c};
Point(7) = {c, c, -c};
Point(8) = {0., c, -c};
Point(9) = {L, 0., 0.};
Point(10) = {L, L, 0.};
Point(11) = {0., L, 0.};
Point(12) = {0., 0., -L};
Point(13) = {L, 0., -L};
Point(14) = {L, L, -L};
Point(15) = {0., L, -L};
// The cube: top (z = 0), bottom (z = -c), verticals (downwards).
Line(1) = {1, 2};  Line(2) = {2, 3};  Line(3) = {4, 3};  Line(4) = {1, 4};
Line(5) = {5, 6};  Line(6) = {6, 7};  Line(7) = {8, 7};  Line(8) = {5, 8};
Line(9) = {1, 5};  Line(10) = {2, 6}; Line(11) = {3, 7}; Line(12) = {4, 8};
// Radial edges, from the cube outwards.
Line(13) = {2, 9};  Line(14) = {3, 10}; Line(15) = {4, 11};
Line(16) = {5, 12}; Line(17) = {6, 13}; Line(18) = {7, 14}; Line(19) = {8, 15};
// The outer box: top, bottom, verticals (downwards).
Line(20) = {9, 10};  Line(21) = {11, 10};
Line(22) = {12, 13}; Line(23) = {13, 14}; Line(24) = {15, 14};
Line(25) = {12, 15};
Line(26) = {9, 13};  Line(27) = {10, 14}; Line(28) = {11, 15};

Transfinite Curve{1:8, 20:25} = n + 1;
h_ = c / n; m_ = k; len_ = c; Call GrowthRatio;
rk = r_;
Transfinite Curve{9:12, 26:28} = k + 1 Using Progression rk;
h_ = c / n; m_ = m; len_ = L - c; Call GrowthRatio;
Transfinite Curve{13:19} = m + 1 Using Progression r_;

// The cube's faces: top, bottom, y = 0, x = c, y = c, x = 0.
Curve Loop(1) = {1, 2, -3, -4};    Plane Surface(1) = {1};
Curve Loop(2) = {5, 6, -7, -8};    Plane Surface(2) = {2};
Curve Loop(3) = {1, 10, -5, -9};   Plane Surface(3) = {3};
Curve Loop(4) = {2, 11, -6, -10};  Plane Surface(4) = {4};
Curve Loop(5) = {3, 11, -7, -12};  Plane Surface(5) = {5};
Curve Loop(6) = {4, 12, -8, -9};   Plane Surface(6) = {6};
// Shell X: outer x = L, top, y = 0, diagonal x = y, diagonal x = -z.
Curve Loop(7) = {20, 27, -23, -26};  Plane Surface(7) = {7};
Curve Loop(8) = {13, 20, -14, -2};   Plane Surface(8) = {8};
Curve Loop(9) = {13, 26, -17, -10};  Plane Surface(9) = {9};
Curve Loop(10) = {14, 27, -18, -11}; Plane Surface(10) = {10};
Curve Loop(11) = {17, 23, -18, -6};  Plane Surface(11) = {11};
// Shell Y: outer y = L, top, x = 0, diagonal y = -z.
Curve Loop(12) = {21, 27, -24, -28}; Plane Surface(12) = {12};
Curve Loop(13) = {15, 21, -14, -3};  Plane Surface(13) = {13};
Curve Loop(14) = {15, 28, -19, -12}; Plane Surface(14) = {14};
Curve Loop(15) = {19, 24, -18, -7};  Plane Surface(15) = {15};
// Shell Z: outer z = -L, y = 0, x = 0.
Curve Loop(16) = {22, 23, -24, -25}; Plane Surface(16) = {16};
Curve Loop(17) = {16, 22, -17, -5};  Plane Surface(17) = {17};
Curve Loop(18) = {16, 25, -19, -8};  Plane Surface(18) = {18};

Transfinite Surface{1} = {1, 2, 3, 4};
Transfinite Surface{2} = {5, 6, 7, 8};
Transfinite Surface{3} = {1, 2, 6, 5};
Transfinite Surface{4} = {2, 3, 7, 6};
Transfinite Surface{5} = {4, 3, 7, 8};
Transfinite Surface{6} = {1, 4, 8, 5};
Transfinite Surface{7} = {9, 10, 14, 13};
Transfinite Surface{8} = {2, 9, 10, 3};
Transfinite Surface{9} = {2, 9, 13, 6};
Transfinite Surface{10} = {3, 10, 14, 7};
Transfinite Surface{11} = {6, 13, 14, 7};
Transfinite Surface{12} = {11, 10, 14, 15};
Transfinite Surface{13} = {4, 11, 10, 3};
Transfinite Surface{14} = {4, 11, 15, 8};
Transfinite Surface{15} = {8, 15, 14, 7};
Transfinite Surface{16} = {12, 13, 14, 15};
Transfinite Surface{17} = {5, 12, 13, 6};
Transfinite Surface{18} = {5, 12, 15, 8};
Recombine Surface{1:18};

Surface Loop(1) = {1, 2, 3, 4, 5, 6};       Volume(1) = {1};
Surface Loop(2) = {4, 7, 8, 9, 10, 11};     Volume(2) = {2};
Surface Loop(3) = {5, 12, 13, 14, 10, 15};  Volume(3) = {3};
Surface Loop(4) = {2, 16, 17, 18, 11, 15};  Volume(4) = {4};
Transfinite Volume{1} = {1, 2, 3, 4, 5, 6, 7, 8};
Transfinite Volume{2} = {2, 3, 7, 6, 9, 10, 14, 13};
Transfinite Volume{3} = {4, 3, 7, 8, 11, 10, 14, 15};
Transfinite Volume{4} = {5, 6, 7, 8, 12, 13, 14, 15};
Recombine Volume{1:4};

// ---- Sphere: centre (0, 0, zc), lowest point (0, 0, g0).
zc = R + g0;
xa = R * Sin(cs / R);
zA = zc - Sqrt(R^2 - xa^2);      // the hull above (xa, 0) and (0, xa)
zD = zc - Sqrt(R^2 - 2 * xa^2);  // the hull above (xa, xa)
zt = g0 + cs;                    // the top of the cube
Point(101) = {0., 0., g0};      // S, lowest point
Point(102) = {xa, 0., zA};      // A
Point(103) = {xa, xa, zD};      // D
Point(104) = {0., xa, zA};      // B
Point(105) = {0., 0., zt};      // St
Point(106) = {xa, 0., zt};      // At
Point(107) = {xa, xa, zt};      // Dt
Point(108) = {0., xa, zt};      // Bt
Point(109) = {R, 0., zc};       // E1, on the equator
Point(110) = {R / Sqrt(2.), R / Sqrt(2.), zc};  // Em
Point(111) = {0., R, zc};       // E2
Point(112) = {q, 0., zc};       // Q1, on the top
Point(113) = {q, q, zc};        // Qm
Point(114) = {0., q, zc};       // Q2
Point(115) = {0., 0., zc};      // C, the centre
Point(116) = {xa, 0., zc};      // centre of the circle x = xa on the hull
Point(117) = {0., xa, zc};      // centre of the circle y = xa on the hull
// The cube: bottom on the hull (great circles through S, small circles
// x = xa and y = xa), top z = zt, verticals (upwards).
Circle(101) = {101, 115, 102};
Circle(102) = {102, 116, 103};
Circle(103) = {104, 117, 103};
Circle(104) = {101, 115, 104};
Line(105) = {105, 106}; Line(106) = {106, 107};
Line(107) = {108, 107}; Line(108) = {105, 108};
Line(109) = {101, 105}; Line(110) = {102, 106};
Line(111) = {103, 107}; Line(112) = {104, 108};
// Radial edges: great circles on the hull, lines inside.
Circle(113) = {102, 115, 109};
Circle(114) = {103, 115, 110};
Circle(115) = {104, 115, 111};
Line(116) = {106, 112}; Line(117) = {107, 113};
Line(118) = {108, 114}; Line(119) = {105, 115};
// The equator, the top's square [0, q]^2, and the top from the equator
// inwards.
Circle(120) = {109, 115, 110};
Circle(121) = {111, 115, 110};
Line(122) = {112, 113};
Line(123) = {114, 113};
Line(124) = {115, 112}; Line(125) = {115, 114};
Line(126) = {109, 112}; Line(127) = {110, 113}; Line(128) = {111, 114};

hs = cs / ns;
Transfinite Curve{101:108, 120:125} = ns + 1;
h_ = hs; m_ = ks;
len_ = zt - g0; Call GrowthRatio;
Transfinite Curve{109} = ks + 1 Using Progression r_;
rks = r_;
ht = hs * rks^(ks - 1);  // the cube's top layer
len_ = zt - zA; Call GrowthRatio;
Transfinite Curve{110, 112} = ks + 1 Using Progression r_;
len_ = zt - zD; Call GrowthRatio;
Transfinite Curve{111} = ks + 1 Using Progression r_;
Transfinite Curve{126:128} = ks + 1 Using Progression rks;
m_ = ms;
h_ = hs; len_ = R * (Pi / 2. - cs / R); Call GrowthRatio;
Transfinite Curve{113, 115} = ms + 1 Using Progression r_;
h_ = hs; len_ = R * (Pi / 2. - Acos((zc - zD) / R)); Call GrowthRatio;
Transfinite Curve{114} = ms + 1 Using Progression r_;
h_ = ht; len_ = Sqrt((q - xa)^2 + (zc - zt)^2); Call GrowthRatio;
Transfinite Curve{116, 118} = ms + 1 Using Progression r_;
h_ = ht; len_ = Sqrt(2. * (q - xa)^2 + (zc - zt)^2);
Call GrowthRatio;
Transfinite Curve{117} = ms + 1 Using Progression r_;
h_ = ht; len_ = zc - zt; Call GrowthRatio;
Transfinite Curve{119} = ms + 1 Using Progression r_;

// The cube's faces: bottom (hull), top, y = 0, x = xa, y = xa, x = 0.
Curve Loop(101) = {101, 102, -103, -104}; Surface(101) = {101} In Sphere {115};
Curve Loop(102) = {105, 106, -107, -108}; Plane Surface(102) = {102};
Curve Loop(103) = {101, 110, -105, -109}; Plane Surface(103) = {103};
Curve Loop(104) = {102, 111, -106, -110}; Plane Surface(104) = {104};
Curve Loop(105) = {103, 111, -107, -112}; Plane Surface(105) = {105};
Curve Loop(106) = {104, 112, -108, -109}; Plane Surface(106) = {106};
// Shell X: hull, top, y = 0, diagonal x = y, the face towards shell Z.
Curve Loop(107) = {113, 120, -114, -102}; Surface(107) = {107} In Sphere {115};
Curve Loop(108) = {126, 122, -127, -120}; Plane Surface(108) = {108};
Curve Loop(109) = {113, 126, -116, -110}; Plane Surface(109) = {109};
Curve Loop(110) = {114, 127, -117, -111}; Plane Surface(110) = {110};
Curve Loop(111) = {116, 122, -117, -106}; Surface(111) = {111};
// Shell Y: hull, top, x = 0, the face towards shell Z.
Curve Loop(112) = {115, 121, -114, -103}; Surface(112) = {112} In Sphere {115};
Curve Loop(113) = {128, 123, -127, -121}; Plane Surface(113) = {113};
Curve Loop(114) = {115, 128, -118, -112}; Plane Surface(114) = {114};
Curve Loop(115) = {118, 123, -117, -107}; Surface(115) = {115};
// Shell Z: top, y = 0, x = 0.
Curve Loop(116) = {124, 122, -123, -125}; Plane Surface(116) = {116};
Curve Loop(117) = {105, 116, -124, -119}; Plane Surface(117) = {117};
Curve Loop(118) = {108, 118, -125, -119}; Plane Surface(118) = {118};

Transfinite Surface{101} = {101, 102, 103, 104};
Transfinite Surface{102} = {105, 106, 107, 108};
Transfinite Surface{103} = {101, 102, 106, 105};
Transfinite Surface{104} = {102, 103, 107, 106};
Transfinite Surface{105} = {104, 103, 107, 108};
Transfinite Surface{106} = {101, 104, 108, 105};
Transfinite Surface{107} = {102, 109, 110, 103};
Transfinite Surface{108} = {109, 112, 113, 110};
Transfinite Surface{109} = {102, 109, 112, 106};
Transfinite Surface{110} = {103, 110, 113, 107};
Transfinite Surface{111} = {106, 112, 113, 107};
Transfinite Surface{112} = {104, 111, 110, 103};
Transfinite Surface{113} = {111, 114, 113, 110};
Transfinite Surface{114} = {104, 111, 114, 108};
Transfinite Surface{115} = {108, 114, 113, 107};
Transfinite Surface{116} = {115, 112, 113, 114};
Transfinite Surface{117} = {105, 106, 112, 115};
Transfinite Surface{118} = {105, 108, 114, 115};
Recombine Surface{101:118};

Surface Loop(101) = {101, 102, 103, 104, 105, 106};    Volume(101) = {101};
Surface Loop(102) = {104, 107, 108, 109, 110, 111};    Volume(102) = {102};
Surface Loop(103) = {105, 112, 113, 114, 110, 115};    Volume(103) = {103};
Surface Loop(104) = {102, 116, 117, 118, 111, 115};    Volume(104) = {104};
Transfinite Volume{101} = {101, 102, 103, 104, 105, 106, 107, 108};
Transfinite Volume{102} = {102, 103, 107, 106, 109, 110, 113, 112};
Transfinite Volume{103} = {104, 103, 107, 108, 111, 110, 113, 114};
Transfinite Volume{104} = {105, 106, 107, 108, 115, 112, 113, 114};
Recombine Volume{101:104};

Physical Volume("sphere", 1) = {101:104};
Physical Volume("block", 2) = {1:4};
Physical Surface("sphere contact surface", 1) = {101};
Physical Surface("block contact surface", 2) = {1};
Physical Surface("sphere top", 3) = {108, 113, 116};
Physical Surface("block bottom", 4) = {16};
Physical Surface("symmetry x = 0", 5) = {6, 14, 18, 106, 114, 118};
Physical Surface("symmetry y = 0", 6) = {3, 9, 17, 103, 109, 117};
Physical Surface("other faces", 7) = {7, 8, 12, 13, 107, 112};
