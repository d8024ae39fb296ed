#!/usr/bin/env bash
# No end flare with the penalty of the current geometry (issue 8,
# "Deformable plates": the radius profile at maximum compression
# homogeneous, R / sqrt(lambda), within 0.5 % in every node layer; and
# doc/drop_test.md, "End flare"): the drop test as a Model with rigid
# plates (parameter_files/drop_test_model.prm, node-to-surface penalty at
# the default Penalty scale factor 0.1) on the study's 5120-cell mesh
# (Global refinement = 2), 5 kg at 2 m/s, without gravity (so that the
# rubber is compressed by the impact alone, as in
# drop_test_deformable_plates).
# A first run finds the maximum compression (the impactor's velocity
# crosses zero, interpolated between rows 0.01 ms apart); the second stops
# there and writes the fields, from which radius_profile.py takes the
# largest deformed radius of each node layer against R / sqrt(lambda) of a
# homogeneous compression of an incompressible cylinder (R = 12.5 mm).
# Bound: 0.5 % in every layer, the issue's.
# Measured (2026-12-03): t = 9.768 ms, lambda = 0.4289, largest deviation
# 0.36 % (layer Z = 22.5 mm); the end layers +0.20 % (bottom) and -0.32 %
# (top). With the reference geometry's penalty of before the same run gave
# t = 9.878 ms, lambda = 0.4340 and a flare of +2.14 % (bottom) and +2.00 %
# (top) against -0.1 to -0.8 % in the middle: the interior of each end
# face sank 0.14 mm into its plate, the rim 0.025 mm, so the rim ring was
# squeezed harder than the rest and bulged out. (The rim nodes also take
# the springs of the hull faces next to them, since the plates act on the
# hull too; at their reference size these outweighed the end faces', while
# in the current geometry the end faces, spread to 1/lambda of their area,
# dominate.) With the current geometry every end node sinks 0.021 to
# 0.027 mm.
# Usage: end_flare_rigid_plates.sh EXECUTABLE SOURCE_DIR NPROC
set -euo pipefail
exe=$1; source_dir=$2; nproc=$3
source "$source_dir/tests/model/script_helpers.sh"

# run NAME END_TIME FIELD_INTERVAL: drop_test_model.prm at 5120 cells
# without gravity, in NAME/.
run() {
  sed -e "s|set Mesh file *= *\(meshes/.*\)|set Mesh file = $source_dir/parameter_files/\1|" \
      -e "s|set Global refinement *=.*|set Global refinement = 2|" \
      -e "s|set Gravity *=.*|set Gravity = 0, 0, 0|" \
      -e "s|set End time *=.*|set End time = $2|" \
      -e "s|set Field output interval *=.*|set Field output interval = $3|" \
      -e "s|set History output interval *=.*|set History output interval = 0.01|" \
      -e "s|set Output directory *=.*|set Output directory = $1|" \
      "$source_dir/parameter_files/drop_test_model.prm" > "$1.prm"
  rm -rf "$1"
  run_prm "$1.prm" "$1.log"
}

run find 10.2 0
# The time at which the impactor's velocity crosses zero from below.
t_max=$(awk -F, '
  NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
  { v = $c["impactor_velocity_z"] }
  NR > 2 && previous < 0 && v >= 0 {
    printf "%.6f\n", t + (-previous / (v - previous)) * ($1 - t); found = 1; exit }
  { previous = v; t = $1 }
  END { if (!found) exit 1 }' find/time_history.csv)
echo "maximum compression at t = $t_max ms"

run maximum "$t_max" "$t_max"
/usr/bin/env python3 "$source_dir/tests/model/radius_profile.py" maximum \
  --radius 12.5 --bound 0.005
