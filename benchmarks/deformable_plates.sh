#!/usr/bin/env bash
# The share of mortar contact in the explicit step of the deformable-plate
# drop test (parameter_files/drop_test_deformable_plates.prm: the rubber
# cylinder between two steel plates meshed as parts, two frictionless
# mortar pairs) at Global refinement 0, 1 and 2 (80, 640 and 5 120 rubber
# cells; 208, 1 664 and 13 312 cells with the plates; refinement 2 is the
# study's mesh), for about 1 000 steps of the impact (End time 0.4 / 2^r
# ms: the stable step halves with each refinement), without field output.
# From each run's run_summary.json: ns per element-cycle of the step
# (element forces, contact, vector updates, communication: the output
# excluded), the contact part and its share, the step less the contact
# part, and the pairs' candidate pairs and searches.
# Usage: benchmarks/deformable_plates.sh [BUILD_DIR] [WORK_DIR] [RANKS...]
set -euo pipefail
source "$(dirname "$0")/arguments.sh"

# model REFINEMENT DIRECTORY: the drop test, short and without fields.
model() {
  local end
  end=$(awk -v r="$1" 'BEGIN { printf "%.6g", 0.4 / 2 ^ r }')
  sed -e "s|set Mesh file *= *\(meshes/.*\)|set Mesh file = $source_dir/parameter_files/\1\n  set Global refinement = $1|" \
      -e "s|set End time *=.*|set End time = $end|" \
      -e "s|set Field output interval *=.*|set Field output interval = 0|" \
      -e "s|set History output interval *=.*|set History output interval = 0.05|" \
      -e "s|set Output directory *=.*|set Output directory = $2|" \
      "$source_dir/parameter_files/drop_test_deformable_plates.prm"
}

# value FILE KEY: a number of run_summary.json.
value() {
  grep -o "\"$2\": *[-0-9.e+]*" "$1" | head -1 | sed 's/.*: *//'
}

printf '%-6s %-5s %-7s %-6s %-10s %-10s %-8s %-14s %-11s %-9s\n' \
  ranks refs cells steps "step ns" "contact ns" share "without (ns)" candidates searches
for n in $ranks; do
  for r in 0 1 2; do
    dir=plates_${n}_$r
    model "$r" "$dir" > "$dir.prm"
    if [ "$n" -gt 1 ]; then
      mpirun --oversubscribe -np "$n" "$build/rubberdyn" "$dir.prm" > "$dir.log"
    else
      "$build/rubberdyn" "$dir.prm" > "$dir.log"
    fi
    s=$dir/run_summary.json
    b=$(grep -o '"ns_per_element_cycle_breakdown": *{[^}]*}' "$s")
    part() { echo "$b" | grep -o "\"$1\": *[-0-9.e+]*" | sed 's/.*: *//'; }
    awk -v n="$n" -v r="$r" -v cells="$(value "$s" cells)" \
        -v steps="$(value "$s" time_steps)" \
        -v a="$(part element_forces)" -v c="$(part contact)" \
        -v v="$(part vector_updates)" -v m="$(part communication)" \
        -v cand=$(( $(value "$s" bottom_candidates) + $(value "$s" top_candidates) )) \
        -v searches=$(( $(value "$s" bottom_searches) + $(value "$s" top_searches) )) 'BEGIN {
      step = a + c + v + m
      printf "%-6d %-5d %-7d %-6d %-10.1f %-10.1f %-8s %-14.1f %-11d %-9d\n",
        n, r, cells, steps, step, c, sprintf("%.1f%%", 100 * c / step),
        step - c, cand, searches }'
  done
done
