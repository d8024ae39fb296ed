// Ironing (Puso & Laursen 2004, example 2; LLNL smith's die-on-slab
// driver), plane strain: a slice of thickness t along y, one element
// through it, with symmetry faces y = 0 and y = t. The cross-section is the
// x-z plane of the 3D set-up: the slab [0, 9] x [0, 3] (9 long, 3 high),
// the die a cylindrical shell segment (a curved plate) of outer radius R =
// 3, thickness 0.2 and chord 5.2 (+-60.07 degrees about its lowest line),
// its axis along y through (2.5, 0, 3 + g0 + R): centred 2.5 from the
// slab's left end (so that its left edge, at x = -0.1, overhangs the
// slab's end), its lowest line g0 = 0.001 above the slab's top (separate
// nodes; Gmsh's built-in kernel would merge a touching point).
//
// Slab: 90 x 30 uniform elements (0.1 x 0.1). Die: 63 elements along
// each half of the hull (2 x 63, 0.0499 along the outer hull), 2 through
// its thickness (0.1). The die's hull is the slave side of the mortar
// pair: it is the finer one (facets of 0.05 against the slab's 0.1), and
// its contact patch moves with it: the slave nodes in contact stay nearly
// the same while it slides (91 to 108 of its 127 lines of hull nodes),
// instead of slab nodes entering and leaving the patch at every step.
//
// With with_die = 0 (meshes/ironing_slab.geo) only the slab is meshed, for
// the node-to-surface variant with a rigid cylinder.
//
// Physical volumes: 1 = slab, 2 = die.
// Physical surfaces: 1 = the slab's bottom z = 0, 2 = the slab's top z = 3
// (master), 3 = the die's outer hull r = 3 (slave), 4 = the die's inner
// face r = 2.8 (driven), 5 = the face y = 0 (both), 6 = the face y = t
// (both), 7 = the other faces (the slab's ends x = 0 and x = 9, the die's
// two edges).
// L and nx can be set from the command line (gmsh -setnumber L 18
// -setnumber nx 180: benchmarks/ironing.sh's longer slab, the same 0.1
// elements, for a stretch of steady sliding free of the slab's ends).
DefineConstant[ with_die = 1, L = 9., nx = 90 ];
// L: slab length (x); nx: slab elements along x
H = 3.;         // slab height (z)
nz = 30;        // slab elements along z
t = 0.1;        // slice thickness (y)
R = 3.;         // die: outer radius
th = 0.2;       // die: thickness
w = 5.2;        // die: chord of the outer hull
x0 = 2.5;       // die: axis position
g0 = 0.001;     // die: initial gap
na = 63;        // die: elements along each half of the hull
nr = 2;         // die: elements through the thickness
eps = 1e-6;

// ---- Slab, y = 0 cross-section (built by extrusion: exact node positions).
Point(1) = {0., 0., 0.};
bottom_line[] = Extrude {L, 0., 0.} { Point{1}; Layers{nx}; };
section[] = Extrude {0., 0., H} { Curve{bottom_line[1]}; Layers{nz}; Recombine; };
slab[] = Extrude {0., t, 0.} { Surface{section[1]}; Layers{1}; Recombine; };

If (with_die)
  // ---- Die, y = 0 cross-section: centre (x0, zc), half angle a.
  zc = H + g0 + R;
  a = Asin(w / (2. * R));
  ri = R - th;
  Point(1011) = {x0, 0., zc};  // centre
  Point(1012) = {x0 - R * Sin(a), 0., zc - R * Cos(a)};  // outer, left end
  Point(1013) = {x0, 0., zc - R};  // outer, lowest
  Point(1014) = {x0 + R * Sin(a), 0., zc - R * Cos(a)};  // outer, right end
  Point(1015) = {x0 - ri * Sin(a), 0., zc - ri * Cos(a)};  // inner, left end
  Point(1016) = {x0, 0., zc - ri};  // inner, lowest
  Point(1017) = {x0 + ri * Sin(a), 0., zc - ri * Cos(a)};  // inner, right end
  Circle(1011) = {1012, 1011, 1013};
  Circle(1012) = {1013, 1011, 1014};
  Circle(1013) = {1015, 1011, 1016};
  Circle(1014) = {1016, 1011, 1017};
  Line(1015) = {1012, 1015};
  Line(1016) = {1013, 1016};
  Line(1017) = {1014, 1017};
  Transfinite Curve{1011, 1012, 1013, 1014} = na + 1;
  Transfinite Curve{1015, 1016, 1017} = nr + 1;
  Curve Loop(1011) = {1011, 1016, -1013, -1015};
  Plane Surface(1011) = {1011};
  Curve Loop(1012) = {1012, 1017, -1014, -1016};
  Plane Surface(1012) = {1012};
  Transfinite Surface{1011} = {1012, 1013, 1016, 1015};
  Transfinite Surface{1012} = {1013, 1014, 1017, 1016};
  Recombine Surface{1011, 1012};
  // Extrude returns per surface: the far face, the volume, then the faces
  // swept by the loop's curves in order (hull, radial, inner, radial).
  die_left[] = Extrude {0., t, 0.} { Surface{1011}; Layers{1}; Recombine; };
  die_right[] = Extrude {0., t, 0.} { Surface{1012}; Layers{1}; Recombine; };
EndIf

// ---- Boundary faces.
bottom[] = Surface In BoundingBox {-eps, -eps, -eps, L + eps, t + eps, eps};
top[] = Surface In BoundingBox {-eps, -eps, H - eps, L + eps, t + eps, H + eps};
front[] = Surface In BoundingBox {-L, -eps, -eps, 2 * L, eps, H + 2 * R + 1};
back[] = Surface In BoundingBox {-L, t - eps, -eps, 2 * L, t + eps, H + 2 * R + 1};
others[] = Abs(CombinedBoundary{ Volume{slab[1]}; });
If (with_die)
  hull[] = {die_left[2], die_right[2]};
  inner[] = {die_left[4], die_right[4]};
  others[] += Abs(CombinedBoundary{ Volume{die_left[1], die_right[1]}; });
  others[] -= {hull[], inner[]};
EndIf
others[] -= {bottom[], top[], front[], back[]};

Physical Volume("slab", 1) = {slab[1]};
Physical Surface("slab bottom", 1) = {bottom[]};
Physical Surface("slab top", 2) = {top[]};
If (with_die)
  Physical Volume("die", 2) = {die_left[1], die_right[1]};
  Physical Surface("die hull", 3) = {hull[]};
  Physical Surface("die inner face", 4) = {inner[]};
EndIf
Physical Surface("face y = 0", 5) = {front[]};
Physical Surface("face y = t", 6) = {back[]};
Physical Surface("other faces", 7) = {others[]};
