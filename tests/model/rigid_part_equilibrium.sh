#!/usr/bin/env bash
# A rigid part in equilibrium on the quasi-static load path (Parts/<name>/
# Quasi-static motion = equilibrium): its free directions are unknowns of
# the Newton system (doc/theory.md, section 14).
# 1. The bonded block (meshes/bonded_block.msh: a Yeoh block 20 x 20 x 10
#    mm on a fixed base, its top bonded to a 2 mm steel plate) with the
#    plate rigid, free in z and ry, pressed by a dead traction on its top
#    that grows linearly across it, t_z = -q (1 + (x - 10) / 10) (resultant
#    -400 q, moment about y), in 10 load steps to q = 1 MPa:
#    - equilibrium of the whole (a conservation law), 1e-8 relative: the
#      base's reaction is minus the load's resultant in z; in x (held) the
#      plate's support balances the base; about y the moments of the base,
#      the load and the plate's support force (at the plate's centre) add
#      up to zero;
#    - Newton converges quadratically (check_newton_log.sh) in at most 4
#      iterations per step, no cut-back (without the geometric stiffness of
#      the turning lever arms every step takes 5, measured);
#    - kinematics: the same rubber block alone (meshes/shear_block.msh, the
#      bonded block's rubber node for node) with its top moved by the
#      plate's final rigid motion as a displacement condition (d_z and the
#      rotation phi about y through the plate's centre of mass, read from
#      the first run's steel_position and steel_rotation_y) has the
#      same base reaction (force x and z, moment y) and the same rubber
#      energy, within 1e-6 relative (the 9 printed digits of the pose and
#      the Newton tolerance).
# 2. The hand-off (quasi-static then explicit) of the same model under a
#    constant traction of 0.2 MPa (the load path starts with it): the plate found by the load path starts the 1 ms
#    explicit run at rest (free in z and ry, with its mass): its rotation
#    equals the load path's to the printed digits, its centre moves less
#    than 1e-6 mm and the kinetic energy stays below 1e-10 of the strain
#    energy.
# 3. A restart from that run's preload checkpoint (Output/Restart from
#    checkpoint, a shorter explicit run) starts the plate at the same pose;
#    with another plate density (its centre of mass moves) it is refused.
# Usage: rigid_part_equilibrium.sh EXECUTABLE SOURCE_DIR NPROC
set -euo pipefail
exe=$1; source_dir=$2; nproc=$3
here=$(cd "$(dirname "$0")" && pwd)
source "$(dirname "$0")/script_helpers.sh"
write_plate() { # NAME SCHEME TRACTION_Z
  cat > "$1.prm" <<PRM
set Study = Model
subsection Mesh
  set Mesh file = $source_dir/parameter_files/meshes/bonded_block.msh
end
$(bonded_block_parts "z, ry")
subsection Boundary conditions
  set Names = base, push
  subsection base
    set Boundary ids = 1
    set Type         = fixed
    set Moment point = 10, 10, 0
  end
  subsection push
    set Boundary ids        = 2
    set Type                = traction
    set Components          = z
    set Function expression = $3
    set Moment point        = 10, 10, 0
  end
end
subsection Time integration
  set Scheme   = $2
  set End time = 1
  subsection Quasi-static
    set Initial step = 0.1
    set Maximum step = 0.1
  end
end
subsection Output
  set Output directory        = $1
  set History output interval = 0
  set Field output interval   = 0
PRM
}

# 1. Equilibrium and kinematics.
write_plate plate quasi-static "-0.001 * t * (1 + (x - 10) / 10)"
echo "end" >> plate.prm
run_prm plate.prm plate.log
grep "Rigid part steel\|^Finished" plate.log
grep -q "^Finished: 10 load steps .* 0 cut-backs" plate.log || { echo "plate: not 10 steps without cut-back"; exit 1; }
bash "$here/check_newton_log.sh" plate.log 1e-1 100 4
# The final pose, then the rubber alone with its top moved by it.
# (Its centre: the first row's position, t = 0.)
read -r cx cz dz phi < <(awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
  NR == 2 { x0 = $c["steel_position_x"]; z0 = $c["steel_position_z"] }
  { z = $c["steel_position_z"] - z0; p = $c["steel_rotation_y"] }
  END { printf "%.9g %.9g %.9g %.9g\n", x0, z0, z, p }' plate/time_history.csv)
echo "plate: centre of mass x = $cx, z = $cz mm; moved d_z = $dz mm, turned phi_y = $phi rad"
cat > rubber.prm <<PRM
set Study = Model
subsection Mesh
  set Mesh file = $source_dir/parameter_files/meshes/shear_block.msh
end
subsection Parts
  set Names = rubber
$(study_rubber_part)
end
subsection Boundary conditions
  set Names = base, top
  subsection base
    set Boundary ids = 1
    set Type         = fixed
    set Moment point = 10, 10, 0
  end
  subsection top
    set Boundary ids        = 2
    set Type                = displacement
    set Components          = x, y, z
    set Function expression = (cos(p * t) - 1) * (x - a) + sin(p * t) * (z - c); \\
                              0; \\
                              d * t - sin(p * t) * (x - a) + (cos(p * t) - 1) * (z - c)
    set Function constants  = a = $cx, c = $cz, d = $dz, p = $phi
  end
end
subsection Time integration
  set Scheme = quasi-static
  subsection Quasi-static
    set Initial step = 0.25
    set Maximum step = 0.25
  end
end
subsection Output
  set Output directory        = rubber
  set History output interval = 0
  set Field output interval   = 0
end
PRM
run_prm rubber.prm rubber.log
grep "^Finished" rubber.log
paste -d, <(tail -n 1 plate/time_history.csv) <(tail -n 1 rubber/time_history.csv) > last.csv
paste -d, <(head -n 1 plate/time_history.csv | sed 's/\([^,]*\)/p:\1/g') \
          <(head -n 1 rubber/time_history.csv | sed 's/\([^,]*\)/r:\1/g') > names.csv
cat names.csv last.csv | awk -F, '
  function abs(x) { return x < 0 ? -x : x }
  function rel(a, b) { return abs(a - b) / abs(b) }
  NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
  {
    # Equilibrium of the whole: the base carries the load in z (the
    # plate is free in z); in x the plate is held, and its support acts
    # at its centre c with the force -steel_force_x, which the base
    # balances; about y (free) the moments of the base, the load and that
    # support force about the base centre (10, 10, 0) add up to zero.
    load = $c["p:push_force_z"]
    balance = abs($c["p:base_force_z"] + load) / abs(load)
    support_x = -$c["p:steel_force_x"]
    lateral = abs($c["p:base_force_x"] + support_x) / abs(support_x)
    support_moment = $c["p:steel_position_z"] * support_x
    moment = abs($c["p:base_moment_y"] + $c["p:push_moment_y"] + support_moment) / abs($c["p:push_moment_y"])
    printf "z: load %.9g kN, base %.9g kN: balance %.1e; x: base %.9g kN, plate support %.9g kN: balance %.1e\n", load, $c["p:base_force_z"], balance, $c["p:base_force_x"], support_x, lateral
    printf "moments y about the base centre: base %.9g, load %.9g, plate support %.9g kN mm: balance %.1e\n", $c["p:base_moment_y"], $c["p:push_moment_y"], support_moment, moment
    worst = 0
    split("base_force_x base_force_z base_moment_y rubber_internal_energy", names, " ")
    for (k = 1; k <= 4; ++k) {
      a = $c["p:" names[k]]; b = $c["r:" names[k]]
      e = rel(a, b); if (e > worst) worst = e
      printf "  %s: rigid plate %.9g, displaced top %.9g (%.1e)\n", names[k], a, b, e
    }
    printf "rigid plate vs its motion prescribed: %.1e\n", worst
    exit (balance > 1e-8 || lateral > 1e-8 || moment > 1e-8 || worst > 1e-6 || abs($c["p:steel_rotation_y"]) < 1e-3)
  }'

# 2. The hand-off: the plate found by the load path starts the explicit
#    run at rest.
write_plate handoff "quasi-static then explicit" "-0.0002 * (1 + (x - 10) / 10)"
echo "  set History output interval = 0.05" >> handoff.prm
echo "end" >> handoff.prm
run_prm handoff.prm handoff.log
grep "Rigid part steel\|^Finished" handoff.log
preload_phi=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
  { p = $c["steel_rotation_y"] } END { printf "%.9g", p }' handoff/preload/time_history.csv)
awk -F, -v phi="$preload_phi" '
  function abs(x) { return x < 0 ? -x : x }
  NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
  {
    if (NR == 2) { z0 = $c["steel_position_z"]; first_phi = $c["steel_rotation_y"] }
    z = abs($c["steel_position_z"] - z0); if (z > worst_z) worst_z = z
    k = $c["kinetic_energy"] / $c["internal_energy"]; if (k > worst_k) worst_k = k
    ++rows
  }
  END {
    printf "%d rows to t = %s ms: plate rotation %.9g (load path %.9g), centre moved %.1e mm, kinetic / strain energy %.1e\n", rows, $c["time"], first_phi, phi, worst_z, worst_k
    exit (rows < 20 || abs(first_phi - phi) > 1e-8 * abs(phi) || abs(phi) < 1e-4 || worst_z > 1e-6 || worst_k > 1e-10)
  }' handoff/time_history.csv

# 3. The preload checkpoint keeps the plate's pose: a restart from it (a
#    shorter explicit run, the load path skipped) starts the plate where
#    the load path left it.
sed -e 's|  set End time = 1|  set End time = 0.2|' \
    -e 's|^subsection Output$|subsection Output\n  set Restart from checkpoint = true|' handoff.prm > restart.prm
run_prm restart.prm restart.log
grep -q "Newton" restart.log && { echo "restart: the load path ran again"; exit 1; }
awk -F, -v phi="$preload_phi" '
  function abs(x) { return x < 0 ? -x : x }
  NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
  NR == 2 { first_phi = $c["steel_rotation_y"] }
  { k = $c["kinetic_energy"] / $c["internal_energy"]; if (k > worst_k) worst_k = k; ++rows }
  END {
    printf "restart from the preload: %d rows, plate rotation %.9g (load path %.9g), kinetic / strain energy %.1e\n", rows, first_phi, phi, worst_k
    exit (rows < 4 || abs(first_phi - phi) > 1e-8 * abs(phi) || worst_k > 1e-10)
  }' handoff/time_history.csv
# Another density moves the plate's centre of mass, about which the load
#    path balanced it: that restart is refused, naming the entry.
sed -e 's|    set Density             = 7.85e-6|    set Density             = 2e-6|' restart.prm > restart_density.prm
if run_prm restart_density.prm restart_density.log 2> restart_density.err; then
  echo "restart with another density: not refused"; exit 1
fi
grep -q "entry 'Output/Restart from checkpoint': the centre of mass of the rigid part 'steel'" restart_density.err ||
  { echo "restart with another density: wrong message"; cat restart_density.err; exit 1; }
echo "restart with another plate density: refused ($(grep -o "has moved ([^)]*)" restart_density.err | head -1))"
