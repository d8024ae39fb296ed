// The slab of meshes/ironing.geo alone (the same nodes and tags, without
// the die): the node-to-surface variant of the ironing benchmark,
// parameter_files/ironing_rigid_die.prm, where a rigid cylinder presses
// and slides on the slab's top.
//
// Physical volumes: 1 = slab. Physical surfaces: 1 = the slab's bottom
// z = 0, 2 = the slab's top z = 3, 5 = the face y = 0, 6 = the face
// y = t, 7 = the slab's ends x = 0 and x = 9.
with_die = 0;
Include "ironing.geo";
