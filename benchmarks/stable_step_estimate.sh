#!/bin/bash
# The drop test (parameter_files/drop_test_cylinder.prm) at Global
# refinement REFINEMENT (4: 40 960 cells) for END_TIME ms on one rank, once
# per Stable time step estimate given (issue 44, "the step no smaller than
# it must be"; doc/theory.md 8.3, "The assembled estimate"): steps, mean
# step, wall time, ns per element-cycle, the assembled estimate's
# refreshes, stiffness products and gain, the energy error and the
# impactor's peak force and displacement.
#
# Usage: stable_step_estimate.sh EXECUTABLE SOURCE_DIR [REFINEMENT [END_TIME [ESTIMATE...]]]
#   REFINEMENT  Drop test/Global refinement (default 4)
#   END_TIME    ms (default 0.5)
#   ESTIMATE    element, assembled, or 'none' for an executable that does
#               not know the entry (an older build); default: element
#               assembled. 'assembled:N' also sets the refresh interval N.
set -euo pipefail
exe=$1; source_dir=$2; refinement=${3:-4}; end_time=${4:-0.5}
shift $(( $# < 4 ? $# : 4 ))
estimates=("$@")
[ ${#estimates[@]} -eq 0 ] && estimates=(element assembled)
for estimate in "${estimates[@]}"; do
  name=drop_${refinement}_${estimate/:/_}
  python3 - "$source_dir/parameter_files/drop_test_cylinder.prm" "$refinement" \
    "$end_time" "$estimate" "$name" > "$name.prm" <<'PY'
import re, sys
path, refinement, end_time, estimate, name = sys.argv[1:]
text = open(path).read()
text = re.sub(r"set Global refinement *=.*", "set Global refinement = " + refinement, text)
text = re.sub(r"set End time *=.*", "set End time = " + end_time, text)
text = re.sub(r"set Output directory *=.*", "set Output directory = " + name, text)
text = re.sub(r"set Field output interval *=.*", "set Field output interval = 0", text)
if estimate != "none":
    kind, _, interval = estimate.partition(":")
    extra = "  set Stable time step estimate = " + kind + "\n"
    if interval:
        extra += "  set Stable time step refresh interval = " + interval + "\n"
    text = text.replace("subsection Time integration\n", "subsection Time integration\n" + extra, 1)
print(text)
PY
  rm -rf "$name"
  /usr/bin/time -o "$name.time" -f "%e" "$exe" "$name.prm" > "$name.log" 2>&1
  python3 - "$name/run_summary.json" "$name.time" "$estimate" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
wall = float(open(sys.argv[2]).read().split()[-1])
line = (f"{sys.argv[3]}: {s['cells']} cells, {s['time_steps']} steps to {s['end_time']:.4g} ms "
        f"({s['end_time'] / s['time_steps']:.4g} ms a step), {wall:.1f} s wall, "
        f"{s['ns_per_element_cycle']:.0f} ns per element-cycle, energy error "
        f"{s['max_energy_error_of_deformable_energy']:.2e} of the deformable energy, "
        f"peak impactor force {s['max_impactor_force']:.6g} kN, displacement "
        f"{s['max_impactor_displacement']:.6g} mm")
a = s.get("assembled_step_estimate")
if a:
    line += (f"; {a['refreshes']} estimates ({a['unconverged']} unconverged), "
             f"{a['stiffness_products']} stiffness products, {a['seconds']:.2f} s, "
             f"gain {a['smallest_gain']:.3f}-{a['largest_gain']:.3f}")
print(line)
PY
done
