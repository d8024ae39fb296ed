#!/usr/bin/env bash
# The tutorial (doc/tutorial/) runs as shipped and says what its pages say:
# parameter_files/tutorial/1_free_flight.prm ... 5_preload_then_drag.prm,
# unchanged, in the working directory (their results go to
# output/tutorial/<step>/ below it). Checked, step by step (the numbers the
# pages quote, measured 2026-12-07, in brackets):
#  1. free flight: kinetic energy 1/2 m |v0|^2 = 0.0569125 J on every row
#     to 1e-9 relative (m = 500 mm^3 x 7.85e-6 kg/mm^3; the steel block
#     flies free, so only round-off may change it), no internal energy;
#     the last row at the End time or less than a step after it;
#  2. the impact: contact from 0.2 ms (1 mm gap at 5 mm/ms; within one
#     history row, 0.01 ms), largest energy error below 0.1 % (0.039 %; the
#     run warns at 1 %, and the rubber-top-as-slave variant the page warns
#     about makes 2.1 %), peak normal force 0.317 kN within 2 %, no
#     WARNING in the log;
#  3. the tied bond: all 81 nodes of the rubber's bottom tied, largest
#     energy error below 0.1 % (0.074 %);
#  4. the quasi-static press with default solver settings: reaches t = 3
#     without a cut-back, the first step's free flight logs no energy
#     (below 1e-12 J: 6.8e-29), press force at t = 1 -0.2239 kN within 1 %, drag
#     force at t = 3 0.0381 kN within 2 % (the page's numbers, rounded);
#  5. the hand-off: until the drag starts at 1 ms the kinetic energy stays
#     below 1e-10 of the strain energy (3e-20; issue 43 asks for 1e-3) and
#     the held press force equals the preload's last to 1e-8 relative (the
#     Newton tolerance), largest energy error below 0.1 % (0.030 %), the
#     explicit drag force at 1 mm of drag (t = 2.5 ms) within 10 % of the
#     quasi-static one at the same drag (2.3 %: inertia and ringing).
# And, where gmsh 4.8.4 is installed, the two meshes regenerate from
# block_impact.geo byte for byte (as parameter_files/meshes/regenerate.sh).
# Usage: tutorial.sh EXECUTABLE SOURCE_DIR NPROC
set -euo pipefail
exe=$1; source_dir=$2; nproc=${3:-1}
dir=$source_dir/parameter_files/tutorial

run() { # STEP: run parameter_files/tutorial/STEP.prm, log to STEP.log
  if [ "$nproc" -gt 1 ]; then
    mpirun --oversubscribe -np "$nproc" "$exe" "$dir/$1.prm" > "$1.log"
  else
    "$exe" "$dir/$1.prm" > "$1.log"
  fi
  echo "tutorial: $1: $(grep '^Finished' "$1.log" | tail -1)"
}
fail() { echo "tutorial: FAILED: $*" >&2; exit 1; }
# column CSV NAME: the values of the column NAME, one per row
column() {
  awk -F, -v name="$2" 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == name) c = i;
    if (!c) { print "no column " name > "/dev/stderr"; exit 1 } next } { print $c }' "$1"
}
# check DESCRIPTION AWK_CONDITION [VARIABLES...]: fail unless the condition holds
check() {
  local what=$1 cond=$2; shift 2
  awk "$@" "BEGIN { exit !($cond) }" || fail "$what"
  echo "tutorial: ok: $what"
}

run 1_free_flight
h=output/tutorial/1_free_flight/time_history.csv
ke=$(column $h kinetic_energy | awk '{ d = $1 / 0.0569125 - 1; if (d < 0) d = -d; if (d > m) m = d } END { print m + 0 }')
ie=$(column $h internal_energy | awk '{ if ($1 > m) m = $1 } END { print m + 0 }')
check "step 1: kinetic energy constant ($ke)" "ke <= 1e-9 && ie == 0" -v ke="$ke" -v ie="$ie"
# The last row is the end state's: at or just past End time = 0.15 ms, less
# than a step after it (issue 43: the last step had no row).
last=$(column $h time | tail -1); dt=$(column $h time_step | tail -1)
check "step 1: last row at t = $last ms (step $dt ms)" "last >= 0.15 && last < 0.15 + dt" -v last="$last" -v dt="$dt"

run 2_impact
h=output/tutorial/2_impact/time_history.csv
grep -q WARNING 2_impact.log && fail "step 2 warns: $(grep WARNING 2_impact.log)"
first=$(paste -d, <(column $h time) <(column $h impact_normal_force) | awk -F, '$2 > 0 { print $1; exit }')
peak=$(column $h impact_normal_force | sort -g | tail -1)
err=$(column $h energy_error | sort -g | tail -1)
check "step 2: contact from $first ms, peak $peak kN, energy error $err" \
  "first >= 0.19 && first <= 0.21 && peak > 0.317 * 0.98 && peak < 0.317 * 1.02 && err < 1e-3" \
  -v first="$first" -v peak="$peak" -v err="$err"

run 3_tied
h=output/tutorial/3_tied/time_history.csv
tied=$(column $h bond_active_nodes | sort -g | head -1)
err=$(column $h energy_error | sort -g | tail -1)
check "step 3: $tied nodes tied, energy error $err" "tied == 81 && err < 1e-3" -v tied="$tied" -v err="$err"

run 4_press
h=output/tutorial/4_press/time_history.csv
grep -q '"reached_end": true' output/tutorial/4_press/run_summary.json || fail "step 4 did not reach its end"
grep -q '"cutbacks": 0,' output/tutorial/4_press/run_summary.json || fail "step 4 cut back"
press=$(paste -d, <(column $h time) <(column $h press_force_z) | awk -F, '$1 == 1 { print $2 }')
drag=$(column $h drag_force_x | tail -1)
check "step 4: press $press kN at t = 1, drag $drag kN at t = 3" \
  "press < -0.2239 * 0.99 && press > -0.2239 * 1.01 && drag > 0.0381 * 0.98 && drag < 0.0381 * 1.02" \
  -v press="$press" -v drag="$drag"
# The Newton log's energy of the first step's predictor: the block's 0.3 mm
# of free flight, a rigid motion, puts no energy into the model (0.04 J at
# the end); until 2026-12-08 it read 1.018e+03 J (the prescribed dofs'
# right-hand side -K_fc du_c, issue 43).
first_energy=$(awk '/Step to t = 0.1 /{ s = 1 } s && /iteration 1:/ { sub(/.*energy /, ""); print $1; exit }' 4_press.log)
check "step 4: the free flight's first Newton energy $first_energy J" "e < 1e-12" -v e="$first_energy"
qs_drag=$(paste -d, <(column $h time) <(column $h drag_force_x) | awk -F, '$1 == 2.5 { print $2 }')

run 5_preload_then_drag
h=output/tutorial/5_preload_then_drag/time_history.csv
p=output/tutorial/5_preload_then_drag/preload/time_history.csv
held=$(column $p press_force_z | tail -1)
rest=$(paste -d, <(column $h time) <(column $h kinetic_energy) <(column $h internal_energy) <(column $h press_force_z) |
  awk -F, -v held="$held" '$1 < 1 { k = $2 / $3; if (k > m) m = k; d = $4 / held - 1; if (d < 0) d = -d; if (d > dm) dm = d }
    END { print m + 0, dm + 0 }')
err=$(column $h energy_error | sort -g | tail -1)
ex_drag=$(paste -d, <(column $h time) <(column $h drag_force_x) | awk -F, '$1 >= 2.5 { print $2; exit }')
check "step 5: at rest before the drag (kinetic / strain energy, held force drift: $rest), energy error $err, drag $ex_drag kN against $qs_drag quasi-static" \
  "k <= 1e-10 && d <= 1e-8 && err < 1e-3 && ex / qs > 0.9 && ex / qs < 1.1" \
  -v k="${rest% *}" -v d="${rest#* }" -v err="$err" -v ex="$ex_drag" -v qs="$qs_drag"

if command -v gmsh > /dev/null && [ "$(gmsh --version 2>&1)" = "4.8.4" ]; then
  home=$(mktemp -d)
  for shared in 0 1; do
    name=$([ $shared = 0 ] && echo tied || echo shared)
    HOME=$home gmsh -3 -format msh22 -setnumber shared $shared "$dir/block_impact.geo" \
      -o "block_impact_$name.msh" > /dev/null
    cmp -s "block_impact_$name.msh" "$dir/block_impact_$name.msh" ||
      fail "block_impact_$name.msh differs from what block_impact.geo makes"
  done
  rm -rf "$home"
  echo "tutorial: ok: the meshes regenerate byte for byte"
fi
echo "tutorial: passed"
