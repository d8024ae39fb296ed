#!/usr/bin/env bash
# A body held only by a mortar pair whose faces touch in the mesh (gap 0),
# quasi-static: the study's rubber block of meshes/block_on_plate.msh
# (10 x 10 x 5 mm, 5 x 5 x 3 cells) stands on an elastic steel plate
# (20 x 20 x 2 mm, 4 x 4 x 1 cells, separate nodes, non-matching) whose
# bottom is fixed; the block's top carries a traction t_z = -0.2 MPa * t
# (a dead load per reference area: 0.02 kN at t = 1 on its 100 mm^2), and
# nothing else holds it: a Coulomb pair (mu 0.8) rubber on plate. As in
# the bushing, whose bolt, sleeves and plate hang on such pairs.
#
# In the first load step every gap is 0: the pair's tangent takes a closed
# gap as active (normal stiffness and friction's sticking stiffness; the
# force there, p = 0, is the same either way). Without that the first
# system is singular in the block's rigid motions (and a gap of a
# round-off above 0, as the integrals give some nodes of touching faces,
# made friction's cone negative and the tangent NaN): measured before the change, 3 cut-backs (15 iterations each) and
# 94 Newton iterations; after it, 0 cut-backs and 4 to 7 iterations a step.
# Checked (1 and 2 ranks):
#  - no cut-back, at most 8 Newton iterations in every load step;
#  - statics, exact for any discretisation: at every row the fixed base's
#    force z equals the applied load 0.02 t kN to 1e-8 relative, and so
#    does the pair's force z; the lateral forces of both are below 1e-10 kN
#    (the load is along z and the model symmetric);
#  - all 36 nodes of the block's bottom in contact, none slipping (the
#    rubber's lateral expansion under 0.2 MPa needs mu above the measured
#    tangential / normal force ratio 0.58).
# Usage: contact_closed_gap.sh EXECUTABLE SOURCE_DIR NPROC
set -euo pipefail
exe=$1; source_dir=$2; nproc=$3
source "$source_dir/tests/model/script_helpers.sh"

cat > closed_gap.prm <<PRM
set Study = Model
subsection Mesh
  set Mesh file = $source_dir/parameter_files/meshes/block_on_plate.msh
end
subsection Parts
  set Names = rubber, plate
$(study_rubber_part)
$(elastic_steel_part plate 2)
end
subsection Boundary conditions
  set Names = ground, press
  subsection ground
    set Boundary ids = 4
    set Type         = fixed
  end
  subsection press
    set Boundary ids        = 3
    set Type                = traction
    set Components          = z
    set Function expression = -2e-4 * t
  end
end
$(coulomb_pair interface 1 2 0.8)
subsection Time integration
  set Scheme                = quasi-static
  set Quasi-static end time = 1
  subsection Quasi-static
    set Initial step = 0.25
    set Maximum step = 0.25
  end
end
subsection Output
  set Output directory      = closed_gap
  set Field output interval = 1
end
PRM
run_prm closed_gap.prm closed_gap.log

# The Newton log: iterations per load step, and the run's cut-backs.
awk '
  /Step to t/ { if (n) { if (count > worst) worst = count }; n++; count = 0 }
  /    iteration [0-9]+:/ { ++count }
  /Finished:/ { finished = $0 }
  END {
    if (count > worst) worst = count
    cutbacks = (finished ~ / 0 cut-backs/) ? 0 : 1
    printf "load steps %d, at most %d Newton iterations in one; %s\n", n, worst, (cutbacks ? "cut back" : "no cut-back")
    exit (finished == "" || cutbacks || worst > 8)
  }' closed_gap.log

awk -F, '
  NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
  { t = $c["time"]; load = 0.02 * t
    if (t == 0) next
    for (k = 0; k < 2; ++k) {
      v = k ? $c["interface_force_z"] : $c["ground_force_z"]
      d = (v - load) / load; if (d < 0) d = -d; if (d > statics) statics = d
    }
    split("ground_force_x ground_force_y interface_force_x interface_force_y", lateral, " ")
    for (k in lateral) { v = $c[lateral[k]]; if (v < 0) v = -v; if (v > side) side = v }
    if ($c["interface_active_nodes"] != 36 || $c["interface_slipping_nodes"] != 0) ++bad_nodes
    ratio = $c["interface_tangential_force"] / $c["interface_normal_force"]
    ++rows }
  END {
    printf "%d loaded rows: base and pair force z against the load, largest relative difference %.1e (bound 1e-8)\n", rows, statics
    printf "largest lateral force %.1e kN (bound 1e-10); rows without 36 active, 0 slipping nodes: %d; tangential / normal force at the end %.3f\n", side, bad_nodes, ratio
    exit (rows != 4 || statics > 1e-8 || side > 1e-10 || bad_nodes)
  }' closed_gap/time_history.csv
