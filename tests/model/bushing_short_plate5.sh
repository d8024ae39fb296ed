#!/usr/bin/env bash
# The shortened drop-tower tests 2, 3 and 4 of the bushing (5 mm plate;
# tests/model/bushing_short_common.sh has the shortening and the checks).
# Test 2 runs its preload; tests 3 and 4 restart from its checkpoint, as
# parameter_files/run_bushing_tests.sh does: they run no load step and
# start from test 2's stored energy (the first row's internal energy equal
# to 1e-12 relative). Tests 3 and 4 are the same model (the study's test 4
# repeated test 3 on a reinforced structure, which the model does not
# have): their histories must be identical.
# Usage: bushing_short_plate5.sh EXECUTABLE SOURCE_DIR NPROC
set -euo pipefail
exe=$1; source_dir=$2; nproc=$3
source "$source_dir/tests/model/script_helpers.sh"
source "$source_dir/tests/model/bushing_short_common.sh"

run_short 2
check_short 2 14.007
for n in 3 4; do
  run_short $n
  if grep -q "Step to" "bushing_test_$n.log"; then
    echo "test $n: ran load steps instead of restarting from test 2's preload"
    exit 1
  fi
  check_short $n 14.007
done
awk -F, '
  FNR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
  FNR == 2 { e[++k] = $c["internal_energy"] }
  END {
    d = (e[2] - e[1]) / e[1]; if (d < 0) d = -d
    printf "stored energy at the hand-off: test 2 %.9g J, test 3 %.9g J\n", e[1], e[2]
    exit (d > 1e-12)
  }' bushing_test_2/time_history.csv bushing_test_3/time_history.csv
cmp bushing_test_3/time_history.csv bushing_test_4/time_history.csv
echo "tests 3 and 4: identical histories"
