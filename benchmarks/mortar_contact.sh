#!/usr/bin/env bash
# The cost of mortar contact in the explicit step (issue 8, "Performance"):
# the rubber block of parameter_files/block_sliding_on_plate.prm (F-bar
# Yeoh, on a fixed rigid plate, non-matching meshes) refined 2, 3 and 4
# times (5 824, 46 592 and 372 736 cells; 400, 1 600 and 6 400 slave
# facets), set sliding over the plate with an initial velocity (1, 0,
# -0.2) mm/ms, for about 100 steps; once with its Coulomb contact pair
# (mu = 0.2) and once without it, on 1 and 2 ranks. From each run's
# run_summary.json: ns per element-cycle of the step (element forces,
# contact, vector updates, communication: the output excluded), the
# contact share, and the pair's search count, time per search and per
# slave facet, and candidate pairs; with N log N per search for the
# growth check.
# Usage: benchmarks/mortar_contact.sh [BUILD_DIR] [WORK_DIR] [RANKS...]
set -euo pipefail
source "$(dirname "$0")/arguments.sh"

# model REFINEMENT WITH_PAIR DIRECTORY: the sliding block.
model() {
  local end
  end=$(awk -v r="$1" 'BEGIN { printf "%.6g", 0.176 / 2 ^ r }')
  sed -e "s|set Mesh file *= *\(meshes/.*\)|set Mesh file = $source_dir/parameter_files/\1\n  set Global refinement = $1|" \
      -e "s|set Element formulation = F-bar|set Element formulation = F-bar\n    set Initial velocity    = 1, 0, -0.2|" \
      -e "s|set End time *=.*|set End time = $end|" \
      -e "s|set Field output interval *=.*|set Field output interval = 0|" \
      -e "s|set History output interval *=.*|set History output interval = 1|" \
      -e "s|set Output directory *=.*|set Output directory = $3|" \
      "$source_dir/parameter_files/block_sliding_on_plate.prm" |
    if [ "$2" = 1 ]; then cat; else
      awk '/^subsection Contact pairs/ { skip = 1 } !skip { print } skip && /^end/ { skip = 0 }'
    fi
}

# value FILE KEY: a number of run_summary.json.
value() {
  grep -o "\"$2\": *[-0-9.e+]*" "$1" | head -1 | sed 's/.*: *//'
}

printf '%-6s %-5s %-9s %-8s %-10s %-10s %-8s %-9s %-12s %-12s %-10s\n' \
  ranks refs cells facets "step ns" "contact ns" share searches "s/search" "us/facet" candidates
for n in $ranks; do
  for r in 2 3 4; do
    for with in 1 0; do
      dir=sliding_${n}_${r}_$with
      model "$r" "$with" "$dir" > "$dir.prm"
      if [ "$n" -gt 1 ]; then
        mpirun --oversubscribe -np "$n" "$build/rubberdyn" "$dir.prm" > "$dir.log"
      else
        "$build/rubberdyn" "$dir.prm" > "$dir.log"
      fi
    done
    s=sliding_${n}_${r}_1/run_summary.json
    b=$(grep -o '"ns_per_element_cycle_breakdown": *{[^}]*}' "$s")
    part() { echo "$b" | grep -o "\"$1\": *[-0-9.e+]*" | sed 's/.*: *//'; }
    step=$(awk -v a="$(part element_forces)" -v b="$(part contact)" -v c="$(part vector_updates)" -v d="$(part communication)" 'BEGIN { print a + b + c + d }')
    contact=$(part contact)
    s0=sliding_${n}_${r}_0/run_summary.json
    b=$(grep -o '"ns_per_element_cycle_breakdown": *{[^}]*}' "$s0")
    step0=$(awk -v a="$(part element_forces)" -v b="$(part contact)" -v c="$(part vector_updates)" -v d="$(part communication)" 'BEGIN { print a + b + c + d }')
    cells=$(value "$s" cells)
    facets=$(awk -v r="$r" 'BEGIN { print 25 * 4 ^ r }')
    searches=$(value "$s" sliding_searches)
    search=$(value "$s" sliding_search_seconds)
    awk -v n="$n" -v r="$r" -v cells="$cells" -v f="$facets" -v step="$step" -v step0="$step0" \
        -v contact="$contact" -v searches="$searches" -v search="$search" \
        -v cand="$(value "$s" sliding_candidates)" 'BEGIN {
      printf "%-6d %-5d %-9d %-8d %-10.1f %-10.1f %-8s %-9d %-12.3g %-12.3g %-10d   (without the pair: %.1f ns)\n",
        n, r, cells, f, step, contact, sprintf("%.1f%%", 100 * contact / step), searches,
        search / searches, 1e6 * search / searches / f, cand, step0 }'
  done
done
