#!/usr/bin/env bash
# Output/History expressions (doc/model.md, "What it writes"): columns of
# time_history.csv computed from the other columns of their row (the
# bushing's drop_weight_force, inner_sleeve_slip and outer_sleeve_pull_out,
# issue 10, are such columns).
# A steel bar (meshes/bar.msh, 100 x 10 x 10 mm) in free flight at
# (1, 2, 0) mm/ms, no load, explicit, 0.01 ms: a rigid translation, so
#  - speed = |bar_momentum| / (rho V) = sqrt(5) mm/ms (rho V = 7.85e-6 kg/mm^3
#    x 10^4 mm^3 = 0.0785 kg) to 1e-8 relative (the CSV prints 9 digits);
#  - travel = |tip displacement| (a history node) = speed x time: the
#    expression travel_error = travel - speed * time, which uses an earlier
#    expression and the time column, stays below 1e-9 mm;
#  - late = time < 0.005 ? 0 : 1 (a ':' inside an expression) switches once.
# Bad input, refused before the run with one line naming the entry: an
# unknown column, a name that is already a column, an entry without ':',
# and expressions in a quasi-static run.
# Usage: history_expressions.sh EXECUTABLE SOURCE_DIR NPROC
set -euo pipefail
exe=$1; source_dir=$2; nproc=$3
source "$source_dir/tests/model/script_helpers.sh"

# bar SCHEME EXPRESSIONS OUTPUT
bar() {
  cat <<PRM
$(steel_bar_model "1, 2, 0")
subsection Time integration
  set Scheme   = $1
  set End time = 0.01
end
subsection Output
  set Output directory        = $3
  set History output interval = 0.001
  set Field output interval   = 0
  set History nodes           = tip: 100, 0, 0
  set History expressions     = $2
end
PRM
}

good="speed: sqrt(bar_momentum_x^2 + bar_momentum_y^2 + bar_momentum_z^2) / 0.0785; travel_error: sqrt(tip_displacement_x^2 + tip_displacement_y^2 + tip_displacement_z^2) - speed * time; late: time < 0.005 ? 0 : 1"
bar explicit "$good" flight > flight.prm
rm -rf flight
run_prm flight.prm flight.log
awk -F, '
  function abs(x) { return x < 0 ? -x : x }
  NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i
            if (!("speed" in c) || !("travel_error" in c) || !("late" in c)) { print "missing columns"; exit 1 }
            next }
  { n++
    e = abs($c["speed"] / sqrt(5) - 1); if (e > speed_error) speed_error = e
    t = abs($c["travel_error"]); if (t > travel_error) travel_error = t
    if ($c["late"] != ($c["time"] < 0.005 ? 0 : 1)) bad_late = 1
    switches += ($c["late"] != previous && n > 1); previous = $c["late"] }
  END {
    printf "%d rows: speed sqrt(5) to %.2g relative, travel - speed time at most %.2g mm, late switches %d time(s)%s\n", n, speed_error, travel_error, switches, bad_late ? " at the wrong time" : ""
    exit (n < 10 || speed_error > 1e-8 || travel_error > 1e-9 || switches != 1 || bad_late) }' flight/time_history.csv

# refused EXPRESSIONS SCHEME: the run must fail, naming the entry.
refused() {
  bar "$2" "$1" refused > refused.prm
  if run_prm refused.prm refused.log 2> refused.err; then
    echo "accepted: $1"; exit 1
  fi
  grep -h "Output/History expressions" refused.log refused.err | head -n 1 |
    sed -e 's/.*error: //'
}
refused "a: bar_momentum_q + 1" explicit
refused "time: 1" explicit
refused "speed = 1" explicit
refused "speed: 1" quasi-static
