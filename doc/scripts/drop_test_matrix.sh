#!/usr/bin/env bash
# The drop-test study's full matrix (reference study ch. 4, Figs. 4.4-4.6)
# with one command:
#   doc/scripts/drop_test_matrix.sh [BUILD_DIR] [REFINEMENT]
# (defaults: build, 3). Runs M = 1, 2, 3, 4, 5 kg x V0 = 0.5, 1, 1.5, 2 m/s
# (20 runs of doc/scripts/drop_test_case.sh: the shipped case with these
# values, no field output, ended 1 ms after the rebound), then writes
#   doc/figures/drop_test_matrix.csv        one row per case (see
#                                           drop_test_case_summary.sh)
#   doc/figures/drop_test_energy_fit.csv    G fitted to the energy balance
#   doc/figures/drop_test_fig44.csv/.png    5 kg at 2 m/s against time
#   doc/figures/drop_test_fig45.png         FE force vs eq. 4.8
#   doc/figures/drop_test_fig46.png         energy density vs w(lambda)
# Environment: JOBS, the number of runs at a time (default 2: two serial runs
# on two cores were faster than one 2-rank run, see doc/drop_test.md);
# RUN_DIR, where the runs go (default BUILD_DIR/drop_test_runs); REUSE=1
# keeps finished runs of identical input (drop_test_case.sh); FIGURES, where
# the results go (default doc/figures of this repository).
set -euo pipefail
repo=$(cd "$(dirname "$0")/../.." && pwd)
build=$(cd "${1:-build}" && pwd); refinement=${2:-3}
jobs_max=${JOBS:-2}
run_dir=${RUN_DIR:-$build/drop_test_runs}
figures=${FIGURES:-$repo/doc/figures}
masses="1 2 3 4 5"; velocities="0.5 1 1.5 2"
case_dir() { echo "$run_dir/r$1_m$2_v$3"; }
mkdir -p "$run_dir" "$figures"

# Longest contacts (heavy, slow) first, so that the last runs are short.
start=$(date +%s)
for m in $(echo $masses | tr ' ' '\n' | sort -rn); do
  for v in $velocities; do
    while [ "$(jobs -rp | wc -l)" -ge "$jobs_max" ]; do wait -n || true; done
    echo "run M = $m kg, V0 = $v m/s, refinement $refinement"
    "$repo/doc/scripts/drop_test_case.sh" "$build" \
      "$(case_dir "$refinement" "$m" "$v")" "$m" "$v" "$refinement" &
  done
done
wait
for m in $masses; do for v in $velocities; do
  dir=$(case_dir "$refinement" "$m" "$v")
  if [ ! -f "$dir/run_summary.json" ]; then
    echo "run M = $m kg, V0 = $v m/s failed:"; tail -5 "$dir/log.txt"; exit 1
  fi
done; done
echo "20 runs in $(( $(date +%s) - start )) s"

{
  "$repo/doc/scripts/drop_test_case_summary.sh" --header
  for m in $masses; do for v in $velocities; do
    "$repo/doc/scripts/drop_test_case_summary.sh" \
      "$(case_dir "$refinement" "$m" "$v")" "$m" "$v"
  done; done
} > "$figures/drop_test_matrix.csv"

# Fig. 4.4: the 5 kg, 2 m/s case against time.
awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i;
                   print "time_ms,impactor_displacement_mm,rubber_compression_mm,impactor_force_kN"; next }
         { printf "%s,%s,%.9g,%s\n", $c["time"], $c["impactor_displacement"],
             $c["rubber_top_displacement"] - $c["rubber_bottom_displacement"],
             $c["impactor_force"] }' \
  "$(case_dir "$refinement" 5 2)/time_history.csv" > "$figures/drop_test_fig44.csv"

"$repo/doc/scripts/drop_test_plots.sh" "$figures"
