// The rubber bushing assembly of the drop-tower study (issue 10; the study's
// chapters 5-6, ../../doc/bushing.md): an M16 bolt with its big nut and a
// washer clamping the aluminium inner sleeve of a rubber bushing against a
// sheet-metal brace; the rubber body with its two end lips, a plastic and a
// metal outer sleeve; the plate hit by the drop weight, held by the metal
// sleeve at one end and lying on a support at the other, its last
// clamp_size bolted to the support; the drop weight.
// Full 3D model, hexahedra only. Lengths in mm.
//
// The study's CAD is not public. This layout and every default below are
// our reconstruction, chosen to resemble a subframe bushing for an M16
// bolt; each parameter carries a one-line reason. Every parameter can be
// changed with gmsh -setnumber NAME VALUE (DefineConstant).
//
// Frame: z is the bolt axis, z up; the drop weight falls along -z. z = 0
// is the washer's top face (= the inner sleeve's bottom end). The plate
// leaves the bushing along +x; the brace reaches out along -x and +-y.
//
// The section y = 0, x >= 0, with the defaults (not to scale; the same
// drawing as doc/bushing.md):
//
//   z
//   78   +----+                                        +-----------+ 73
//        |head|                                        |   drop    |
//   68   +----+--+-------------------+                 |  weight   |
//        |    |  :  brace (t 8)      | x = 45          | x 100-160 |
//   60   |    |  +------+------------+---+             +-----------+ 33
//        |    |  |inner | rubber lip     |               gap 0.5
//   54   |    |  |sleeve|        +--+--+-+
//        |    |  |      |        |p |m |
//        |bolt|  |      | rubber |l |e |
//  32.5  |    |  |      |        |a |t +=================================+
//  27.5  |    |  |      |        |s |a +========= plate ===========+-----+
//        |    |  |      |        |t |l |                          | sup-|
//    6   |    |  |      |        +--+--+-+                        | port|
//        |    |  |      | rubber lip     |                        +-----+ 7.5
//    0   |    |  +------+--+-------------+
//        |    |  washer    |
//   -4   +----+------+-----+
//        |  nut      |
//  -18   +----+------+
//        |end |
//  -24   +----+
//        0    8 8.5  14    25 27.5 29.5 32.5      45         260   300   x
//
// Which parts share nodes (one conforming mesh) and why:
// - bolt (head and shank) and nut: the thread is not modelled; a nut that
//   shares the shank's nodes over its bore is the simplest joint that
//   carries the preload (as bolted_plates.geo). The nut is a part of its
//   own (material id 2), so that it can be held and its material chosen.
// - rubber and inner sleeve: the rubber is vulcanised onto the aluminium;
//   the study ties only rubber and plastic sleeve, so this bond is
//   conforming.
// - metal outer sleeve and plate: the sleeve is pressed into the plate's
//   eye; sharing the nodes of the eye keeps the plate's mesh simple.
// Every other pair of touching parts has nodes of its own, meshed
// differently where they touch (contact or tied pairs later): bolt /
// brace, bolt / inner sleeve, bolt / washer (the 0.5 mm hole clearance is
// not meshed); head / brace top; brace / inner sleeve end and rubber lip;
// washer / inner sleeve end and rubber lip; nut / washer; rubber /
// plastic sleeve (tied later); plastic / metal sleeve (contact: the
// pull-out); sleeve ends / lips; plate / support; plate / drop weight
// (gap weight_gap). Faces of clamped or stacked parts coincide (gap 0).
//
// How parts keep nodes of their own: Gmsh's built-in kernel merges
// coincident points, and with them curves and surfaces (Geometry.
// AutoCoherence, needed to close the rotations and to join the blocks of
// one part). So each part (or conforming group) is built in a staging
// box of its own, shifted along z by stage_shift * its stage number, and
// all but the first are translated back with AutoCoherence switched off.
// The shifts are whole numbers and the parts' base heights are the
// parameters' values, so the translations are exact in floating point
// for the defaults; extruded nodes are placed at mesh time, in place.
// (The rotations' mesh nodes can land one unit in the last place off
// their plane: the brace's hole nodes are at z = 59.99999999999999.)
//
// Cells (tests/io/bushing_mesh.cc checks them and every volume and area):
// n = 1: 7394 (bolt 2340, nut 192, washer 336, inner sleeve 768, rubber
// 1344, plastic sleeve 576, metal sleeve 576, plate 300, brace 612,
// support 210, drop weight 140); n = 2: 28 680 (4608, 672, 1344, 2880,
// 9792, 2304, 2304, 1200, 2376, 720, 480).
//
// Cross-sections: an O-grid, 4 n_quarter elements around every round
// part but bolt and nut, which have 4 bolt_quarter around (all start at
// 45 degrees, so that a quarter faces one side of a square). Round hulls
// are polygons of N flat facets (N = 4 n_quarter, or 4 bolt_quarter for
// bolt and nut) with their corners on the circles: an annulus a < r < b
// has the area (N / 2) sin(2 pi / N) (b^2 - a^2), short of the circles'
// by 1.14 % at N = 24 (n = 1; bolt and nut at every n) and 0.29 % at
// N = 48 (n = 2) (see bolted_plates.geo). The bolt's core is a square
// (half-width bolt_radius / 2) with a ring A to r = bolt_radius; the
// brace's hole and the plate's eye are O-grid rings blended into
// squares, and blocks make the rest of the plates.
//
// Tags (parameter_files/meshes/README.md): physical volume = material id,
// physical surface = boundary id; every boundary face is in exactly one.
//   Volumes: 1 bolt (head + shank), 2 nut, 3 washer, 4 inner sleeve,
//   5 rubber, 6 plastic outer sleeve, 7 metal outer sleeve, 8 plate,
//   9 brace, 10 support, 11 drop weight.
//   Surfaces:
//    1 bolt shank side r = bolt_radius between nut top and head
//    2 head underside (z = L + t_brace)   3 bolt end (the shank's end face)
//    4 bolt's other free faces (head top and side, the end's side)
//    5 nut top (z = -t_washer)            6 nut's other free faces
//    7 washer top (z = 0)   8 washer bottom   9 washer hole wall and rim
//   10 inner sleeve top end (z = L)  11 its bottom end (z = 0)  12 its bore
//   13 rubber top lip face (z = L)   14 rubber bottom lip face (z = 0)
//   15 rubber outer face r = rubber_radius (between the lips)
//   16 the lips' inner faces (z = lip_height, L - lip_height), which the
//      outer sleeves' ends touch     17 the lips' rims
//   18 plastic sleeve inner  19 plastic sleeve outer  20 its ends
//   21 metal sleeve inner  22 metal sleeve outer (off the plate)  23 ends
//   24 plate top (but its clamp patch)   25 plate bottom
//   26 plate's other free faces (edges)
//   27 brace underside (z = L)   28 brace top (but the clamp patches)
//   29, 30, 31 the clamp patches on the brace top: back (-x), front +y,
//      front -y   32 brace hole wall   33 brace rims
//   34 support top   35 support's other faces
//   36 drop weight bottom   37 drop weight's other faces
//   38 plate clamp: the plate's top over its last clamp_size (bolted to
//      the support)
//
// Mesh density: n multiplies the element counts (n = 1: a coarse mesh of
// a few thousand cells for tests; the default n = 2 is the study's mesh)
// but two: the thin parts (sleeves, washer, brace, plate) have n_thin = 2
// elements through their thickness, and the bolt's and nut's cross-section
// has bolt_quarter = 6 elements per quarter circle at every n, so that no
// steel element is much below 1 mm (the explicit time step). The other
// counts follow element sizes of about 4 / n (axial, radial) and 10 / n
// to 15 / n (in the plane of brace and plate).

// ------------------------------------------------------------ parameters
// Each with its reason (doc/bushing.md has the same table).
// Mesh density: 2 is the study's mesh, 1 the tests' coarse mesh.
DefineConstant[ n = 2 ];
// Elements through the thickness of the thin parts (sleeves, washer,
// brace, plate): at least 2 (the issue's minimum). 2 at every n keeps the
// thinnest steel element, the metal sleeve's, 1 mm thick (2 n made it
// 0.5 mm at n = 2 and halved the explicit time step).
DefineConstant[ n_thin = 2 ];
// Elements per quarter circle of bolt, nut and head (the bolt's core a
// square of bolt_quarter x bolt_quarter cells, its ring to r =
// bolt_radius 2 bolt_quarter / 6 elements radially): 6 keeps the bolt's
// smallest edge at 1.17 mm (the ring's corner cells; the core's cells
// 1.33 mm), which 6 n made 0.59 mm at n = 2. At least 2.
DefineConstant[ bolt_quarter = 6 ];
// Bolt M16 x 2, grade 10.9 (ISO 4014):
//   nominal diameter 16;
DefineConstant[ bolt_radius = 8. ];
//   17 mm medium clearance hole (ISO 273), also the washer's and the inner
//   sleeve's bore;
DefineConstant[ hole_radius = 8.5 ];
//   the hex head, 24 across flats, as a cylinder;
DefineConstant[ head_radius = 12. ];
//   M16 head height k = 10;
DefineConstant[ head_height = 10. ];
//   the thread protruding below the nut, pulled in the preload.
DefineConstant[ bolt_end_length = 6. ];
// Nut: a big flange nut, 30 across, a little higher than m = 13 of an
// M16 nut.
DefineConstant[ nut_radius = 15. ];
DefineConstant[ nut_height = 14. ];
// Washer: a stiff steel disc, the bushing's axial stop: it covers the
// lower lip (r = 32.5) and the metal sleeve's end (a disc of radius 30,
// 0.5 beyond the sleeve, let the tilted sleeve slide off its rim).
DefineConstant[ washer_radius = 36. ];
DefineConstant[ washer_thickness = 4. ];
// Inner sleeve: an aluminium tube, wall 5.5, the bushing's clamped
// length L = 60.
DefineConstant[ inner_sleeve_radius = 14. ];
DefineConstant[ inner_sleeve_length = 60. ];
// Rubber: a wall of 11, as a subframe bushing's; lips 6 thick reaching
// 3 beyond the metal sleeve.
DefineConstant[ rubber_radius = 25. ];
DefineConstant[ lip_radius = 32.5 ];
DefineConstant[ lip_height = 6. ];
// Outer sleeves: a plastic one and a thin steel one around it.
DefineConstant[ plastic_thickness = 2.5 ];
DefineConstant[ metal_thickness = 2. ];
// Plate hit by the drop weight: 5 thick as the study's tests 2-4 (test 1:
// 4), its mid-plane at the sleeves' mid-height, 90 wide (15.5 of plate
// beside the eye), its far end at x = 300 on the support.
DefineConstant[ plate_thickness = 5. ];
DefineConstant[ plate_z = inner_sleeve_length / 2. ];
DefineConstant[ plate_half_width = 45. ];
DefineConstant[ plate_end = 300. ];
// Brace: a steel bracket 8 thick above the bushing (a 4 mm sheet folded
// under the head by 22 mm in 6 ms of test 4, doc/bushing.md "The rig"),
// reaching x = -brace_back and y = +-brace_half_width; the O-grid square
// around the hole has the half-width brace_square; the clamped (bolted)
// areas are clamp_size wide, as is the plate's bolted end on the support.
DefineConstant[ brace_thickness = 8. ];
DefineConstant[ brace_square = 25. ];
DefineConstant[ brace_back = 90. ];
DefineConstant[ brace_half_width = 85. ];
DefineConstant[ clamp_size = 20. ];
// Support: a block (rigid later) under the plate's far end.
DefineConstant[ support_length = 40. ];
DefineConstant[ support_height = 20. ];
// Drop weight: a block (rigid later) above the plate from x = weight_x,
// centred on y = 0, weight_gap above the plate's top.
DefineConstant[ weight_x = 100. ];
DefineConstant[ weight_length = 60. ];
DefineConstant[ weight_width = 60. ];
DefineConstant[ weight_height = 40. ];
DefineConstant[ weight_gap = 0.5 ];
// The edges of the drop weight's bottom and of the support's top that run
// across the plate (along y) are rounded with this radius, twice the
// plate's thickness, as bending tools' are: a sharp rigid edge cuts into
// the plate's facets where it folds (doc/bushing.md, "The rig"). 0: sharp
// edges.
DefineConstant[ edge_radius = 10. ];
// Flat facets along each rounded edge (a quarter circle; even), the same
// at every n: the drop weight's volume, and with it its density for a
// given mass, does not depend on the mesh.
DefineConstant[ edge_facets = 8 ];
// The pretension section: a plane across the shank between washer (z = 0)
// and brace (z = L), inside the inner sleeve. A layer of shank elements
// (4 / n high) is centred on it, so that the plane cuts that layer's
// elements halfway and lies on no element face (doc/quasi_static.md,
// "Bolt pretension": a plane on element faces cuts none).
DefineConstant[ section_z = inner_sleeve_length / 2. ];

// -------------------------------------------------- derived and checked
L = inner_sleeve_length;
plastic_radius = rubber_radius + plastic_thickness;   // plastic sleeve's outer
metal_radius = plastic_radius + metal_thickness;      // metal sleeve's outer
plate_bottom = plate_z - plate_thickness / 2.;
plate_top = plate_z + plate_thickness / 2.;
z_nut_top = -washer_thickness;
z_nut_bottom = z_nut_top - nut_height;
z_end = z_nut_bottom - bolt_end_length;
z_head = L + brace_thickness;                         // the head's underside
c45 = Sqrt(0.5);
eps = 1e-6;

If (n < 1 || n != Floor(n))
  Error("bushing.geo: n must be a positive integer"); Abort;
EndIf
If (n_thin < 2 || n_thin != Floor(n_thin))
  Error("bushing.geo: n_thin must be an integer of at least 2"); Abort;
EndIf
If (bolt_quarter < 2 || bolt_quarter != Floor(bolt_quarter))
  Error("bushing.geo: bolt_quarter must be an integer of at least 2");
  Abort;
EndIf
If (!(bolt_radius < hole_radius && hole_radius < head_radius &&
      head_radius <= nut_radius && hole_radius < inner_sleeve_radius &&
      inner_sleeve_radius < rubber_radius && metal_radius < lip_radius &&
      hole_radius < washer_radius))
  Error("bushing.geo: the radii must increase outwards"); Abort;
EndIf
If (!(2. / n < section_z && section_z < L - 2. / n))
  Error("bushing.geo: section_z's element layer must lie within 0 < z < L");
  Abort;
EndIf
If (!(lip_height < plate_bottom && plate_top < L - lip_height))
  Error("bushing.geo: the plate must lie between the lips"); Abort;
EndIf
// The plate's eye fits in its square, the drop weight lies between the
// bushing and the support and clear of the brace, and the brace covers
// the upper lip on every side.
If (!(metal_radius + 1. < plate_half_width &&
      plate_half_width < weight_x && weight_x + weight_length <
      plate_end - support_length && brace_square + clamp_size < weight_x &&
      clamp_size < support_length &&
      hole_radius < brace_square && lip_radius < brace_square + clamp_size &&
      lip_radius < brace_half_width && lip_radius < brace_back))
  Error("bushing.geo: inconsistent plate, brace or drop weight extents");
  Abort;
EndIf
If (!(edge_radius >= 0. && 2. * edge_radius < weight_length &&
      2. * edge_radius < support_length && edge_radius < weight_height &&
      edge_radius < support_height))
  Error("bushing.geo: edge_radius must lie between 0 and half the drop "
        "weight's and the support's length and below their heights");
  Abort;
EndIf
If (edge_facets < 2 || edge_facets % 2 != 0)
  Error("bushing.geo: edge_facets must be an even number of at least 2");
  Abort;
EndIf

// ---------------------------------------------------------- mesh counts
n_quarter = 6 * n;          // elements per quarter circle (24 n around)
ring_q = n_quarter;         // the Rings macro's elements per quarter
axial_size = 4. / n;        // element length along the axis and radially
plane_size = 10. / n;       // in the brace's plane
plate_size = 15. / n;       // in the plate's plane (its O-grid side: 90 / 6n)

// count = Max(1, Round(count_length / count_size)), a macro's result.
Macro Count
  count = Round(count_length / count_size);
  If (count < 1)
    count = 1;
  EndIf
Return

// The staging boxes (see the header): stage k is built at z + k
// stage_shift, far above everything else.
stage_shift = 1000. * Ceil((z_head + head_height - z_end + 1000.) / 1000.);

// ---------------------------------------------------------------- macros
// Rings: annular O-grid rings about the z axis. Input ring_r[] (radii,
// increasing), ring_n[] (elements radially in each ring), ring_z, ring_q
// (elements per quarter circle). A radial
// line at 45 degrees (nodes at exact fractions of each ring's width),
// rotated four times by 90 degrees (nodes at exact fractions of the
// angle; the last rotation's line merges with the first). Output
// ring_s[k * #ring_n[] + i]: the surface of ring i in quarter k, from
// 45 + 90 k to 135 + 90 k degrees; the surfaces are counter-clockwise
// seen from +z.
Macro Rings
  rings_p = newp;
  Point(rings_p) = {ring_r[0] * c45, ring_r[0] * c45, ring_z};
  rings_lines[] = {};
  For rings_i In {0:#ring_n[] - 1}
    rings_d = ring_r[rings_i + 1] - ring_r[rings_i];
    rings_e[] = Extrude {rings_d * c45, rings_d * c45, 0.} {
      Point{rings_p}; Layers{ring_n[rings_i]};
    };
    rings_lines[] += rings_e[1];
    rings_p = rings_e[0];
  EndFor
  ring_s[] = {};
  For rings_k In {0:3}
    // For each line: its rotated copy, the surface and the two arcs.
    rings_out[] = Extrude {{0., 0., 1.}, {0., 0., 0.}, Pi / 2.} {
      Curve{rings_lines[]}; Layers{ring_q}; Recombine;
    };
    For rings_i In {0:#ring_n[] - 1}
      ring_s[] += rings_out[4 * rings_i + 1];
      rings_lines[rings_i] = rings_out[4 * rings_i];
    EndFor
  EndFor
Return

// FindArc: the arc of radius arc_R on the boundary of the surface arc_s in
// quarter arc_k, oriented counter-clockwise (from 45 + 90 k degrees).
// Output arc (signed curve tag), arc_start, arc_end (its end points).
Macro FindArc
  arc_bnd[] = Boundary{ Surface{arc_s}; };
  arc_found = 0;
  arc_angle = Pi / 4. + arc_k * Pi / 2.;
  For arc_i In {0:#arc_bnd[] - 1}
    arc_c = Abs(arc_bnd[arc_i]);
    arc_ends[] = Boundary{ Curve{arc_c}; };
    arc_p0[] = Point{arc_ends[0]};
    arc_p1[] = Point{arc_ends[1]};
    If (Abs(Hypot(arc_p0[0], arc_p0[1]) - arc_R) < eps &&
        Abs(Hypot(arc_p1[0], arc_p1[1]) - arc_R) < eps)
      arc_found += 1;
      If (Abs(arc_p0[0] - arc_R * Cos(arc_angle)) < eps &&
          Abs(arc_p0[1] - arc_R * Sin(arc_angle)) < eps)
        arc = arc_c; arc_start = arc_ends[0]; arc_end = arc_ends[1];
      Else
        arc = -arc_c; arc_start = arc_ends[1]; arc_end = arc_ends[0];
      EndIf
    EndIf
  EndFor
  If (arc_found != 1)
    Error("bushing.geo: FindArc found %g arcs of radius %g", arc_found,
          arc_R);
    Abort;
  EndIf
Return

// SquareCore: the bolt's core, a square of half-width core_a (corners at
// 45 + 90 k degrees) with core_q x core_q cells, and ring A from
// its sides to the arcs core_arc[k] (signed, counter-clockwise; end
// points core_rim[k] at 45 + 90 k degrees), core_n elements radially.
// Output core_s[] (the core, then ring A's four quarters).
Macro SquareCore
  core_corner[] = {};
  For core_k In {0:3}
    core_angle = Pi / 4. + core_k * Pi / 2.;
    core_corner[] += newp;
    Point(newp) = {core_a * Sqrt(2.) * Cos(core_angle),
                   core_a * Sqrt(2.) * Sin(core_angle), core_z};
  EndFor
  For core_k In {0:3}
    core_side[core_k] = newl;
    Line(core_side[core_k]) = {core_corner[core_k],
                               core_corner[(core_k + 1) % 4]};
    core_spoke[core_k] = newl;
    Line(core_spoke[core_k]) = {core_corner[core_k], core_rim[core_k]};
  EndFor
  Transfinite Curve {core_side[]} = core_q + 1;
  Transfinite Curve {core_spoke[]} = core_n + 1;
  core_loop = newll;
  Curve Loop(core_loop) = {core_side[]};
  core_s[] = {news};
  Plane Surface(core_s[0]) = {core_loop};
  Transfinite Surface {core_s[0]} = {core_corner[]};
  For core_k In {0:3}
    core_loop = newll;
    Curve Loop(core_loop) = {core_spoke[core_k], core_arc[core_k],
                             -core_spoke[(core_k + 1) % 4],
                             -core_side[core_k]};
    core_s[] += news;
    Plane Surface(news) = {core_loop};
    Transfinite Surface {core_s[core_k + 1]} = {
      core_corner[core_k], core_rim[core_k], core_rim[(core_k + 1) % 4],
      core_corner[(core_k + 1) % 4]};
  EndFor
  Recombine Surface {core_s[]};
Return

// HoleGrid: a flat plate at z = grid_z with a round hole, made of blocks
// on the grid grid_x[] x grid_y[] (grid_nx[i] elements along x in column
// i, grid_ny[j] along y in row j); the block (grid_ic, grid_jc), a square
// centred on the axis, holds the hole: an O-grid ring from the hole's
// arcs grid_arc[k] (signed, counter-clockwise, start points
// grid_rim[k] at 45 + 90 k degrees) to the square's sides, grid_m
// elements radially. Block and ring sides are transfinite lines (nodes
// on the straight lines). Output grid_block[i * #grid_ny[] + j] (the
// block's surface; -1 for the square) and grid_s[] (all surfaces).
Macro HoleGrid
  grid_nj = #grid_y[];
  grid_pt[] = {};
  For grid_i In {0:#grid_x[] - 1}
    For grid_j In {0:grid_nj - 1}
      grid_pt[] += newp;
      Point(newp) = {grid_x[grid_i], grid_y[grid_j], grid_z};
    EndFor
  EndFor
  // Lines along x (grid_h) and along y (grid_v), indexed by their start.
  grid_h[] = {}; grid_v[] = {};
  For grid_i In {0:#grid_x[] - 1}
    For grid_j In {0:grid_nj - 1}
      grid_h[] += -1; grid_v[] += -1;
      If (grid_i < #grid_x[] - 1)
        grid_h[grid_i * grid_nj + grid_j] = newl;
        Line(newl) = {grid_pt[grid_i * grid_nj + grid_j],
                      grid_pt[(grid_i + 1) * grid_nj + grid_j]};
        Transfinite Curve {grid_h[grid_i * grid_nj + grid_j]} =
          grid_nx[grid_i] + 1;
      EndIf
      If (grid_j < grid_nj - 1)
        grid_v[grid_i * grid_nj + grid_j] = newl;
        Line(newl) = {grid_pt[grid_i * grid_nj + grid_j],
                      grid_pt[grid_i * grid_nj + grid_j + 1]};
        Transfinite Curve {grid_v[grid_i * grid_nj + grid_j]} =
          grid_ny[grid_j] + 1;
      EndIf
    EndFor
  EndFor
  grid_block[] = {}; grid_s[] = {};
  For grid_i In {0:#grid_x[] - 2}
    For grid_j In {0:grid_nj - 2}
      grid_block[] += -1;
      If (grid_i != grid_ic || grid_j != grid_jc)
        grid_loop = newll;
        Curve Loop(grid_loop) = {grid_h[grid_i * grid_nj + grid_j],
                                 grid_v[(grid_i + 1) * grid_nj + grid_j],
                                 -grid_h[grid_i * grid_nj + grid_j + 1],
                                 -grid_v[grid_i * grid_nj + grid_j]};
        grid_new = news;
        Plane Surface(grid_new) = {grid_loop};
        Transfinite Surface {grid_new};
        grid_block[grid_i * (grid_nj - 1) + grid_j] = grid_new;
        grid_s[] += grid_new;
      EndIf
    EndFor
  EndFor
  // The square's corners at 45 + 90 k degrees and its sides, counter-
  // clockwise: k = 0 the side y = +a (from +x to -x), 1 x = -a, 2 y = -a,
  // 3 x = +a.
  grid_i = grid_ic; grid_j = grid_jc;
  grid_sq[] = {grid_pt[(grid_i + 1) * grid_nj + grid_j + 1],
               grid_pt[grid_i * grid_nj + grid_j + 1],
               grid_pt[grid_i * grid_nj + grid_j],
               grid_pt[(grid_i + 1) * grid_nj + grid_j]};
  grid_side[] = {-grid_h[grid_i * grid_nj + grid_j + 1],
                 -grid_v[grid_i * grid_nj + grid_j],
                 grid_h[grid_i * grid_nj + grid_j],
                 grid_v[(grid_i + 1) * grid_nj + grid_j]};
  If (grid_nx[grid_ic] != n_quarter || grid_ny[grid_jc] != n_quarter)
    Error("bushing.geo: the hole's square needs n_quarter cells a side");
    Abort;
  EndIf
  For grid_k In {0:3}
    grid_spoke[grid_k] = newl;
    Line(newl) = {grid_rim[grid_k], grid_sq[grid_k]};
  EndFor
  Transfinite Curve {grid_spoke[]} = grid_m + 1;
  For grid_k In {0:3}
    grid_loop = newll;
    Curve Loop(grid_loop) = {grid_spoke[grid_k], grid_side[grid_k],
                             -grid_spoke[(grid_k + 1) % 4],
                             -grid_arc[grid_k]};
    grid_new = news;
    Plane Surface(grid_new) = {grid_loop};
    Transfinite Surface {grid_new} = {grid_rim[grid_k], grid_sq[grid_k],
                                      grid_sq[(grid_k + 1) % 4],
                                      grid_rim[(grid_k + 1) % 4]};
    grid_s[] += grid_new;
  EndFor
  Recombine Surface {grid_s[]};
Return

// MakeBlock: an axis-parallel block from (box_x, box_y, box_z), edges box_dx,
// box_dy, box_dz, box_nx x box_ny x box_nz cells, by extrusion (exact node
// positions). Output box_volume, box_bottom, box_top.
Macro MakeBlock
  box_p = newp;
  Point(box_p) = {box_x, box_y, box_z};
  box_l[] = Extrude {box_dx, 0., 0.} { Point{box_p}; Layers{box_nx}; };
  box_f[] = Extrude {0., box_dy, 0.} {
    Curve{box_l[1]}; Layers{box_ny}; Recombine;
  };
  box_v[] = Extrude {0., 0., box_dz} {
    Surface{box_f[1]}; Layers{box_nz}; Recombine;
  };
  box_volume = box_v[1]; box_bottom = box_f[1]; box_top = box_v[0];
Return

// RoundedBlock: a block from (box_x, box_y, box_z), edges box_dx, box_dy,
// box_dz, whose two edges along y on the face z = box_z are rounded with
// the radius box_r (> 0); box_s = +1: the block lies above z = box_z, -1:
// below it. Made as a profile in the xz-plane, extruded along y (box_ny
// cells). Each rounded corner is a quarter disc of three quads (its centre
// square and two quads on the arc, 2 box_m cells along the arc, box_k
// radially beyond the square); between the corners box_nx cells along x,
// beyond the radius box_nz cells along z. The profile's quads have their
// normals along the extrusion (positive hexahedra): for box_s = -1, whose
// profile is the mirror image, it is extruded the other way (from y =
// box_y + box_dy). Output box_volumes[].
Macro RoundedBlock
  rb_x[] = {box_x, box_x + box_r, box_x + box_dx - box_r, box_x + box_dx};
  rb_y = (box_s > 0) ? box_y : box_y + box_dy;
  // z of the profile's levels: the face, the corners' centres, the far face
  rb_z[] = {box_z, box_z + box_s * box_r, box_z + box_s * box_dz};
  // Corner points: level 1 (A_L, O_L, O_R, A_R), level 0 (B_L, B_R), level
  // 2 (the far face's four), then per corner R1 (on O-A), R2 (on O-B), Q
  // (inside) and M (the arc's middle).
  rb_p[] = {};
  For rb_i In {0:3}
    rb_p[] += newp; Point(newp) = {rb_x[rb_i], rb_y, rb_z[1]};
  EndFor
  For rb_i In {1:2}
    rb_p[] += newp; Point(newp) = {rb_x[rb_i], rb_y, rb_z[0]};
  EndFor
  For rb_i In {0:3}
    rb_p[] += newp; Point(newp) = {rb_x[rb_i], rb_y, rb_z[2]};
  EndFor
  rb_o[] = {rb_p[1], rb_p[2]};       // the corners' centres
  rb_a[] = {rb_p[0], rb_p[3]};       // the arcs' ends on level 1
  rb_b[] = {rb_p[4], rb_p[5]};       // the arcs' ends on level 0
  rb_r1[] = {}; rb_r2[] = {}; rb_q[] = {}; rb_m[] = {};
  For rb_c In {0:1}
    rb_sx = (rb_c == 0) ? -1 : 1;    // from the centre towards the edge
    rb_ox = rb_x[1 + rb_c];
    rb_r1[] += newp;
    Point(newp) = {rb_ox + rb_sx * box_r / 2., rb_y, rb_z[1]};
    rb_r2[] += newp;
    Point(newp) = {rb_ox, rb_y, rb_z[1] - box_s * box_r / 2.};
    rb_q[] += newp;
    Point(newp) = {rb_ox + rb_sx * 0.45 * box_r, rb_y,
                   rb_z[1] - box_s * 0.45 * box_r};
    rb_m[] += newp;
    Point(newp) = {rb_ox + rb_sx * c45 * box_r, rb_y,
                   rb_z[1] - box_s * c45 * box_r};
  EndFor
  // Curves of each corner: 0 A-M, 1 M-B (arcs), 2 A-R1, 3 R1-O, 4 B-R2,
  // 5 R2-O, 6 R1-Q, 7 Q-R2, 8 M-Q.
  rb_l[] = {};
  For rb_c In {0:1}
    rb_l[] += newl; Circle(newl) = {rb_a[rb_c], rb_o[rb_c], rb_m[rb_c]};
    rb_l[] += newl; Circle(newl) = {rb_m[rb_c], rb_o[rb_c], rb_b[rb_c]};
    rb_l[] += newl; Line(newl) = {rb_a[rb_c], rb_r1[rb_c]};
    rb_l[] += newl; Line(newl) = {rb_r1[rb_c], rb_o[rb_c]};
    rb_l[] += newl; Line(newl) = {rb_b[rb_c], rb_r2[rb_c]};
    rb_l[] += newl; Line(newl) = {rb_r2[rb_c], rb_o[rb_c]};
    rb_l[] += newl; Line(newl) = {rb_r1[rb_c], rb_q[rb_c]};
    rb_l[] += newl; Line(newl) = {rb_q[rb_c], rb_r2[rb_c]};
    rb_l[] += newl; Line(newl) = {rb_m[rb_c], rb_q[rb_c]};
    Transfinite Curve {rb_l[{9 * rb_c + 0, 9 * rb_c + 1}]} = box_m + 1;
    Transfinite Curve {rb_l[{9 * rb_c + 3, 9 * rb_c + 5, 9 * rb_c + 6,
                             9 * rb_c + 7}]} = box_m + 1;
    Transfinite Curve {rb_l[{9 * rb_c + 2, 9 * rb_c + 4, 9 * rb_c + 8}]} =
      box_k + 1;
  EndFor
  // The straight curves between: 18 B_L-B_R, 19 O_L-O_R (box_nx), 20 A_L
  // up, 21 O_L up, 22 O_R up, 23 A_R up (box_nz), 24 to 26 along the far
  // face (left strip, core, right strip).
  rb_l[] += newl; Line(newl) = {rb_b[0], rb_b[1]};
  rb_l[] += newl; Line(newl) = {rb_o[0], rb_o[1]};
  Transfinite Curve {rb_l[{18, 19}]} = box_nx + 1;
  For rb_i In {0:3}
    rb_l[] += newl; Line(newl) = {rb_p[rb_i], rb_p[6 + rb_i]};
  EndFor
  Transfinite Curve {rb_l[{20:23}]} = box_nz + 1;
  For rb_i In {0:2}
    rb_l[] += newl; Line(newl) = {rb_p[6 + rb_i], rb_p[7 + rb_i]};
  EndFor
  Transfinite Curve {rb_l[{24, 26}]} = box_k + box_m + 1;
  Transfinite Curve {rb_l[25]} = box_nx + 1;
  // The ten quads: per corner its three, then the left strip, the core,
  // the right strip and the strip along the face between the corners.
  rb_s[] = {};
  For rb_c In {0:1}
    rb_f = 9 * rb_c;
    rb_loops[] = {};
    rb_loops[] += newll;
    Curve Loop(newll) = {rb_l[rb_f + 3], -rb_l[rb_f + 5], -rb_l[rb_f + 7],
                         -rb_l[rb_f + 6]};
    rb_loops[] += newll;
    Curve Loop(newll) = {rb_l[rb_f + 2], rb_l[rb_f + 6], -rb_l[rb_f + 8],
                         -rb_l[rb_f + 0]};
    rb_loops[] += newll;
    Curve Loop(newll) = {rb_l[rb_f + 8], rb_l[rb_f + 7], -rb_l[rb_f + 4],
                         -rb_l[rb_f + 1]};
    For rb_i In {0:2}
      rb_new = news;
      Plane Surface(rb_new) = {rb_loops[rb_i]};
      rb_s[] += rb_new;
    EndFor
    Transfinite Surface {rb_s[3 * rb_c + 0]} = {rb_o[rb_c], rb_r1[rb_c],
                                                rb_q[rb_c], rb_r2[rb_c]};
    Transfinite Surface {rb_s[3 * rb_c + 1]} = {rb_a[rb_c], rb_r1[rb_c],
                                                rb_q[rb_c], rb_m[rb_c]};
    Transfinite Surface {rb_s[3 * rb_c + 2]} = {rb_m[rb_c], rb_q[rb_c],
                                                rb_r2[rb_c], rb_b[rb_c]};
  EndFor
  rb_loops[] = {};
  rb_loops[] += newll;    // left strip: A_L, O_L, top, top
  Curve Loop(newll) = {rb_l[2], rb_l[3], rb_l[21], -rb_l[24], -rb_l[20]};
  rb_loops[] += newll;    // core: O_L, O_R, top, top
  Curve Loop(newll) = {rb_l[19], rb_l[22], -rb_l[25], -rb_l[21]};
  rb_loops[] += newll;    // right strip: O_R, A_R, top, top
  Curve Loop(newll) = {-rb_l[12], -rb_l[11], rb_l[23], -rb_l[26],
                       -rb_l[22]};
  rb_loops[] += newll;    // along the face: B_L, B_R, O_R, O_L
  Curve Loop(newll) = {rb_l[18], rb_l[13], rb_l[14], -rb_l[19], -rb_l[5],
                       -rb_l[4]};
  For rb_i In {0:3}
    rb_new = news;
    Plane Surface(rb_new) = {rb_loops[rb_i]};
    rb_s[] += rb_new;
  EndFor
  Transfinite Surface {rb_s[6]} = {rb_a[0], rb_o[0], rb_p[7], rb_p[6]};
  Transfinite Surface {rb_s[7]} = {rb_o[0], rb_o[1], rb_p[8], rb_p[7]};
  Transfinite Surface {rb_s[8]} = {rb_o[1], rb_a[1], rb_p[9], rb_p[8]};
  Transfinite Surface {rb_s[9]} = {rb_b[0], rb_b[1], rb_o[1], rb_o[0]};
  // The left corner's quads run clockwise in the (x, box_s z) frame, as
  // extrusion along +y needs; the right corner's (its mirror image) and
  // the strips' run the other way.
  Reverse Surface {rb_s[{3:9}]};
  Recombine Surface {rb_s[]};
  // One surface at a time: the strips have five or six sides, so the
  // lists Extrude returns for several surfaces have no fixed stride.
  box_volumes[] = {};
  For rb_i In {0:9}
    rb_out[] = Extrude {0., box_s * box_dy, 0.} {
      Surface{rb_s[rb_i]}; Layers{box_ny}; Recombine;
    };
    box_volumes[] += rb_out[1];
  EndFor
Return

// Extruded: the tops and volumes of a list of extruded surfaces (Extrude
// returns, for each surface, its top, its volume and its four sides).
Macro Extruded
  ext_top[] = {}; ext_volume[] = {};
  For ext_i In {0:#ext_out[] / 6 - 1}
    ext_top[] += ext_out[6 * ext_i];
    ext_volume[] += ext_out[6 * ext_i + 1];
  EndFor
Return

// ------------------------------------------- stage 0: bolt and nut (in place)
// Cross-section at the nut's top z = -t_washer: the core and ring A to
// r = bolt_radius (the shank), and the nut's ring from the shank to
// nut_radius (its bore is the shank: they share the nodes of r =
// bolt_radius over the nut's height).
// Bolt, nut and head have bolt_quarter elements per quarter circle.
ring_q = bolt_quarter;
ring_z = z_nut_top;
count_length = nut_radius - bolt_radius; count_size = axial_size; Call Count;
ring_r[] = {bolt_radius, nut_radius}; ring_n[] = {count};
Call Rings;
nut_ring[] = ring_s[];
core_rim[] = {};
core_arc[] = {};
For k In {0:3}
  arc_s = nut_ring[k]; arc_R = bolt_radius; arc_k = k; Call FindArc;
  core_arc[] += arc; core_rim[] += arc_start;
EndFor
core_a = bolt_radius / 2.; core_z = z_nut_top; core_q = bolt_quarter;
// Ring A: 2 elements radially at the default (1.17 mm at the core's
// corners, 2 mm at its sides' middles).
core_n = Round(bolt_quarter / 3.);
If (core_n < 1)
  core_n = 1;
EndIf
Call SquareCore;
shank_section[] = core_s[];

// The nut (down to its bottom) and the shank inside it.
count_length = nut_height; count_size = axial_size; Call Count;
ext_out[] = Extrude {0., 0., -nut_height} {
  Surface{shank_section[], nut_ring[]}; Layers{count}; Recombine;
};
Call Extruded;
bolt_volumes[] = {ext_volume[{0:4}]};
nut_volumes[] = {ext_volume[{5:8}]};
// The bolt's end below the nut.
count_length = bolt_end_length; Call Count;
ext_out[] = Extrude {0., 0., -bolt_end_length} {
  Surface{ext_top[{0:4}]}; Layers{count}; Recombine;
};
Call Extruded;
bolt_volumes[] += ext_volume[];
bolt_end_faces[] = ext_top[];
// The shank up to the section's element layer (axial_size high, centred
// on z = section_z, so that the section plane cuts its elements halfway),
// through it, and on to the head's underside.
section_low = section_z - axial_size / 2.;
section_high = section_z + axial_size / 2.;
count_length = section_low - z_nut_top; Call Count;
ext_out[] = Extrude {0., 0., section_low - z_nut_top} {
  Surface{shank_section[]}; Layers{count}; Recombine;
};
Call Extruded;
bolt_volumes[] += ext_volume[];
ext_out[] = Extrude {0., 0., axial_size} {
  Surface{ext_top[]}; Layers{1}; Recombine;
};
Call Extruded;
bolt_volumes[] += ext_volume[];
count_length = z_head - section_high; Call Count;
ext_out[] = Extrude {0., 0., z_head - section_high} {
  Surface{ext_top[]}; Layers{count}; Recombine;
};
Call Extruded;
bolt_volumes[] += ext_volume[];
head_base[] = ext_top[];
// The head: the shank's cross-section and a ring to head_radius, built at
// z_head on the shank's arcs (the new radial line starts at the shank's
// point at 45 degrees; Gmsh merges the coinciding points and arcs).
ring_z = z_head;
count_length = head_radius - bolt_radius; count_size = axial_size; Call Count;
ring_r[] = {bolt_radius, head_radius}; ring_n[] = {count};
Call Rings;
head_base[] += ring_s[];
count_length = head_height; Call Count;
ext_out[] = Extrude {0., 0., head_height} {
  Surface{head_base[]}; Layers{count}; Recombine;
};
Call Extruded;
bolt_volumes[] += ext_volume[];
stage_volumes_0[] = {bolt_volumes[], nut_volumes[]};
ring_q = n_quarter;           // the other parts

// -------------------------------------------------------- stage 1: washer
shift = 1 * stage_shift;
ring_z = -washer_thickness + shift;
count_length = washer_radius - hole_radius; count_size = axial_size;
Call Count;
ring_r[] = {hole_radius, washer_radius}; ring_n[] = {count};
Call Rings;
ext_out[] = Extrude {0., 0., washer_thickness} {
  Surface{ring_s[]}; Layers{n_thin}; Recombine;
};
Call Extruded;
washer_volumes[] = ext_volume[];

// ----------------------------------- stage 2: inner sleeve and rubber body
// Cross-section at z = 0: the inner sleeve (hole_radius to
// inner_sleeve_radius), the rubber (to rubber_radius) and the lip (to
// lip_radius); the rubber shares the sleeve's nodes at
// r = inner_sleeve_radius. Lips from z = 0 to lip_height and from
// L - lip_height to L.
shift = 2 * stage_shift;
ring_z = shift;
count_length = rubber_radius - inner_sleeve_radius; count_size = axial_size;
Call Count;
n_rubber = count;
count_length = lip_radius - rubber_radius; Call Count;
n_lip = count;
ring_r[] = {hole_radius, inner_sleeve_radius, rubber_radius, lip_radius};
ring_n[] = {n_thin, n_rubber, n_lip};
Call Rings;
sleeve_s[] = {}; rubber_s[] = {}; lip_s[] = {};
For k In {0:3}
  sleeve_s[] += ring_s[3 * k]; rubber_s[] += ring_s[3 * k + 1];
  lip_s[] += ring_s[3 * k + 2];
EndFor
count_length = lip_height; count_size = axial_size; Call Count;
n_lip_layers = Max(count, 2);       // lips: 2 at least, as thin parts
count_length = L - 2. * lip_height; Call Count;
n_middle = count;
ext_out[] = Extrude {0., 0., lip_height} {
  Surface{sleeve_s[], rubber_s[], lip_s[]}; Layers{n_lip_layers}; Recombine;
};
Call Extruded;
inner_volumes[] = ext_volume[{0:3}];
rubber_volumes[] = ext_volume[{4:11}];
ext_out[] = Extrude {0., 0., L - 2. * lip_height} {
  Surface{ext_top[{0:7}]}; Layers{n_middle}; Recombine;
};
Call Extruded;
inner_volumes[] += ext_volume[{0:3}];
rubber_volumes[] += ext_volume[{4:7}];
upper[] = ext_top[];
// The upper lip's ring, on the rubber's arcs at z = L - lip_height.
ring_z = L - lip_height + shift;
ring_r[] = {rubber_radius, lip_radius}; ring_n[] = {n_lip};
Call Rings;
ext_out[] = Extrude {0., 0., lip_height} {
  Surface{upper[], ring_s[]}; Layers{n_lip_layers}; Recombine;
};
Call Extruded;
inner_volumes[] += ext_volume[{0:3}];
rubber_volumes[] += ext_volume[{4:11}];

// ------------------------------------------ stage 3: plastic outer sleeve
shift = 3 * stage_shift;
ring_z = lip_height + shift;
ring_r[] = {rubber_radius, plastic_radius}; ring_n[] = {n_thin};
Call Rings;
ext_out[] = Extrude {0., 0., L - 2. * lip_height} {
  Surface{ring_s[]}; Layers{n_middle}; Recombine;
};
Call Extruded;
plastic_volumes[] = ext_volume[];

// ------------------------------------ stage 4: metal outer sleeve and plate
// The sleeve from lip_height to the plate's bottom, through the plate's
// eye (sharing the nodes of r = metal_radius with the plate) and on to
// L - lip_height.
shift = 4 * stage_shift;
ring_z = lip_height + shift;
ring_r[] = {plastic_radius, metal_radius}; ring_n[] = {n_thin};
Call Rings;
count_length = plate_bottom - lip_height; count_size = axial_size; Call Count;
ext_out[] = Extrude {0., 0., plate_bottom - lip_height} {
  Surface{ring_s[]}; Layers{count}; Recombine;
};
Call Extruded;
metal_volumes[] = ext_volume[];
metal_at_plate[] = ext_top[];
// The plate's bottom face: an O-grid ring from the sleeve's outer arcs to
// the square |x|, |y| <= plate_half_width, and a block on to plate_end.
grid_arc[] = {}; grid_rim[] = {};
For k In {0:3}
  arc_s = metal_at_plate[k]; arc_R = metal_radius; arc_k = k; Call FindArc;
  grid_arc[] += arc; grid_rim[] += arc_start;
EndFor
// The last clamp_size of the plate, over the support, is its bolted area
// (a block of its own, whose top is the plate clamp patch).
grid_x[] = {-plate_half_width, plate_half_width, plate_end - clamp_size,
            plate_end};
grid_y[] = {-plate_half_width, plate_half_width};
count_length = plate_end - clamp_size - plate_half_width;
count_size = plate_size;
Call Count;
grid_nx[] = {n_quarter, count};
count_length = clamp_size; Call Count;
grid_nx[] += count;
grid_ny[] = {n_quarter};
grid_ic = 0; grid_jc = 0; grid_z = plate_bottom + shift;
// Radially 2 n: the ring's sides run from 15.5 (mid-side) to 34.1
// (corner) at the defaults, about the square's side cells (15 / n).
grid_m = 2 * n;
Call HoleGrid;
plate_bottom_faces[] = grid_s[];
ext_out[] = Extrude {0., 0., plate_thickness} {
  Surface{metal_at_plate[], plate_bottom_faces[]}; Layers{n_thin}; Recombine;
};
Call Extruded;
metal_volumes[] += ext_volume[{0:3}];
plate_volumes[] = ext_volume[{4:#ext_volume[] - 1}];
plate_top_faces[] = ext_top[{4:#ext_top[] - 1}];
plate_clamp_face = -1;
For i In {0:#plate_bottom_faces[] - 1}
  If (plate_bottom_faces[i] == grid_block[2])
    plate_clamp_face = plate_top_faces[i];
  EndIf
EndFor
count_length = L - lip_height - plate_top; count_size = axial_size; Call Count;
ext_out[] = Extrude {0., 0., L - lip_height - plate_top} {
  Surface{ext_top[{0:3}]}; Layers{count}; Recombine;
};
Call Extruded;
metal_volumes[] += ext_volume[];

// ---------------------------------------------------------- stage 5: brace
// A rectangle x from -brace_back to brace_square + clamp_size, |y| <=
// brace_half_width, at z = L (underside) to L + brace_thickness, with the
// bolt hole: blocks on a 4 x 5 grid, the O-grid square |x|, |y| <=
// brace_square in the middle. The clamped areas are the tops of three
// blocks: back (x < -brace_back + clamp_size, |y| <= brace_square) and the
// two front corners (x > brace_square, |y| > brace_half_width -
// clamp_size): a triangle around the bushing, clear of the drop weight.
shift = 5 * stage_shift;
// The hole's arcs: a point at 45 degrees rotated four times.
p = newp;
Point(p) = {hole_radius * c45, hole_radius * c45, L + shift};
grid_arc[] = {}; grid_rim[] = {p};
For k In {0:3}
  out[] = Extrude {{0., 0., 1.}, {0., 0., 0.}, Pi / 2.} {
    Point{p}; Layers{n_quarter};
  };
  grid_arc[] += out[1];
  p = out[0];
  If (k < 3)
    grid_rim[] += p;
  EndIf
EndFor
grid_x[] = {-brace_back, -brace_back + clamp_size, -brace_square,
            brace_square, brace_square + clamp_size};
grid_y[] = {-brace_half_width, -brace_half_width + clamp_size,
            -brace_square, brace_square, brace_half_width - clamp_size,
            brace_half_width};
grid_nx[] = {}; grid_ny[] = {};
For i In {0:3}
  count_length = grid_x[i + 1] - grid_x[i]; count_size = plane_size;
  Call Count;
  grid_nx[] += (i == 2) ? n_quarter : count;
EndFor
For j In {0:4}
  count_length = grid_y[j + 1] - grid_y[j]; count_size = plane_size;
  Call Count;
  grid_ny[] += (j == 2) ? n_quarter : count;
EndFor
grid_ic = 2; grid_jc = 2; grid_z = L + shift;
grid_m = 3 * n;
Call HoleGrid;
brace_bottom_faces[] = grid_s[];
// The clamp patches' blocks (index i * 5 + j).
clamp_blocks[] = {grid_block[0 * 5 + 2], grid_block[3 * 5 + 4],
                  grid_block[3 * 5 + 0]};
ext_out[] = Extrude {0., 0., brace_thickness} {
  Surface{brace_bottom_faces[]}; Layers{n_thin}; Recombine;
};
Call Extruded;
brace_volumes[] = ext_volume[];
brace_top_faces[] = ext_top[];
clamp_faces[] = {};
For c In {0:2}
  For i In {0:#brace_bottom_faces[] - 1}
    If (brace_bottom_faces[i] == clamp_blocks[c])
      clamp_faces[] += brace_top_faces[i];
    EndIf
  EndFor
EndFor

// ---------------------------------------------- stages 6, 7: support, weight
// The support under the plate's far end, its top on the plate's bottom,
// with its top's edges along y rounded (edge_radius).
shift = 6 * stage_shift;
box_x = plate_end - support_length; box_y = -plate_half_width;
box_dx = support_length; box_dy = 2. * plate_half_width;
box_dz = support_height;
box_nx = 2 * n; box_ny = 3 * n; box_nz = n;
If (edge_radius > 0.)
  box_z = plate_bottom + shift; box_s = -1;
  box_r = edge_radius; box_m = edge_facets / 2; box_k = n;
  Call RoundedBlock;
  support_volumes[] = box_volumes[];
Else
  box_z = plate_bottom - support_height + shift;
  Call MakeBlock;
  support_volumes[] = {box_volume};
EndIf
// The drop weight above the plate, weight_gap above its top, with its
// bottom's edges along y rounded (edge_radius).
shift = 7 * stage_shift;
box_x = weight_x; box_y = -weight_width / 2.;
box_z = plate_top + weight_gap + shift;
box_dx = weight_length; box_dy = weight_width; box_dz = weight_height;
box_nx = 2 * n; box_ny = 2 * n; box_nz = n;
If (edge_radius > 0.)
  box_s = 1; box_r = edge_radius; box_m = edge_facets / 2; box_k = n;
  Call RoundedBlock;
  weight_volumes[] = box_volumes[];
Else
  Call MakeBlock;
  weight_volumes[] = {box_volume};
EndIf

// ------------------------------------------- the parts back into place
// Without AutoCoherence: touching parts keep nodes of their own.
Geometry.AutoCoherence = 0;
Translate {0., 0., -1 * stage_shift} { Volume{washer_volumes[]}; }
Translate {0., 0., -2 * stage_shift} {
  Volume{inner_volumes[], rubber_volumes[]};
}
Translate {0., 0., -3 * stage_shift} { Volume{plastic_volumes[]}; }
Translate {0., 0., -4 * stage_shift} {
  Volume{metal_volumes[], plate_volumes[]};
}
Translate {0., 0., -5 * stage_shift} { Volume{brace_volumes[]}; }
Translate {0., 0., -6 * stage_shift} { Volume{support_volumes[]}; }
Translate {0., 0., -7 * stage_shift} { Volume{weight_volumes[]}; }

// ------------------------------------------------------- physical groups
// FreeFaces: the faces of free_part[] (volumes) on the boundary of its
// group free_group[] (the volumes sharing nodes with it): the faces of
// the part minus those it shares with the rest of the group. Each face
// is then sorted by its bounding box (face_box[]: xmin, ymin, zmin, xmax,
// ymax, zmax; exact in z, which is all the sorting relies on besides a
// radius halfway between two hulls).
Macro FreeFaces
  free_faces[] = Abs(CombinedBoundary{ Volume{free_part[]}; });
  free_rest[] = free_group[];
  free_rest[] -= free_part[];
  If (#free_rest[] > 0)
    free_interface[] = free_faces[];
    free_interface[] -= Abs(CombinedBoundary{ Volume{free_group[]}; });
    free_faces[] -= free_interface[];
  EndIf
Return
// A block's face at z = face_z with its rounded edges (RoundedBlock; the
// block on the side of face_band = +-edge_radius): the faces, from
// free_faces[], that lie within the band from face_z to face_z +
// face_band and are not vertical (the profile's ends); output at_z[] and
// not_at_z[].
Macro FaceWithEdges
  at_z[] = {}; not_at_z[] = {};
  face_lo = Min(face_z, face_z + face_band) - eps;
  face_hi = Max(face_z, face_z + face_band) + eps;
  For face_i In {0:#free_faces[] - 1}
    face_box[] = BoundingBox Surface{free_faces[face_i]};
    If (face_box[2] > face_lo && face_box[5] < face_hi &&
        face_box[4] - face_box[1] > eps)
      at_z[] += free_faces[face_i];
    Else
      not_at_z[] += free_faces[face_i];
    EndIf
  EndFor
Return
// Horizontal faces at z = face_z and the others, from free_faces[]:
// output at_z[] and not_at_z[] (FaceWithEdges with no band).
Macro AtZ
  face_band = 0.;
  Call FaceWithEdges;
Return
// Vertical faces within z_lo <= z <= z_hi and farthest from the axis
// (bounding box) below / above face_r: output inside[], outside[];
// rest[] the other faces.
Macro Vertical
  inside[] = {}; outside[] = {}; rest[] = {};
  For face_i In {0:#free_faces[] - 1}
    face_box[] = BoundingBox Surface{free_faces[face_i]};
    face_far = Max(Max(Abs(face_box[0]), Abs(face_box[1])),
                   Max(Abs(face_box[3]), Abs(face_box[4])));
    If (face_box[5] - face_box[2] > eps && face_box[2] > z_lo - eps &&
        face_box[5] < z_hi + eps)
      If (face_far < face_r)
        inside[] += free_faces[face_i];
      Else
        outside[] += free_faces[face_i];
      EndIf
    Else
      rest[] += free_faces[face_i];
    EndIf
  EndFor
Return

Physical Volume("bolt", 1) = {bolt_volumes[]};
Physical Volume("nut", 2) = {nut_volumes[]};
Physical Volume("washer", 3) = {washer_volumes[]};
Physical Volume("inner sleeve", 4) = {inner_volumes[]};
Physical Volume("rubber", 5) = {rubber_volumes[]};
Physical Volume("plastic outer sleeve", 6) = {plastic_volumes[]};
Physical Volume("metal outer sleeve", 7) = {metal_volumes[]};
Physical Volume("plate", 8) = {plate_volumes[]};
Physical Volume("brace", 9) = {brace_volumes[]};
Physical Volume("support", 10) = {support_volumes[]};
Physical Volume("drop weight", 11) = {weight_volumes[]};

// Bolt and nut.
free_group[] = {bolt_volumes[], nut_volumes[]};
free_part[] = bolt_volumes[];
Call FreeFaces;
z_lo = z_nut_top; z_hi = z_head; face_r = bolt_radius + 1.;
Call Vertical;
shank_side[] = inside[];
free_faces[] = {outside[], rest[]};
face_z = z_head; Call AtZ;
head_underside[] = at_z[];
free_faces[] = not_at_z[];
face_z = z_end; Call AtZ;
Physical Surface("bolt shank side", 1) = {shank_side[]};
Physical Surface("head underside", 2) = {head_underside[]};
Physical Surface("bolt end", 3) = {at_z[]};
Physical Surface("bolt other free faces", 4) = {not_at_z[]};
free_part[] = nut_volumes[];
Call FreeFaces;
face_z = z_nut_top; Call AtZ;
Physical Surface("nut top", 5) = {at_z[]};
Physical Surface("nut other free faces", 6) = {not_at_z[]};

// Washer.
free_group[] = washer_volumes[]; free_part[] = washer_volumes[];
Call FreeFaces;
face_z = 0.; Call AtZ;
Physical Surface("washer top", 7) = {at_z[]};
free_faces[] = not_at_z[];
face_z = -washer_thickness; Call AtZ;
Physical Surface("washer bottom", 8) = {at_z[]};
Physical Surface("washer hole wall and rim", 9) = {not_at_z[]};

// Inner sleeve and rubber.
free_group[] = {inner_volumes[], rubber_volumes[]};
free_part[] = inner_volumes[];
Call FreeFaces;
face_z = L; Call AtZ;
Physical Surface("inner sleeve top end", 10) = {at_z[]};
free_faces[] = not_at_z[];
face_z = 0.; Call AtZ;
Physical Surface("inner sleeve bottom end", 11) = {at_z[]};
Physical Surface("inner sleeve bore", 12) = {not_at_z[]};
free_part[] = rubber_volumes[];
Call FreeFaces;
face_z = L; Call AtZ;
Physical Surface("rubber top lip face", 13) = {at_z[]};
free_faces[] = not_at_z[];
face_z = 0.; Call AtZ;
Physical Surface("rubber bottom lip face", 14) = {at_z[]};
free_faces[] = not_at_z[];
z_lo = lip_height; z_hi = L - lip_height;
face_r = (rubber_radius + lip_radius) / 2.;
Call Vertical;
Physical Surface("rubber outer face", 15) = {inside[]};
free_faces[] = rest[];
face_z = lip_height; Call AtZ;
lip_inner[] = at_z[];
free_faces[] = not_at_z[];
face_z = L - lip_height; Call AtZ;
lip_inner[] += at_z[];
Physical Surface("rubber lips' inner faces", 16) = {lip_inner[]};
Physical Surface("rubber lips' rims", 17) = {not_at_z[], outside[]};

// Plastic outer sleeve.
free_group[] = plastic_volumes[]; free_part[] = plastic_volumes[];
Call FreeFaces;
z_lo = lip_height; z_hi = L - lip_height;
face_r = (rubber_radius + plastic_radius) / 2.;
Call Vertical;
Physical Surface("plastic sleeve inner", 18) = {inside[]};
Physical Surface("plastic sleeve outer", 19) = {outside[]};
Physical Surface("plastic sleeve ends", 20) = {rest[]};

// Metal outer sleeve and plate.
free_group[] = {metal_volumes[], plate_volumes[]};
free_part[] = metal_volumes[];
Call FreeFaces;
face_r = (plastic_radius + metal_radius) / 2.;
Call Vertical;
Physical Surface("metal sleeve inner", 21) = {inside[]};
Physical Surface("metal sleeve outer", 22) = {outside[]};
Physical Surface("metal sleeve ends", 23) = {rest[]};
free_part[] = plate_volumes[];
Call FreeFaces;
face_z = plate_top; Call AtZ;
plate_top_free[] = at_z[];
plate_top_free[] -= {plate_clamp_face};
Physical Surface("plate top", 24) = {plate_top_free[]};
free_faces[] = not_at_z[];
face_z = plate_bottom; Call AtZ;
Physical Surface("plate bottom", 25) = {at_z[]};
Physical Surface("plate other free faces", 26) = {not_at_z[]};

// Brace.
free_group[] = brace_volumes[]; free_part[] = brace_volumes[];
Call FreeFaces;
face_z = L; Call AtZ;
Physical Surface("brace underside", 27) = {at_z[]};
free_faces[] = not_at_z[];
face_z = L + brace_thickness; Call AtZ;
brace_top[] = at_z[];
brace_top[] -= clamp_faces[];
Physical Surface("brace top", 28) = {brace_top[]};
Physical Surface("brace clamp back", 29) = {clamp_faces[0]};
Physical Surface("brace clamp front +y", 30) = {clamp_faces[1]};
Physical Surface("brace clamp front -y", 31) = {clamp_faces[2]};
free_faces[] = not_at_z[];
z_lo = L; z_hi = L + brace_thickness; face_r = hole_radius + 1.;
Call Vertical;
Physical Surface("brace hole wall", 32) = {inside[]};
Physical Surface("brace rims", 33) = {outside[], rest[]};

// Support and drop weight: the support's top and the drop weight's
// bottom, with their rounded edges.
free_group[] = support_volumes[]; free_part[] = support_volumes[];
Call FreeFaces;
face_z = plate_bottom; face_band = -edge_radius; Call FaceWithEdges;
Physical Surface("support top", 34) = {at_z[]};
Physical Surface("support other faces", 35) = {not_at_z[]};
free_group[] = weight_volumes[]; free_part[] = weight_volumes[];
Call FreeFaces;
face_z = plate_top + weight_gap; face_band = edge_radius;
Call FaceWithEdges;
Physical Surface("drop weight bottom", 36) = {at_z[]};
Physical Surface("drop weight other faces", 37) = {not_at_z[]};
// The plate's bolted end (last, so that ids 1 to 37 keep their order).
Physical Surface("plate clamp", 38) = {plate_clamp_face};
