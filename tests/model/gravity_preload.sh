#!/usr/bin/env bash
# Gravity on the quasi-static load path (model::GravityLoad): the weight of
# every node (its lumped mass times Model/Gravity) grows linearly with the
# pseudo-time to its full value at the end of the load path.
# The bonded block (meshes/bonded_block.msh: a Yeoh block 20 x 20 x 10 mm,
# density 1.1e-6 kg/mm^3, on a fixed base, bonded to a 2 mm steel plate,
# 7.85e-6 kg/mm^3) with the plate rigid and in equilibrium in z, under 1000
# g (0, 0, -9.81 mm/ms^2, to make the sag visible: 0.34 mm):
# 1. the base carries the whole weight at every step, t * 9.81 (4000 * 1.1e-6
#    + 800 * 7.85e-6) = t * 0.1047708 kN (a closed form; 1e-8 relative),
#    and the plate sinks;
# 2. the hand-off (quasi-static then explicit, 1 ms) starts in equilibrium
#    under the gravity the explicit run applies: the plate does not move
#    (1e-9 mm), the kinetic energy stays below 1e-10 of the strain energy and
#    the base still carries the weight;
# 3. the densities now weigh on the preload: a restart from its checkpoint
#    with another rubber density is refused, naming the entry.
# Usage: gravity_preload.sh EXECUTABLE SOURCE_DIR NPROC
set -euo pipefail
exe=$1; source_dir=$2; nproc=$3
source "$(dirname "$0")/script_helpers.sh"
write() { # NAME SCHEME
  cat > "$1.prm" <<PRM
set Study = Model
subsection Model
  set Gravity = 0, 0, -9.81
end
subsection Mesh
  set Mesh file = $source_dir/parameter_files/meshes/bonded_block.msh
end
$(bonded_block_parts "z")
subsection Boundary conditions
  set Names = base
  subsection base
    set Boundary ids = 1
    set Type         = fixed
  end
end
subsection Time integration
  set Scheme   = $2
  set End time = 1
  subsection Quasi-static
    set Initial step = 0.25
    set Maximum step = 0.25
  end
end
subsection Output
  set Output directory        = $1
  set History output interval = 0.05
  set Field output interval   = 0
end
PRM
}

# 1. The load path.
write load_path quasi-static
run_prm load_path.prm load_path.log
grep "Gravity\|^Finished" load_path.log
awk -F, '
  function abs(x) { return x < 0 ? -x : x }
  NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
  {
    weight = $1 * 9.81 * (4000 * 1.1e-6 + 800 * 7.85e-6)
    if (weight > 0) { e = abs($c["base_force_z"] - weight) / weight; if (e > worst) worst = e }
    if (NR == 2) z0 = $c["steel_position_z"]
    sag = z0 - $c["steel_position_z"]
    ++rows
  }
  END {
    printf "%d rows: base vs t * 0.1047708 kN %.1e; the plate sank %.4f mm\n", rows, worst, sag
    exit (rows != 5 || worst > 1e-8 || sag < 0.1)
  }' load_path/time_history.csv

# 2. The hand-off.
write handoff "quasi-static then explicit"
run_prm handoff.prm handoff.log
grep "^Finished" handoff.log
awk -F, '
  function abs(x) { return x < 0 ? -x : x }
  NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
  {
    if (NR == 2) z0 = $c["steel_position_z"]
    z = abs($c["steel_position_z"] - z0); if (z > moved) moved = z
    k = $c["kinetic_energy"] / $c["internal_energy"]; if (k > worst_k) worst_k = k
    e = abs($c["base_force_z"] - 0.1047708) / 0.1047708; if (e > worst_base) worst_base = e
    ++rows
  }
  END {
    printf "%d rows to %s ms: plate moved %.1e mm, kinetic / strain energy %.1e, base vs the weight %.1e\n", rows, $1, moved, worst_k, worst_base
    exit (rows < 20 || moved > 1e-9 || worst_k > 1e-10 || worst_base > 1e-8)
  }' handoff/time_history.csv

# 3. Another density for the restart.
sed -e 's|    set Density             = 1.1e-6|    set Density             = 1.2e-6|' \
    -e 's|^subsection Output$|subsection Output\n  set Restart from checkpoint = true|' handoff.prm > restart.prm
if run_prm restart.prm restart.log 2> restart.err; then
  echo "a restart with another density under gravity was not refused"; exit 1
fi
grep -q "entry 'Output/Restart from checkpoint': the model differs from the preload's .*Density" restart.err ||
  { echo "wrong message:"; cat restart.err; exit 1; }
echo "restart with another rubber density under gravity: refused"
