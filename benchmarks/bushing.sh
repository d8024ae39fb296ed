#!/bin/bash
# The bushing's drop-tower test 4 (issue 10, doc/verification/bushing.md "Benchmark"):
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
# written by tests/model/bushing_short_common.sh's bushing_variant. The
# impact writes a checkpoint every 0.5 ms: called again in the same
# directory after an interruption (e.g. a machine that stops its processes),
# it continues from the last checkpoint instead of starting anew, and
# reports the wall time of all pieces together.
set -euo pipefail
exe=$1; source_dir=$2; nproc=${3:-2}; mesh_n=${4:-2}; impact=${5:-0.5}
steps=${6:-1}
step_size=$(awk -v s="$steps" 'BEGIN { print 1 / s }')
source "$source_dir/tests/model/bushing_short_common.sh"

run() { # NAME: appends its log and its wall time (one line per piece)
  /usr/bin/time -a -o "bushing_bench_$1.time" \
    -f "%e s wall, %M kB peak memory (rank 0)" \
    mpirun --oversubscribe -np "$nproc" "$exe" "bushing_bench_$1.prm" \
    >> "bushing_bench_$1.log" 2>&1
}

if [ -f bushing_bench_4/checkpoint/study.txt ] ||
   [ -f bushing_bench_4/checkpoint.old/study.txt ]; then
  echo "continuing test 4 from its checkpoint in bushing_bench_4/checkpoint"
else
  bushing_variant 2 "$mesh_n" 0.001 "$step_size" bushing_bench_2
  rm -rf bushing_bench_2 bushing_bench_4 bushing_bench_*.log bushing_bench_*.time
  run 2
  echo "preload (n = $mesh_n, $nproc ranks, $steps load steps): $(grep '^Finished: .*load steps' bushing_bench_2.log)"
  echo "  $(tail -1 bushing_bench_2.time)"

  bushing_variant 4 "$mesh_n" "$impact" "$step_size" bushing_bench_4
  sed -i "s|set Checkpoint interval *= *[0-9.]*$|set Checkpoint interval = 0.5|" bushing_bench_4.prm
  grep -q "Checkpoint interval = 0.5" bushing_bench_4.prm ||
    { echo "bushing_bench_4.prm: no Checkpoint interval"; exit 1; }
  mkdir -p bushing_bench_4/preload
  cp -r bushing_bench_2/preload/checkpoint bushing_bench_4/preload/
fi
run 4
echo "impact (test 4, $impact ms): $(grep '^Finished:' bushing_bench_4.log | tail -1)"
echo "  $(tail -1 bushing_bench_4.time) ($(grep -c 'peak memory' bushing_bench_4.time) pieces)"
/usr/bin/python3 - bushing_bench_4/run_summary.json bushing_bench_4.time <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
# One line per piece; a killed piece has a line of its exit status first.
wall = sum(float(line.split()[0]) for line in open(sys.argv[2])
           if line.strip().endswith("peak memory (rank 0)"))
b = s["ns_per_element_cycle_breakdown"]
ns = s["ns_per_element_cycle"]
print(f"  {s['cells']} cells ({s['deformable_cells']} deformable), {s['dofs']} dofs, {s['ranks']} ranks, {s['time_steps']} steps to {s['end_time']:.4g} ms, {wall:.1f} s wall in all (the solver's, last piece: {s['wall_seconds']:.1f} s for {s['timed_steps']} steps)")
print(f"  last piece: {ns:.0f} ns per element-cycle (x ranks): element forces {b['element_forces']:.0f}, contact {b['contact']:.0f} ({100 * b['contact'] / ns:.1f} %), vector updates {b['vector_updates']:.0f}, communication {b['communication']:.0f}, output {b['output']:.0f}")
# The step shrinks during the impact (at n = 2 from 9.95e-5 ms at the
# start to 8.6e-5 ms from 6 ms on: 40 ms took 460 861 steps, 1.15 times
# the start's rate; doc/verification/bushing.md "Benchmark"): a short run's
# extrapolation is a lower bound.
print(f"  40 ms at this cost and step: {s['time_steps'] * 40 / s['end_time']:.0f} steps, {wall * 40 / s['end_time'] / 60:.0f} minutes (a lower bound: the step shrinks during the impact)")
print(f"  energy error {100 * s['max_energy_error']:.3g} % of the largest energy; added mass fraction {s['added_mass_fraction']}")
PY
