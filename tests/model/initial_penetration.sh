#!/usr/bin/env bash
# Initial penetrations (issue 43, "the newcomer's path"): a steel block
# that starts 0.3 mm inside the rubber block it is to hit.
#
# The mesh: meshes/stacked_blocks.msh (rubber 10 x 10 x 5 mm, 4 x 4 x 2
# cells, top z = 5, surface 2; steel 10 x 10 x 5 mm, 5 x 5 x 3 cells,
# bottom z = 5.05, surface 3) with the steel block's nodes moved down by
# 0.35 mm: its bottom at z = 4.7, 0.3 mm below the rubber's top over the
# whole face. The steel falls at 5 m/s onto the rubber, whose bottom is
# fixed, through a Coulomb pair (mu 0.2), the rubber's top the slave.
# What the geometry says: all 5 x 5 = 25 slave nodes of the rubber's top
# penetrate, each by 0.3 mm (two flat faces: every mean gap is the
# distance); of equal ones the report names the lowest in x, y, z: the
# corner (0, 0, 5).
#
# Checked (1 and 2 ranks):
#  (a) Initial penetration = report: the log line with 25 nodes, 0.3 mm at
#      (0, 0, 5), and the same in run_summary.json; the run keeps the
#      overlap, as before the check: the first row's pair force is the
#      penalty's eps A g (above 10 times the whole impact's peak force of
#      (b)), and the steel block leaves with more kinetic energy than it
#      came with (the symptom of the issue).
#  (b) Initial penetration = move slave nodes out: the log line (25 nodes
#      moved by up to 0.3 mm); the rubber's top is then at z = 4.7, so the
#      lumped mass is rho_s 500 mm^3 + rho_r 470 mm^3 (to 1e-9, relative);
#      the first row's pair force is below 1e-6 of the impact's peak (it is
#      the round-off of a zero gap); the energy balance closes: the energy
#      error stays below 1 % of the impact energy m v^2 / 2 = 0.0490625 J
#      (steel 3.925e-3 kg at 5 mm/ms) at every row (the run's own warning
#      threshold).
#  (c) The rigid surfaces: meshes/bar.msh (100 x 10 x 10 mm along x, end
#      x = 0 surface 1, 2 x 2 faces) against a rigid plane at x = 0.3 with
#      normal +x: its 9 end nodes are 0.3 mm inside; --check logs the line
#      with Contact/Initial penetration = report, and with move slave nodes
#      out the bar is 99.7 mm long (lumped mass 7.85e-6 * 9970 kg).
#  (d) The other paths log the same once: --check of the quasi-static
#      scheme and of quasi-static then explicit (whose explicit run builds
#      after the load path's and finds the nodes moved: one line, and its
#      lumped mass is (b)'s).
# Usage: initial_penetration.sh EXECUTABLE SOURCE_DIR NPROC
set -euo pipefail
exe=$1; source_dir=$2; nproc=$3
source "$source_dir/tests/model/script_helpers.sh"

# The overlapping mesh (the same as tests/bad_input/meshes/
# overlapping_blocks.msh).
awk '
  /^\$Nodes/ { nodes = 1; print; next }
  /^\$EndNodes/ { nodes = 0 }
  nodes && NF == 4 && $4 > 5.02 { printf "%s %s %s %.12g\n", $1, $2, $3, $4 - 0.35; next }
  /^2 [34] "upper/ { sub(/10\.05/, "9.7"); sub(/5\.05/, "4.7") }
  { print }' "$source_dir/parameter_files/meshes/stacked_blocks.msh" > overlapping_blocks.msh

# overlap_model NAME CHOICE [SCHEME [END_TIME]]: the model with Initial
# penetration = CHOICE, output to NAME (the steel at rest in the
# quasi-static schemes, which take no initial velocity).
overlap_model() {
  cat <<PRM
set Study = Model
subsection Mesh
  set Mesh file = overlapping_blocks.msh
end
subsection Parts
  set Names = rubber, steel
$(study_rubber_part)
  subsection steel
    set Material ids     = 2
    set Model            = Elastic
    set Young's modulus  = 210
    set Poisson's ratio  = 0.3
    set Density          = 7.85e-6
    set Initial velocity = $([ "${3:-explicit}" = explicit ] && echo "0, 0, -5" || echo "0, 0, 0")
  end
end
subsection Boundary conditions
  set Names = ground
  subsection ground
    set Boundary ids = 1
    set Type         = fixed
  end
end
subsection Contact pairs
  set Names = impact
  subsection impact
    set Slave boundary ids           = 2
    set Master boundary ids          = 3
    set Type                         = Coulomb
    set Static friction coefficient  = 0.2
    set Dynamic friction coefficient = 0.2
    set Initial penetration          = $2
  end
end
subsection Time integration
  set Scheme   = ${3:-explicit}
  set End time = ${4:-1.2}
end
subsection Output
  set Output directory        = $1
  set Field output interval   = 0
  set History output interval = 0.01
end
PRM
}

# check_prm PRM LOG: rubberdyn --check PRM on $nproc ranks, the log to LOG.
check_prm() {
  if [ "$nproc" -gt 1 ]; then
    mpirun --oversubscribe -np "$nproc" "$exe" --check "$1" > "$2"
  else
    "$exe" --check "$1" > "$2"
  fi
}

# column CSV NAME ROW: the value of column NAME in data row ROW (1: first).
column() {
  awk -F, -v name="$2" -v row="$3" '
    NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
    NR == row + 1 { printf "%.17g", $c[name] }' "$1"
}
# largest CSV NAME: the largest |value| of column NAME.
largest() {
  awk -F, -v name="$2" '
    function abs(x) { return x < 0 ? -x : x }
    NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
    abs($c[name]) > m { m = abs($c[name]) } END { printf "%.17g", m }' "$1"
}
# require TEXT CONDITION: print TEXT, fail unless the awk CONDITION holds.
require() {
  echo "$1"
  awk "BEGIN { exit !($2) }" || { echo "FAILED: $2"; exit 1; }
}

# (a) report (to 0.1 ms: the push from the overlap folds the rubber's
# elements at 0.31 ms, F-bar's hull collapse ends the run there)
overlap_model report report explicit 0.1 > report.prm
run_prm report.prm report.log
expected_report="WARNING: Contact pairs/impact: 25 slave nodes start inside the master surface, by up to 0.3 mm (at (0, 0, 5)); kept (Contact pairs/impact/Initial penetration = report): the penalty pushes them out from the first step"
[ "$(grep -c "Initial penetration" report.log)" = 1 ] ||
  { echo "one line expected:"; cat report.log; exit 1; }
grep -qF "$expected_report" report.log ||
  { echo "(a) no report line:"; cat report.log; exit 1; }
echo "(a) $(grep -F "Contact pairs/impact:" report.log | sed 's/^ *//')"
grep -qF '"initial_penetrations": [{"interaction": "Contact pairs/impact", "nodes": 25, "max_penetration": 0.3, "at": [0, 0, 5], "action": "report", "moved_nodes": 0, "max_move": 0}]' report/run_summary.json ||
  { echo "(a) run_summary.json:"; grep initial_penetrations report/run_summary.json; exit 1; }

# (b) move slave nodes out
overlap_model move "move slave nodes out" > move.prm
run_prm move.prm move.log
grep -qF "Contact pairs/impact: 25 slave nodes start inside the master surface, by up to 0.3 mm (at (0, 0, 5)); moved out onto it (Contact pairs/impact/Initial penetration = move slave nodes out): 25 nodes' reference coordinates changed, by up to 0.3 mm" move.log ||
  { echo "(b) no move line:"; cat move.log; exit 1; }
echo "(b) $(grep -F "Contact pairs/impact:" move.log | sed 's/^ *//')"
grep -qF '"action": "move slave nodes out", "moved_nodes": 25, "max_move": 0.3}]' move/run_summary.json ||
  { echo "(b) run_summary.json:"; grep initial_penetrations move/run_summary.json; exit 1; }
mass=$(sed -n 's/.*Lumped mass \([^ ]*\) kg.*/\1/p' move.log)
require "(b) lumped mass $mass kg, rho_s 500 + rho_r 470 mm^3 = 0.004442 kg" \
  "$mass / (7.85e-6 * 500 + 1.1e-6 * 470) - 1 < 1e-9 && 1 - $mass / (7.85e-6 * 500 + 1.1e-6 * 470) < 1e-9"
peak=$(largest move/time_history.csv impact_normal_force)
first=$(column move/time_history.csv impact_normal_force 1)
require "(b) pair normal force: first row $first kN, peak $peak kN" \
  "$peak > 0.01 && ($first < 0 ? -$first : $first) < 1e-6 * $peak"
# (energy_error is relative to the run's largest energy, here the impact
# energy; 1 %: the bound at which a run warns.)
energy_error=$(largest move/time_history.csv energy_error)
require "(b) largest |energy error| $energy_error of the impact energy m v^2 / 2 = 0.0490625 J" \
  "$energy_error < 0.01"
# (a) against (b)
first_report=$(column report/time_history.csv impact_normal_force 1)
kinetic_report=$(largest report/time_history.csv kinetic_energy)
# The pair's penalty per area is K/h of the rubber under the slave facets
# (doc/contact.md, section 4; penalty scale 1): the Yeoh rubber's bulk
# modulus K = 2 mu (1 + nu) / (3 (1 - 2 nu)), mu = 2 C10 = 1.1e-3 GPa,
# nu = 0.499, over h = V/A = 2.5 mm; on A = 100 mm^2 with g = 0.3 mm the
# first evaluation pushes with eps A g = 6.5956 kN.
require "(a) first row's pair force $first_report kN, eps A g = 6.5956 kN; largest kinetic energy $kinetic_report J (> 1.5 x the impact's 0.0490625 J)" \
  "$first_report / (2 * 1.1e-3 * 1.499 / (3 * 0.002) / 2.5 * 100 * 0.3) - 1 < 1e-6 && 1 - $first_report / (2 * 1.1e-3 * 1.499 / (3 * 0.002) / 2.5 * 100 * 0.3) < 1e-6 && $first_report > 10 * $peak && $kinetic_report > 1.5 * 0.0490625"

# (c) a rigid plane at x = 0.3 against the bar's end x = 0.
rigid_model() {
  cat <<PRM
$(steel_bar_model)
subsection Rigid surfaces
  set Names = wall
  subsection wall
    set Shape        = plane
    set Point        = 0.3, 0, 0
    set Direction    = 1, 0, 0
    set Boundary ids = 1
  end
end
subsection Contact
  set Initial penetration = $1
end
subsection Output
  set Output directory = rigid
end
PRM
}
rigid_model report > rigid_report.prm
rigid_model "move slave nodes out" > rigid_move.prm
check_prm rigid_report.prm rigid_report.log
check_prm rigid_move.prm rigid_move.log
grep -qF "WARNING: Rigid surfaces/wall: 9 nodes of its Boundary ids start inside the rigid surface 'wall', by up to 0.3 mm (at (0, 0, 0)); kept (Contact/Initial penetration = report)" rigid_report.log ||
  { echo "(c) no report line:"; cat rigid_report.log; exit 1; }
grep -qF "Rigid surfaces/wall: 9 nodes of its Boundary ids start inside the rigid surface 'wall', by up to 0.3 mm (at (0, 0, 0)); moved out onto it (Contact/Initial penetration = move slave nodes out): 9 nodes' reference coordinates changed, by up to 0.3 mm" rigid_move.log ||
  { echo "(c) no move line:"; cat rigid_move.log; exit 1; }
echo "(c) $(grep -F "Rigid surfaces/wall:" rigid_move.log | sed 's/^ *//')"
mass=$(sed -n 's/.*Lumped mass \([^ ]*\) kg.*/\1/p' rigid_move.log)
require "(c) lumped mass $mass kg, 7.85e-6 * 9970 mm^3 = 0.0782645 kg" \
  "$mass / (7.85e-6 * 9970) - 1 < 1e-9 && 1 - $mass / (7.85e-6 * 9970) < 1e-9"

# (d) the quasi-static scheme and the hand-off, --check.
overlap_model qs report quasi-static > qs.prm
overlap_model handoff "move slave nodes out" "quasi-static then explicit" > handoff.prm
check_prm qs.prm qs.log
check_prm handoff.prm handoff.log
grep -qF "$expected_report" qs.log || { echo "(d) quasi-static:"; cat qs.log; exit 1; }
[ "$(grep -c "Contact pairs/impact: 25 slave nodes" handoff.log)" = 1 ] ||
  { echo "(d) the hand-off logs once:"; cat handoff.log; exit 1; }
mass=$(sed -n 's/.*Lumped mass \([^ ]*\) kg.*/\1/p' handoff.log)
require "(d) quasi-static and hand-off log the line once; the hand-off's explicit run: lumped mass $mass kg" \
  "$mass / (7.85e-6 * 500 + 1.1e-6 * 470) - 1 < 1e-9 && 1 - $mass / (7.85e-6 * 500 + 1.1e-6 * 470) < 1e-9"
