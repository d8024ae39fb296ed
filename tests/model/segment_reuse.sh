#!/usr/bin/env bash
# Kept mortar segments (Contact pairs/<name>/Segment reuse slip): the
# sliding rubber block of parameter_files/block_sliding_on_plate.prm (a
# Coulomb pair, 2 mm slave facets on 2.5 mm master facets, pressed for
# 1.5 ms, then pulled across at 1 mm/ms to 5 ms) run twice on the same
# ranks, integrating its segments every step (the reference: the pair's
# exact evaluation) and keeping them while nothing moves more than
# 0.001 mm along a facet relative to it. Held integrals shift a gap by
# about that distance over the facet's size, relative (5e-4 here), so:
#  - the normal force F_z agrees with the reference's at every row within
#    1e-3 of the reference's largest (measured 4.5e-4, at 1.67 ms, as the
#    pull starts);
#  - the friction work at the end within 1e-4 relative (measured 7.7e-6),
#    and the sliding ratio -F_x / F_z over the steady phase (t >= 3 ms)
#    within 1e-3 of the reference's (both are mu = 0.2 within 0.2 %);
#  - the pair's energy error (its books) stays below 0.5 % of its
#    friction work, as the reference's does (block_sliding_on_plate);
#  - the runs differ at all (some row not equal to the reference's):
#    otherwise no segment was kept and the test proves nothing.
# The time saved is a benchmark's (doc/contact.md), not asserted here.
# Usage: segment_reuse.sh EXECUTABLE SOURCE_DIR NPROC
set -euo pipefail
exe=$1; source_dir=$2; nproc=$3
rm -rf every kept ./*.prm ./*.log
ln -sfn "$source_dir/parameter_files/meshes" meshes
for run in every:0 kept:0.001; do
  name=${run%%:*}; reuse=${run#*:}
  sed -e "s|output/block_sliding_on_plate|$name|" \
      -e "s|set Field output interval *=.*|set Field output interval = 0|" \
      -e "s|^\(    set Dynamic friction coefficient.*\)$|\1\n    set Segment reuse slip = $reuse|" \
      "$source_dir/parameter_files/block_sliding_on_plate.prm" > "$name.prm"
  grep -q "Segment reuse slip = $reuse" "$name.prm" ||
    { echo "$name.prm: no Segment reuse slip"; exit 1; }
  mpirun --oversubscribe -np "$nproc" "$exe" "$name.prm" > "$name.log" 2>&1 ||
    { cat "$name.log"; exit 1; }
done
paste -d, every/time_history.csv kept/time_history.csv | awk -F, '
  function abs(x) { return x < 0 ? -x : x }
  NR == 1 { n = NF / 2; for (i = 1; i <= n; ++i) c[$i] = i; next }
  { fz = $c["sliding_force_z"]; fz_kept = $(n + c["sliding_force_z"])
    if (abs(fz) > fz_max) fz_max = abs(fz)
    if (abs(fz_kept - fz) > dz) dz = abs(fz_kept - fz)
    for (i = 1; i <= n; ++i) if ($i != $(n + i)) differ = 1
    if ($c["time"] >= 3) {
      ratio += -$c["sliding_force_x"] / fz; ++rows
      ratio_kept += -$(n + c["sliding_force_x"]) / fz_kept
    }
    work = $c["sliding_friction_work"]; work_kept = $(n + c["sliding_friction_work"])
    error_kept = $(n + c["sliding_energy_error"]) }
  END {
    dz /= fz_max
    ratio /= rows; ratio_kept /= rows
    dw = abs(work_kept - work) / work
    printf "normal force: largest difference %.2g of the largest (bound 1e-3)\n", dz
    printf "friction work %.8g against %.8g: %.2g relative (bound 1e-4)\n", work_kept, work, dw
    printf "sliding ratio (t >= 3 ms, %d rows): %.6f against %.6f (bound 1e-3)\n", rows, ratio_kept, ratio
    printf "pair energy error %.3g J, %.3g %% of its friction work (bound 0.5 %%)\n", error_kept, 100 * abs(error_kept) / work_kept
    exit (!differ || dz > 1e-3 || dw > 1e-4 || abs(ratio_kept - ratio) > 1e-3 ||
          rows < 10 || abs(error_kept) > 0.005 * work_kept)
  }' || { echo "kept segments: out of bounds (or no segment kept)"; exit 1; }
