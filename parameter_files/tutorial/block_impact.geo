// The tutorial's model (doc/tutorial/): a rubber block bonded to a steel
// plate, and a separate steel block above it that hits or presses it.
//
//   steel plate    [0, 30] x [0, 30] x [0, 3]     (z up; mm)
//   rubber block   [5, 25] x [5, 25] x [3, 13]    8 x 8 x 4 hexahedra
//   steel block    [10, 20] x [10, 20] x [14, 19] 4 x 4 x 2 hexahedra,
//                  1 mm above the rubber, nodes of its own
//
// Two ways to bond the rubber to the plate, chosen by the number 'shared':
//   shared = 0 (block_impact_tied.msh): the rubber has nodes of its own on
//     the plate (the plate meshed 6 x 6 x 1, non-matching); a tied contact
//     pair bonds them (doc/tutorial/3_tied.md).
//   shared = 1 (block_impact_shared.msh): the plate is meshed in 3 x 3
//     patches (2 + 8 + 2 cells a side, 12 x 12 x 1), and the rubber is
//     extruded from the middle patch: the two parts share the nodes there
//     (LS-DYNA's merged nodes).
//
// Physical volumes (material ids, Parts/<name>/Material ids):
//   1 = rubber, 2 = plate, 3 = steel block.
// Physical surfaces (boundary ids, Boundary ids of conditions and pairs):
//   1 = plate bottom (z = 0)
//   2 = plate top (z = 3): with shared = 0 the whole face, with shared = 1
//       the ring around the rubber (the rest is inside the model)
//   3 = rubber bottom (z = 3; shared = 0 only: with shared nodes it is
//       not a boundary)
//   4 = rubber top (z = 13)
//   5 = steel block bottom (z = 14)
//   6 = steel block top (z = 19)
//   7 = every other outer face (the sides of the three bodies)
//
// Make the meshes (Gmsh's ASCII format 2.2; Debian 12's gmsh 4.8.4):
//   gmsh -3 -format msh22 -setnumber shared 0 block_impact.geo -o block_impact_tied.msh
//   gmsh -3 -format msh22 -setnumber shared 1 block_impact.geo -o block_impact_shared.msh
//
// Built from transfinite patches and extrusions with Layers and Recombine,
// so every cell is a hexahedron and every node lies where the layers put
// it. Gmsh's built-in kernel merges coincident points: the rubber's corners
// (5, 5, 3) lie inside the plate's face when shared = 0, and the steel
// block is 1 mm away, so nothing else is merged.
DefineConstant[ shared = {0, Name "bond by shared nodes (1) or a tied pair (0)"} ];

plate_thickness = 3.; rubber_height = 10.; gap = 1.; block_height = 5.;
eps = 1e-6;

// The plate: patches between the lines x, y = xs[] with ns[] cells each.
If (shared)
  xs[] = {0., 5., 25., 30.}; ns[] = {2, 8, 2};
Else
  xs[] = {0., 30.}; ns[] = {6};
EndIf
n = #xs[];
For j In {0 : n - 1}
  For i In {0 : n - 1}
    Point(1 + i + n * j) = {xs[i], xs[j], 0.};
  EndFor
EndFor
For j In {0 : n - 1}           // lines along x: 1000 + ...
  For i In {0 : n - 2}
    Line(1000 + i + n * j) = {1 + i + n * j, 2 + i + n * j};
    Transfinite Curve{1000 + i + n * j} = ns[i] + 1;
  EndFor
EndFor
For j In {0 : n - 2}           // lines along y: 2000 + ...
  For i In {0 : n - 1}
    Line(2000 + i + n * j) = {1 + i + n * j, 1 + i + n * (j + 1)};
    Transfinite Curve{2000 + i + n * j} = ns[j] + 1;
  EndFor
EndFor
plate_faces[] = {};
For j In {0 : n - 2}
  For i In {0 : n - 2}
    Curve Loop(3000 + i + n * j) = {1000 + i + n * j, 2000 + i + 1 + n * j,
                                   -(1000 + i + n * (j + 1)), -(2000 + i + n * j)};
    Plane Surface(3000 + i + n * j) = {3000 + i + n * j};
    Transfinite Surface{3000 + i + n * j};
    Recombine Surface{3000 + i + n * j};
    plate_faces[] += {3000 + i + n * j};
  EndFor
EndFor
plate[] = {};
plate_top_faces[] = {};
For k In {0 : #plate_faces[] - 1}
  out[] = Extrude {0., 0., plate_thickness} { Surface{plate_faces[k]}; Layers{1}; Recombine; };
  plate_top_faces[] += {out[0]};
  plate[] += {out[1]};
EndFor

// The rubber block: extruded from the plate's middle patch (shared nodes),
// or from a face of its own on the plate.
If (shared)
  rubber[] = Extrude {0., 0., rubber_height} { Surface{plate_top_faces[4]}; Layers{4}; Recombine; };
Else
  Point(100) = {5., 5., plate_thickness};
  rubber_line[] = Extrude {20., 0., 0.} { Point{100}; Layers{8}; };
  rubber_face[] = Extrude {0., 20., 0.} { Curve{rubber_line[1]}; Layers{8}; Recombine; };
  rubber[] = Extrude {0., 0., rubber_height} { Surface{rubber_face[1]}; Layers{4}; Recombine; };
EndIf

// The steel block, 1 mm above the rubber.
z_block = plate_thickness + rubber_height + gap;
Point(200) = {10., 10., z_block};
block_line[] = Extrude {10., 0., 0.} { Point{200}; Layers{4}; };
block_face[] = Extrude {0., 10., 0.} { Curve{block_line[1]}; Layers{4}; Recombine; };
block[] = Extrude {0., 0., block_height} { Surface{block_face[1]}; Layers{2}; Recombine; };

// Faces by position.
z1 = plate_thickness; z2 = z1 + rubber_height; z3 = z_block + block_height;
plate_bottom[] = Surface In BoundingBox {-eps, -eps, -eps, 30. + eps, 30. + eps, eps};
at_z1[] = Surface In BoundingBox {-eps, -eps, z1 - eps, 30. + eps, 30. + eps, z1 + eps};
under_rubber[] = Surface In BoundingBox {5. - eps, 5. - eps, z1 - eps, 25. + eps, 25. + eps, z1 + eps};
rubber_top[] = Surface In BoundingBox {5. - eps, 5. - eps, z2 - eps, 25. + eps, 25. + eps, z2 + eps};
block_bottom[] = Surface In BoundingBox {10. - eps, 10. - eps, z_block - eps, 20. + eps, 20. + eps, z_block + eps};
block_top[] = Surface In BoundingBox {10. - eps, 10. - eps, z3 - eps, 20. + eps, 20. + eps, z3 + eps};
If (shared)
  plate_top[] = at_z1[];
  plate_top[] -= {under_rubber[]};   // the middle patch is inside the model
  rubber_bottom[] = {};
Else
  rubber_bottom[] = under_rubber[];
  plate_top[] = at_z1[];
  plate_top[] -= {rubber_bottom[]};
EndIf
// CombinedBoundary: the outer faces of the union (not the faces between
// the plate's patches, nor, with shared nodes, under the rubber).
others[] = Abs(CombinedBoundary{ Volume{plate[], rubber[1]}; });
others[] += Abs(Boundary{ Volume{block[1]}; });
others[] -= {plate_bottom[], at_z1[], rubber_top[], block_bottom[], block_top[]};

Physical Volume("rubber", 1) = {rubber[1]};
Physical Volume("plate", 2) = {plate[]};
Physical Volume("steel block", 3) = {block[1]};
Physical Surface("plate bottom", 1) = {plate_bottom[]};
Physical Surface("plate top", 2) = {plate_top[]};
If (!shared)
  Physical Surface("rubber bottom", 3) = {rubber_bottom[]};
EndIf
Physical Surface("rubber top", 4) = {rubber_top[]};
Physical Surface("steel block bottom", 5) = {block_bottom[]};
Physical Surface("steel block top", 6) = {block_top[]};
Physical Surface("sides", 7) = {others[]};
