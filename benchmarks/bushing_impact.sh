#!/bin/bash
# The bushing's test 4 impact alone, without its preload (doc/verification/
# bushing.md "Benchmark": parameter_files/bushing_test_4.prm with Scheme =
# explicit and the pretension section removed, the weight touching the plate
# from 0.03 ms), at the shipped mesh, with or without selective mass scaling
# and the pairs' Penalty time step: cells, steps, wall time, ns per
# element-cycle (x ranks) with its breakdown, the solve's iterations and the
# energy error (issue 44's side-by-side runs).
#
# Usage: bushing_impact.sh EXECUTABLE SOURCE_DIR [NPROC [IMPACT [TARGET [PENALTY_STEP [NAME]]]]]
#   NPROC         MPI ranks (default 2)
#   IMPACT        ms of impact (default 0.3)
#   TARGET        Time integration/Selective mass scaling time step (ms;
#                 default 0: none)
#   PENALTY_STEP  every contact pair's Penalty time step (ms; default 0)
#   NAME          output directory and file prefix (default bushing_impact)
# An EXECUTABLE that does not know the two entries (an older build) runs
# with both 0. BUSHING_MESH=meshes/bushing_1.msh in the environment takes
# another mesh of parameter_files/ (the coarse n = 1).
set -euo pipefail
exe=$1; source_dir=$2; nproc=${3:-2}; impact=${4:-0.3}; target=${5:-0}
penalty_step=${6:-0}; name=${7:-bushing_impact}
python3 - "$source_dir/parameter_files/bushing_test_4.prm" "$source_dir/parameter_files" \
  "$impact" "$target" "$penalty_step" "$name" "${BUSHING_MESH:-}" > "$name.prm" <<'PY'
import re, sys
path, folder, impact, target, penalty_step, name, mesh = sys.argv[1:]
text = open(path).read()
# The pretension section out (no preload), explicit from the start.
start = text.index("subsection Pretension sections")
end = text.index("\nend\n", start) + 5
text = text[:start] + text[end:]
text = re.sub(r"set Mesh file *= *(\S+)", lambda m: "set Mesh file = " + folder + "/" + (mesh or m.group(1)), text)
text = re.sub(r"set Scheme *=.*", "set Scheme = explicit", text)
text = re.sub(r"set End time *=.*", "set End time = " + impact, text)
text = re.sub(r"set Output directory *=.*", "set Output directory = " + name, text)
text = re.sub(r"set Restart from checkpoint *=.*", "set Restart from checkpoint = false", text)
text = re.sub(r"set Checkpoint interval *=.*", "set Checkpoint interval = 0", text)
text = re.sub(r"set Field output interval *=.*", "set Field output interval = 0", text)
text = re.sub(r"set History output interval *=.*", "set History output interval = 0.005", text)
if float(target) > 0:
    text = text.replace("subsection Time integration\n",
        "subsection Time integration\n  set Selective mass scaling time step = " + target + "\n", 1)
if float(penalty_step) > 0:
    names = re.search(r"subsection Contact pairs\n  set Names = ((?:.*\\\n)*.*)", text).group(1)
    pairs = [n.strip() for n in names.replace("\\\n", " ").split(",")]
    text += "subsection Contact pairs\n" + "".join(
        "  subsection %s\n    set Penalty time step = %s\n  end\n" % (p, penalty_step) for p in pairs) + "end\n"
print(text)
PY
rm -rf "$name"
/usr/bin/time -o "$name.time" -f "%e" \
  mpirun --oversubscribe -np "$nproc" "$exe" "$name.prm" > "$name.log" 2>&1
/usr/bin/python3 - "$name/run_summary.json" "$name.time" "$target" "$penalty_step" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
wall = float(open(sys.argv[2]).read().split()[-1])
b = s["ns_per_element_cycle_breakdown"]
ns = s["ns_per_element_cycle"]
print(f"target {sys.argv[3]} ms, penalty step {sys.argv[4]} ms: {s['cells']} cells, {s['ranks']} ranks, {s['time_steps']} steps to {s['end_time']:.4g} ms ({s['end_time'] / s['time_steps']:.3g} ms a step), {wall:.1f} s wall")
print(f"  {ns:.0f} ns per element-cycle (x ranks): element forces {b['element_forces']:.0f}, contact {b['contact']:.0f} ({100 * b['contact'] / ns:.1f} %), vector updates {b['vector_updates']:.0f}, communication {b['communication']:.0f}, output {b['output']:.0f}")
m = s.get("selective_mass_scaling")
if m:
    print(f"  selective mass scaling: {m['mean_iterations']:.1f} iterations a step (largest {m['largest_iterations']})")
print(f"  energy error {100 * s['max_energy_error']:.3g} % of the largest energy, {100 * s['max_energy_error_of_deformable_energy']:.3g} % of the deformable; 40 ms at this step and cost: {wall * 40 / s['end_time'] / 60:.0f} minutes")
PY
