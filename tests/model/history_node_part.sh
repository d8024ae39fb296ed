#!/usr/bin/env bash
# Output/History nodes at a point where two parts have nodes of their own
# (doc/model.md, "What it writes"): 'name: x, y, z in part' takes the
# named part's node (the bushing's inner_sleeve_slip compares the sleeve's
# end with the brace at the same point, issue 10).
# meshes/block_on_plate.msh: the block's corner (5, 5, 2) stands on a node
# of the plate's top. No contact pair: the block (initial velocity
# (0, 0, -1) mm/ms, no load) flies through the plate, which is fixed at its
# bottom and stays unloaded. Explicit, 0.01 ms:
#  - corner_block: the block's corner moves as the block, -t in z (a rigid
#    translation) to 1e-9 mm, and not in x, y;
#  - corner_plate: the plate's node at the same point does not move (0);
#  - without a part the same point is refused (tests/bad_input/
#    history_node_two_parts.prm).
#  - time_history.svg has a History nodes panel with their columns.
# Usage: history_node_part.sh EXECUTABLE SOURCE_DIR NPROC
set -euo pipefail
exe=$1; source_dir=$2; nproc=$3
source "$source_dir/tests/model/script_helpers.sh"

cat > block.prm <<PRM
set Study = Model
subsection Mesh
  set Mesh file = $source_dir/parameter_files/meshes/block_on_plate.msh
end
subsection Parts
  set Names = block, plate
  subsection block
    set Material ids     = 1
    set Model            = Elastic
    set Young's modulus  = 0.01
    set Poisson's ratio  = 0.45
    set Density          = 1.1e-6
    set Initial velocity = 0, 0, -1
  end
$(elastic_steel_part plate 2)
end
subsection Boundary conditions
  set Names = base
  subsection base
    set Boundary ids = 4
    set Type         = fixed
  end
end
subsection Time integration
  set Scheme   = explicit
  set End time = 0.01
end
subsection Output
  set Output directory        = block
  set History output interval = 0.001
  set Field output interval   = 0
  set History nodes           = corner_block: 5, 5, 2 in block; corner_plate: 5, 5, 2 in plate
end
PRM
rm -rf block
run_prm block.prm block.log
awk -F, '
  function abs(x) { return x < 0 ? -x : x }
  NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
  { n++
    e = abs($c["corner_block_displacement_z"] + $c["time"])
    e = e + abs($c["corner_block_displacement_x"]) + abs($c["corner_block_displacement_y"])
    if (e > block_error) block_error = e
    p = abs($c["corner_plate_displacement_x"]) + abs($c["corner_plate_displacement_y"]) + abs($c["corner_plate_displacement_z"])
    if (p > plate_moved) plate_moved = p
    last_z = $c["corner_block_displacement_z"] }
  END {
    printf "%d rows: the block'"'"'s corner at %.6g mm at the end (-t to %.2g mm), the plate'"'"'s node at the same point moved %.2g mm\n", n, last_z, block_error, plate_moved
    exit (n < 10 || block_error > 1e-9 || plate_moved != 0 || last_z > -0.009) }' block/time_history.csv

# The plot has a panel of the history nodes (doc/model.md, "What it
# writes"), with the six columns of the two nodes in its legend.
svg=block/time_history.svg
grep -q '>History nodes</text>' "$svg" || { echo "time_history.svg has no History nodes panel"; exit 1; }
for column in corner_block_displacement_x corner_block_displacement_z corner_plate_displacement_y; do
  grep -q ">$column</text>" "$svg" || { echo "time_history.svg has no curve $column"; exit 1; }
done
echo "time_history.svg: a History nodes panel with the nodes' displacements"
