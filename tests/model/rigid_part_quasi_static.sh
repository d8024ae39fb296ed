#!/usr/bin/env bash
# Rigid parts in the quasi-static solver stand still (statics cannot place a
# body that nothing loads; a rigid part's motion is the explicit run's).
# 1. The bonded block (meshes/bonded_block.msh: a Yeoh block, its top
#    bonded to a steel plate) with the steel as a rigid part, the rubber's
#    base pushed up 2 mm in 4 load steps: the plate's nodes do not move
#    (history nodes at the plate's top corner and at the bonded interface:
#    |u| = 0), the force of the solid on the plate (steel_force_z) equals
#    the base's reaction to 1e-10 relative, no lateral force (1e-10), no
#    cut-back; and the rubber's reaction equals that of the same model with
#    the plate elastic (210 GPa, 2e5 times the rubber's modulus) and its top
#    fixed, within 1e-4 (a held rigid plate is a clamped rigid plate; the
#    difference is the steel's compliance, measured 1.5e-5), the rigid one
#    the stiffer.
# 2. The hand-off (quasi-static then explicit) with a free rigid part:
#    meshes/rigid_drop.msh, a rubber block under a follower pressure on its
#    top (0.2 MPa), and 5 mm above it a rigid steel block with an initial
#    velocity of -2 mm/ms and an angular velocity of 0.02 rad/ms about x.
#    On the load path the block stands still; in the 2 ms explicit run
#    before it reaches the rubber it moves uniformly: its centre at
#    z = 17.5 - 2 t (1e-7 mm: the 9 printed digits), its velocity -2
#    (1e-12), while the preloaded
#    rubber stays quiet (its kinetic energy below 1e-12 of its strain
#    energy).
# Usage: rigid_part_quasi_static.sh EXECUTABLE SOURCE_DIR NPROC
set -euo pipefail
exe=$1; source_dir=$2; nproc=$3
source "$(dirname "$0")/script_helpers.sh"
write_bonded() { # NAME STEEL_MODEL EXTRA_NAME EXTRA_SUBSECTION
  cat > "$1.prm" <<PRM
set Study = Model
subsection Mesh
  set Mesh file = $source_dir/parameter_files/meshes/bonded_block.msh
end
subsection Parts
  set Names = rubber, steel
$(study_rubber_part)
  subsection steel
    set Material ids        = 2
    set Model               = $2
    set Young's modulus     = 210
    set Poisson's ratio     = 0.3
    set Density             = 7.85e-6
  end
end
subsection Boundary conditions
  set Names = base$3
  subsection base
    set Boundary ids        = 1
    set Type                = displacement
    set Components          = z
    set Function expression = 2 * t
  end
$4
end
subsection Time integration
  set Scheme = quasi-static
  subsection Quasi-static
    set Initial step = 0.25
    set Maximum step = 0.25
  end
end
subsection Output
  set Output directory        = $1
  set History output interval = 0
  set History nodes           = corner: 0, 0, 12; interface: 10, 10, 10
end
PRM
}
write_bonded rigid Rigid "" ""
write_bonded elastic Elastic ", top" "  subsection top
    set Boundary ids = 2
    set Type         = fixed
  end"
run_prm rigid.prm rigid.log
run_prm elastic.prm elastic.log
grep "Rigid part steel" rigid.log
grep -q "^Finished: 4 load steps .* 0 cut-backs" rigid.log || { echo "rigid: not 4 steps without cut-back"; exit 1; }
paste -d, rigid/time_history.csv elastic/time_history.csv | awk -F, '
  function abs(x) { return x < 0 ? -x : x }
  NR == 1 { for (i = 1; i <= NF; ++i) if (!($i in c)) c[$i] = i; else e[$i] = i; next }
  $1 > 0 {
    F = $c["base_force_z"]
    balance = abs($c["steel_force_z"] - F) / F; if (balance > worst_balance) worst_balance = balance
    lateral = (abs($c["steel_force_x"]) + abs($c["steel_force_y"])) / F; if (lateral > worst_lateral) worst_lateral = lateral
    for (d = 1; d <= 3; ++d) {
      u = abs($c["corner_displacement_" substr("xyz", d, 1)]) + abs($c["interface_displacement_" substr("xyz", d, 1)])
      if (u > moved) moved = u
    }
    clamped = F / $e["base_force_z"] - 1
    if (abs(clamped) > worst_clamped) worst_clamped = abs(clamped)
    if (clamped < 0) softer = 1
    printf "t %.2f: base %.9g kN, rigid plate %.9g kN, elastic clamped plate %.9g kN (%+.2e)\n", $1, F, $c["steel_force_z"], $e["base_force_z"], clamped
    ++rows
  }
  END {
    printf "%d steps: balance %.1e, lateral %.1e, plate nodes moved %.1e mm, rigid vs clamped elastic plate %.1e\n", rows, worst_balance, worst_lateral, moved, worst_clamped
    exit (rows != 4 || worst_balance > 1e-10 || worst_lateral > 1e-10 || moved > 0 || worst_clamped > 1e-4 || softer)
  }'

# 2. The hand-off with a free rigid part.
sed -e "s|set Mesh file *= *meshes/|set Mesh file = $source_dir/parameter_files/meshes/|" \
    -e "s|set Gravity *=.*|set Gravity = 0, 0, 0|" \
    -e "s|set End time *=.*|set End time = 2\n  set Scheme = quasi-static then explicit|" \
    -e "s|set Names = floor|set Names = floor, load|" \
    -e "s|set Output directory *=.*|set Output directory = drop|" \
    -e "s|set Field output interval *=.*|set Field output interval = 0|" \
    -e "s|set History output interval *=.*|set History output interval = 0.05|" \
    "$source_dir/parameter_files/rigid_drop.prm" > drop.prm
cat >> drop.prm <<PRM
subsection Boundary conditions
  subsection load
    set Boundary ids        = 2
    set Type                = pressure
    set Function expression = 0.0002
  end
end
PRM
run_prm drop.prm drop.log
grep "Rigid part block\|^Finished" drop.log
awk -F, '
  function abs(x) { return x < 0 ? -x : x }
  NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
  {
    t = $c["time"]
    z = abs($c["block_position_z"] - (17.5 - 2 * t)); if (z > worst_z) worst_z = z
    v = abs($c["block_velocity_z"] + 2); if (v > worst_v) worst_v = v
    k = $c["rubber_kinetic_energy"] / $c["rubber_internal_energy"]; if (k > worst_k) worst_k = k
    ++rows
  }
  END {
    printf "%d rows to t = %.2f: block centre vs 17.5 - 2 t %.1e mm, velocity vs -2 %.1e, rubber kinetic / strain energy %.1e\n", rows, t, worst_z, worst_v, worst_k
    exit (rows < 40 || worst_z > 1e-7 || worst_v > 1e-12 || worst_k > 1e-12)
  }' drop/time_history.csv
