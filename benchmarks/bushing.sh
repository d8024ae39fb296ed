#!/bin/bash
# The bushing's drop-tower test 4 (issue 10, doc/bushing.md "Benchmark"):
# test 2's preload (parameter_files/bushing_test_2.prm, its explicit run cut
# to 0.001 ms), then test 4 restarted from it for IMPACT ms of the impact;
# reports the preload's Newton iterations and wall time, and the explicit
# run's cells, steps, wall time, ns per element-cycle and its breakdown
# (run_summary.json), the contact share, and the wall time that 40 ms
# would take at the same cost per step.
#
# Usage: bushing.sh EXECUTABLE SOURCE_DIR [NPROC [MESH_N [IMPACT [STEPS]]]]
#   NPROC   MPI ranks (default 2)
#   MESH_N  mesh density n: 2 (meshes/bushing.msh, 28 680 cells; default) or
#           1 (meshes/bushing_1.msh, 7394 cells)
#   IMPACT  ms of the explicit run (default 0.5)
#   STEPS   load steps of the preload: 4 (the shipped quarter steps) or 1
#           (the whole pseudo-time at once, as the shortened ctests;
#           default 1)
# Runs in the working directory (bushing_bench_*); the parameter files are
# written by tests/model/bushing_short_common.sh's bushing_variant.
set -euo pipefail
exe=$1; source_dir=$2; nproc=${3:-2}; mesh_n=${4:-2}; impact=${5:-0.5}
steps=${6:-1}
step_size=$(awk -v s="$steps" 'BEGIN { print 1 / s }')
source "$source_dir/tests/model/bushing_short_common.sh"

run() { # NAME
  /usr/bin/time -f "%e s wall, %M kB peak memory (rank 0)" \
    mpirun --oversubscribe -np "$nproc" "$exe" "bushing_bench_$1.prm" \
    > "bushing_bench_$1.log" 2> "bushing_bench_$1.time"
}

bushing_variant 2 "$mesh_n" 0.001 "$step_size" bushing_bench_2
rm -rf bushing_bench_2 bushing_bench_4
run 2
echo "preload (n = $mesh_n, $nproc ranks, $steps load steps): $(grep '^Finished: .*load steps' bushing_bench_2.log)"
echo "  $(tail -1 bushing_bench_2.time)"

bushing_variant 4 "$mesh_n" "$impact" "$step_size" bushing_bench_4
mkdir -p bushing_bench_4/preload
cp -r bushing_bench_2/preload/checkpoint bushing_bench_4/preload/
run 4
echo "impact (test 4, $impact ms): $(grep '^Finished:' bushing_bench_4.log)"
echo "  $(tail -1 bushing_bench_4.time)"
/usr/bin/python3 - bushing_bench_4/run_summary.json <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
b = s["ns_per_element_cycle_breakdown"]
ns = s["ns_per_element_cycle"]
print(f"  {s['cells']} cells ({s['deformable_cells']} deformable), {s['dofs']} dofs, {s['ranks']} ranks, {s['time_steps']} steps to {s['end_time']:.4g} ms, {s['wall_seconds']:.1f} s")
print(f"  {ns:.0f} ns per element-cycle (x ranks): element forces {b['element_forces']:.0f}, contact {b['contact']:.0f} ({100 * b['contact'] / ns:.1f} %), vector updates {b['vector_updates']:.0f}, communication {b['communication']:.0f}, output {b['output']:.0f}")
print(f"  40 ms at this cost: {s['time_steps'] * 40 / s['end_time']:.0f} steps, {s['wall_seconds'] * 40 / s['end_time'] / 60:.0f} minutes")
print(f"  energy error {100 * s['max_energy_error']:.3g} % of the largest energy; added mass fraction {s['added_mass_fraction']}")
PY
