// The drop test with deformable plates: the rubber cylinder of
// drop_test_cylinder.geo (80 hexahedra, diameter 25 mm, height 24 mm,
// z from 0 to 24) between two steel plates 40 x 40 x 5 mm (8 x 8 x 1
// hexahedra each), the bottom plate z from -5 to 0, the top plate (the
// impactor) z from 24 to 29, both centred on the axis. The plates touch
// the cylinder's ends with nodes of their own (their geometry points are
// the plates' corners, away from the cylinder's points: Gmsh merges
// nothing).
//
// Physical volumes: 1 = rubber, 2 = bottom plate, 3 = top plate.
// Physical surfaces: 1 = hull, 2 = the cylinder's bottom (z = 0), 3 = its
// top (z = 24) (drop_test_cylinder.geo); 4 = the bottom plate's top
// (z = 0), 5 = the top plate's bottom (z = 24), 6 = the bottom plate's
// bottom (z = -5), 7 = the top plate's top (z = 29), 8 = the plates'
// sides.
Include "drop_test_cylinder.geo";

half = 20.; thickness = 5.; height = 24.;
plate_faces[] = {};
For k In {0:1}
  z0 = (k == 0) ? -thickness : height;
  p = newp;
  Point(p) = {-half, -half, z0};
  line[] = Extrude {2 * half, 0., 0.} { Point{p}; Layers{8}; };
  face[] = Extrude {0., 2 * half, 0.} { Curve{line[1]}; Layers{8}; Recombine; };
  plate[] = Extrude {0., 0., thickness} { Surface{face[1]}; Layers{1}; Recombine; };
  plate_volume[k] = plate[1];
  // The extrusion's list: [0] top, [1] volume, [2..5] sides; the bottom
  // is the source surface.
  plate_bottom[k] = face[1];
  plate_top[k] = plate[0];
  plate_sides[] += {plate[2], plate[3], plate[4], plate[5]};
EndFor

Physical Volume("bottom plate", 2) = {plate_volume[0]};
Physical Volume("top plate", 3) = {plate_volume[1]};
Physical Surface("bottom plate top z = 0", 4) = {plate_top[0]};
Physical Surface("top plate bottom z = 24", 5) = {plate_bottom[1]};
Physical Surface("bottom plate bottom z = -5", 6) = {plate_bottom[0]};
Physical Surface("top plate top z = 29", 7) = {plate_top[1]};
Physical Surface("plate sides", 8) = {plate_sides[]};
