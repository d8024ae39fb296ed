#!/usr/bin/env bash
# Run one case of the drop-test study (reference study ch. 4):
#   doc/scripts/drop_test_case.sh BUILD_DIR OUTPUT_DIR MASS VELOCITY REFINEMENT [RANKS]
# MASS in kg, VELOCITY in mm/ms (= m/s). The case is the shipped
# parameter_files/drop_test_cylinder.prm with these values, no field output,
# history rows every 0.02 ms, and `Stop after rebound` (the run ends 1 ms after
# the impactor has left the rubber; End time 60 ms is only a safety net).
# Extra parameter lines can be appended through the environment variable
# DROP_TEST_EXTRA_PRM. The log goes to OUTPUT_DIR/log.txt. The shipped file
# is copied into case.prm, so that REUSE below can compare whole cases (an
# include line would hide a change of the shipped file); the lines after it
# override its values. parameter_files/drop_test_matrix/ shows the same
# cases as variants that include the shipped file.
# With REUSE=1 a case is not run again if OUTPUT_DIR holds a finished run
# (run_summary.json) of the very same case.prm, newer than the executable
# and the shipped parameter file.
set -euo pipefail
build=$(cd "$1" && pwd); mkdir -p "$2"; out=$(cd "$2" && pwd)
mass=$3; velocity=$4; refinement=$5; ranks=${6:-1}
repo=$(cd "$(dirname "$0")/../.." && pwd)
cat > "$out/case.prm.new" <<PRM
$(cat "$repo/parameter_files/drop_test_cylinder.prm")
subsection Drop test
  set Impactor mass      = $mass
  set Impact velocity    = $velocity
  set Global refinement  = $refinement
  set Stop after rebound = true
end
subsection Time integration
  set End time = 60
end
subsection Output
  set Output directory        = $out
  set Field output interval   = 0
  set History output interval = 0.02
end
${DROP_TEST_EXTRA_PRM:-}
PRM
if [ "${REUSE:-0}" = 1 ] && [ -f "$out/run_summary.json" ] &&
   [ "$out/run_summary.json" -nt "$build/rubberdyn" ] &&
   [ "$out/run_summary.json" -nt "$repo/parameter_files/drop_test_cylinder.prm" ] &&
   cmp -s "$out/case.prm" "$out/case.prm.new"; then
  rm "$out/case.prm.new"; exit 0
fi
mv "$out/case.prm.new" "$out/case.prm"
rm -f "$out/run_summary.json"
if [ "$ranks" -gt 1 ]; then
  mpirun -np "$ranks" "$build/rubberdyn" "$out/case.prm" > "$out/log.txt" 2>&1
else
  "$build/rubberdyn" "$out/case.prm" > "$out/log.txt" 2>&1
fi
