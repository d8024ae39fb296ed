#!/usr/bin/env bash
# run_example.sh EXECUTABLE SOURCE_DIR NAME END_TIME HISTORY_INTERVAL [NPROC]
# Runs parameter_files/NAME.prm in the current directory, shortened: the
# mesh path made absolute, End time, History output interval and the
# output directory (NAME) replaced, no field output but the last. Leaves
# NAME/time_history.csv. Lines in the environment variable EXAMPLE_APPEND
# (e.g. a subsection the example does not set) are appended to the file.
set -euo pipefail
exe=$1; source_dir=$2; name=$3; end_time=$4; interval=$5; nproc=${6:-1}
sed -e "s|set Mesh file *= *\(meshes/.*\)|set Mesh file = $source_dir/parameter_files/\1|" \
    -e "s|set End time *=.*|set End time = $end_time|" \
    -e "s|set History output interval *=.*|set History output interval = $interval|" \
    -e "s|set Field output interval *=.*|set Field output interval = 0|" \
    -e "s|set Output directory *=.*|set Output directory = $name|" \
    "$source_dir/parameter_files/$name.prm" > "$name.prm"
if [ -n "${EXAMPLE_APPEND:-}" ]; then
  printf '%s\n' "$EXAMPLE_APPEND" >> "$name.prm"
fi
rm -rf "$name"
if [ "$nproc" -gt 1 ]; then
  mpirun --oversubscribe -np "$nproc" "$exe" "$name.prm"
else
  "$exe" "$name.prm"
fi
