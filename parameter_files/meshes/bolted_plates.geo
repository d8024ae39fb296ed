// A bolt clamping two plates, full 360 degree model, the axis along z.
// Lengths in mm.
//
// - Bolt (M16): shank radius 8 from z = 0 to z = 20 (through both plates),
//   head radius 12, height 10 on top of the plates (z from 20 to 30), nut
//   radius 12, height 13 below them (z from -13 to 0). One part, one
//   conforming mesh (head, shank and nut share their nodes).
// - Lower plate: z from 0 to 10; upper plate: z from 10 to 20. Both are
//   round discs of outer radius 30 with a hole of radius 8.5: a radial gap
//   of 0.5 between shank and plates that is not meshed (the shank shares no
//   node with the plates).
// - Bonded, conforming interfaces: the two plates share their nodes at
//   z = 10; the head's underside shares the nodes of the upper plate's top
//   (z = 20) and the nut's top those of the lower plate's bottom (z = 0)
//   over the annulus 8.5 <= r <= 12. Over 8 < r < 8.5 the head and the nut
//   are bolt material bridging shank and head / nut; between z = 0 and
//   z = 20 that annulus is the empty gap.
//
// Physical volumes: 1 = bolt, 2 = upper plate, 3 = lower plate.
// Physical surfaces (every boundary face in exactly one):
//   1 = support: the lower plate's bottom outside the nut (z = 0,
//       12 <= r <= 30);
//   2 = plate top: the upper plate's top outside the head (z = 20,
//       12 <= r <= 30);
//   3 = bolt surface: every free face of the bolt (head top and side, the
//       head's underside and the nut's top over 8 < r < 8.5, the shank's
//       side r = 8 in the gap, nut side and bottom);
//   4 = plate surfaces: every other boundary face of the plates (the outer
//       rims r = 30 and the hole walls r = 8.5).
// The bonded interfaces are not boundaries and carry no tag.
//
// Cross-section (xy-plane; each level holds some of its parts, see below):
// an O-grid, 24 elements around (6 per quarter) on every ring,
//   core: a square of half-diagonal c = 4 sqrt(2) with its corners on the
//         x and y axes, 6 x 6 elements (no wedge at the axis);
//   ring A: core square -> r = 8 (shank surface), 2 elements radially;
//   ring B: r = 8 -> 8.5 (the gap), 1 element;
//   ring C: r = 8.5 -> 12 (hole -> head / nut rim), 2 elements;
//   ring D: r = 12 -> 30 (plate rim), 4 elements graded geometrically
//           (ratio (30 / 12)^(1/4), so that the cells stay near square).
// The hulls are polygons of 24 flat facets (the reader attaches no
// manifold): the areas are (24 / 2) sin(2 pi / 24) / pi = 0.9886 of the
// circles' (1.14 % short; so are the volumes).
//
// Levels along z and the parts of the cross-section they hold:
//   nut    z -13 .. 0   core, A, B, C   6 layers of 13 / 6
//   plates z 0 .. 20    core, A (shank); C, D (plates)
//                       4 + 4 layers of 2.5
//   head   z 20 .. 30   core, A, B, C   5 layers of 2
// The shank's (and the plates') element layers end at z = 0, 2.5, 5, 7.5,
// 10, 12.5, 15, 17.5, 20: a section plane through the middle of a layer,
// e.g. z = 3.75 (in the lower plate), holds no node.
// Cells per level of the cross-section: core 36, A 48, B 24, C 48, D 96.
// Hexahedra: nut 156 x 6 + shank 84 x 8 + plates 144 x 8 + head 156 x 5 =
// 3540 (bolt 2388, each plate 576); the longest edge is at most 4.5 times
// the shortest in every cell (the gap ring B is 0.5 thick).
//
// Built by extrusion with Layers (exact node positions; see bar.geo): the
// radial line on the x axis from r = 8 to 30 (points at 8.5 and 12),
// rotated by 90 degrees four times about the axis (as tube.geo; Coherence
// merges the last lines with the first), gives the rings B, C and D; the
// core square and the ring A are transfinite surfaces (straight sides,
// Transfinite Curve, whose nodes Gmsh places to about 1e-10 mm) on the
// arcs r = 8 of the ring B. The whole
// cross-section at z = 0 is extruded to z = 10 and on to z = 20, the
// cross-section without ring D down to z = -13 (the nut) and, from z = 20,
// up to z = 30 (the head). The ring B between z = 0 and 20 (the gap) is
// extruded too, so that its top at z = 20 is the head's underside there,
// then deleted (Delete removes only the volumes, not their faces): no
// hexahedron fills the gap, the shank's side r = 8 and the hole wall
// r = 8.5 are boundaries.
r_shank = 8.; r_hole = 8.5; r_head = 12.; r_plate = 30.;
t_plate = 10.; h_head = 10.; h_nut = 13.;
c = r_shank / Sqrt(2.);      // the core square's half-diagonal
n_quarter = 6;               // elements per quarter circle
n_a = 2; n_c = 2; n_d = 4;   // elements radially in the rings A, C, D
n_plate = 4; n_head = 5; n_nut = 6;
eps = 1e-6 * r_plate;

// Ring D's node fractions: geometric, ratio q = (r_plate / r_head)^(1/n_d).
q = (r_plate / r_head)^(1. / n_d);
d_counts[] = {};
d_fracs[] = {};
For k In {1:n_d}
  d_counts[] += 1;
  If (k < n_d)
    d_fracs[] += r_head * (q^k - 1.) / (r_plate - r_head);
  Else
    d_fracs[] += 1.;
  EndIf
EndFor

// The radial line on the x axis, r = 8 -> 8.5 -> 12 -> 30.
Point(1) = {r_shank, 0., 0.};
b[] = Extrude {r_hole - r_shank, 0., 0.} { Point{1}; Layers{1}; };
cr[] = Extrude {r_head - r_hole, 0., 0.} { Point{b[0]}; Layers{n_c}; };
dr[] = Extrude {r_plate - r_head, 0., 0.} {
  Point{cr[0]}; Layers{ {d_counts[]}, {d_fracs[]} };
};

// Rings B, C, D: four rotations by 90 degrees. Extrude returns, for each
// curve, its rotated copy, the surface and the two arcs.
ring_b[] = {}; ring_c[] = {}; ring_d[] = {};
lines[] = {b[1], cr[1], dr[1]};
For quarter In {0:3}
  out[] = Extrude {{0., 0., 1.}, {0., 0., 0.}, Pi / 2.} {
    Curve{lines[]}; Layers{n_quarter}; Recombine;
  };
  ring_b[] += out[1]; ring_c[] += out[5]; ring_d[] += out[9];
  lines[] = {out[0], out[4], out[8]};
EndFor
Coherence;

// The arcs r = 8 (ring B's inner arcs), one per quarter k (from the angle
// k 90 degrees to (k + 1) 90 degrees), and their end points on the axes.
For k In {0:3}
  bnd[] = Boundary{ Surface{ring_b[k]}; };  // line, outer arc, -line, -arc
  arc[k] = Abs(bnd[3]);
  ends[] = Boundary{ Curve{arc[k]}; };
  rim[k] = ends[0];
EndFor

// The core square (corners on the axes) and ring A.
corner[] = {};
corner[] += newp; Point(newp) = {c, 0., 0.};
corner[] += newp; Point(newp) = {0., c, 0.};
corner[] += newp; Point(newp) = {-c, 0., 0.};
corner[] += newp; Point(newp) = {0., -c, 0.};
For k In {0:3}
  side[k] = newl; Line(side[k]) = {corner[k], corner[(k + 1) % 4]};
  spoke[k] = newl; Line(spoke[k]) = {corner[k], rim[k]};
EndFor
Transfinite Curve {side[]} = n_quarter + 1;
Transfinite Curve {spoke[]} = n_a + 1;

// Every curve loop counter-clockwise seen from +z.
loop = newll;
Curve Loop(loop) = {side[]};
core = news;
Plane Surface(core) = {loop};
Transfinite Surface {core} = {corner[]};
ring_a[] = {};
For k In {0:3}
  loop = newll;
  Curve Loop(loop) = {spoke[k], arc[k], -spoke[(k + 1) % 4], -side[k]};
  s = news;
  Plane Surface(s) = {loop};
  Transfinite Surface {s} = {corner[k], rim[k], rim[(k + 1) % 4],
                             corner[(k + 1) % 4]};
  ring_a[] += s;
EndFor
Recombine Surface {core, ring_a[]};

// Along z. Extrude returns, for each surface, the top, the volume and the
// four lateral surfaces: 6 entries.
section[] = {core, ring_a[], ring_b[], ring_c[], ring_d[]};  // 17
lower[] = Extrude {0., 0., t_plate} {
  Surface{section[]}; Layers{n_plate}; Recombine;
};
mid[] = {};
For i In {0:16}
  mid[] += lower[6 * i];
EndFor
upper[] = Extrude {0., 0., t_plate} {
  Surface{mid[]}; Layers{n_plate}; Recombine;
};
// The entries 0 (core), 1-4 (A), 5-8 (B, the gap), 9-12 (C), 13-16 (D).
shank[] = {}; gap[] = {}; plate_lower[] = {}; plate_upper[] = {};
top[] = {}; plate_top[] = {};
For i In {0:16}
  If (i <= 4)
    shank[] += {lower[6 * i + 1], upper[6 * i + 1]};
  ElseIf (i <= 8)
    gap[] += {lower[6 * i + 1], upper[6 * i + 1]};
  Else
    plate_lower[] += lower[6 * i + 1];
    plate_upper[] += upper[6 * i + 1];
  EndIf
  If (i <= 12)
    top[] += upper[6 * i];             // z = 20, r <= 12
  Else
    plate_top[] += upper[6 * i];       // z = 20, r >= 12
  EndIf
EndFor

head[] = {};
out[] = Extrude {0., 0., h_head} { Surface{top[]}; Layers{n_head}; Recombine; };
For i In {0:12}
  head[] += out[6 * i + 1];
EndFor
nut[] = {};
bottom[] = {core, ring_a[], ring_b[], ring_c[]};
out[] = Extrude {0., 0., -h_nut} {
  Surface{bottom[]}; Layers{n_nut}; Recombine;
};
For i In {0:12}
  nut[] += out[6 * i + 1];
EndFor

// The gap: no hexahedra (its faces stay, shared with shank, plates, head).
Delete { Volume{gap[]}; }

bolt[] = {nut[], shank[], head[]};
plates[] = {plate_upper[], plate_lower[]};
// The bonded interfaces bolt / plates: ring C at z = 0 and at z = 20.
bonded[] = {ring_c[]};
For i In {9:12}
  bonded[] += upper[6 * i];
EndFor
// Check the selections against boxes: ring D at z = 0 and 20, ring C at
// z = 0 and 20 (r <= 12 and r >= 8.5 in the plane: the surfaces in the box
// |x|, |y| <= 12 minus those in |x|, |y| <= 8.5, which are core, A, B).
support[] = Surface In BoundingBox {-r_plate - eps, -r_plate - eps, -eps,
                                    r_plate + eps, r_plate + eps, eps};
support[] -= Surface In BoundingBox {-r_head - eps, -r_head - eps, -eps,
                                     r_head + eps, r_head + eps, eps};
If (#support[] != 4 || #plate_top[] != 4 || #bonded[] != 8)
  Error("bolted_plates.geo: unexpected surface selection");
EndIf

bolt_surface[] = Abs(CombinedBoundary{ Volume{bolt[]}; });
bolt_surface[] -= {bonded[]};
plate_surface[] = Abs(CombinedBoundary{ Volume{plates[]}; });
plate_surface[] -= {bonded[], support[], plate_top[]};

Physical Volume("bolt", 1) = {bolt[]};
Physical Volume("upper plate", 2) = {plate_upper[]};
Physical Volume("lower plate", 3) = {plate_lower[]};
Physical Surface("support", 1) = {support[]};
Physical Surface("plate top", 2) = {plate_top[]};
Physical Surface("bolt surface", 3) = {bolt_surface[]};
Physical Surface("plate surfaces", 4) = {plate_surface[]};
