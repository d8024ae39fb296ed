#!/bin/bash
# The reference study's four drop-tower tests (issue 10, doc/bushing.md):
# bushing_test_1.prm (4 mm plate) and bushing_test_2.prm (5 mm) each with
# their own preload; tests 3 and 4 (5 mm, the heavier weight) restart from
# test 2's preload checkpoint, copied into their output directories (the
# preload depends on the plate, not on the drop weight's mass or
# velocity). Run from any directory; the outputs go to output/bushing_test_N
# under the working directory. Each run writes a checkpoint every
# millisecond (Output/Checkpoint interval); to continue an interrupted test,
# run its file with Output/Restart from checkpoint = true.
#
# Usage: run_bushing_tests.sh [EXECUTABLE [NPROC]]
#   EXECUTABLE  the rubberdyn executable (default: build/rubberdyn of this
#               repository)
#   NPROC       MPI ranks (default 2)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
exe=${1:-$here/../build/rubberdyn}
nproc=${2:-2}
run() { # TEST
  echo "bushing_test_$1: $(date)"
  mpirun --oversubscribe -np "$nproc" "$exe" "$here/bushing_test_$1.prm" \
    > "bushing_test_$1.log"
}
run 1
run 2
for n in 3 4; do
  mkdir -p "output/bushing_test_$n/preload"
  # A fresh impact: an earlier run's own checkpoint would be continued.
  rm -rf "output/bushing_test_$n/preload/checkpoint" \
    "output/bushing_test_$n/checkpoint" "output/bushing_test_$n/checkpoint.old"
  cp -r output/bushing_test_2/preload/checkpoint \
    "output/bushing_test_$n/preload/checkpoint"
  run "$n"
done
echo "done: $(date)"
