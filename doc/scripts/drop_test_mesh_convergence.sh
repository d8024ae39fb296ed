#!/usr/bin/env bash
# Mesh convergence of the drop test's M = 5 kg, V0 = 2 m/s case (reference
# study Fig. 4.4):
#   doc/scripts/drop_test_mesh_convergence.sh [BUILD_DIR] [MAX_REFINEMENT]
# (defaults: build, 3) runs Global refinement 1 .. MAX_REFINEMENT (80, 640,
# 5120, ... cells) one after the other with doc/scripts/drop_test_case.sh and
# writes doc/figures/drop_test_mesh_convergence.csv: the refinement, then the
# columns of drop_test_case_summary.sh (force at maximum compression against
# eq. 4.8, compressions, energy error, time steps, wall time).
# Environment: RUN_DIR (default BUILD_DIR/drop_test_runs, shared with
# drop_test_matrix.sh, so REUSE=1 reuses the matrix's run of this case),
# REUSE, FIGURES as for drop_test_matrix.sh.
set -euo pipefail
repo=$(cd "$(dirname "$0")/../.." && pwd)
build=$(cd "${1:-build}" && pwd); max_refinement=${2:-3}
run_dir=${RUN_DIR:-$build/drop_test_runs}
figures=${FIGURES:-$repo/doc/figures}
mkdir -p "$run_dir" "$figures"
{
  echo "refinement,$("$repo/doc/scripts/drop_test_case_summary.sh" --header)"
  for r in $(seq 1 "$max_refinement"); do
    dir=$run_dir/r${r}_m5_v2
    echo "run refinement $r" >&2
    "$repo/doc/scripts/drop_test_case.sh" "$build" "$dir" 5 2 "$r"
    echo "$r,$("$repo/doc/scripts/drop_test_case_summary.sh" "$dir" 5 2)"
  done
} > "$figures/drop_test_mesh_convergence.csv"
cat "$figures/drop_test_mesh_convergence.csv"
