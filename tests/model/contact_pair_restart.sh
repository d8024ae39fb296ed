#!/usr/bin/env bash
# A Coulomb mortar pair survives a crash: the sliding rubber block of
# parameter_files/block_sliding_on_plate.prm checkpointed every 1.3 ms,
# killed (SIGKILL from inside, --simulate-crash-at,
# doc/restarts.md) at 3.0 ms, while it slides, and restarted from the
# checkpoint at 2.6 ms: time_history.csv, with the pair's forces,
# pressures, active and slipping nodes and friction work, is byte for byte
# the uninterrupted run's. (The pair's checkpoint holds the accepted
# tangential tractions, spring energies and slip distances, the accepted
# positions and time, the friction work and the last evaluation's columns;
# the restarted run searches anew, which does not change any segment:
# doc/theory.md, section 15.2.) The same again with the pair's Segment
# reuse slip = 0.01 mm, where the segments depend on when the searches
# were: the checkpoint then holds the search's state and the kept
# segments, and the histories are again identical byte for byte.
# Usage: contact_pair_restart.sh EXECUTABLE SOURCE_DIR NPROC
set -euo pipefail
exe=$1; source_dir=$2; nproc=$3
source "$source_dir/tests/model/script_helpers.sh"
rm -rf full* part* ./*.prm ./*.log
ln -sfn "$source_dir/parameter_files/meshes" meshes
make_prm() { # name directory restart reuse
  sed -e "s|output/block_sliding_on_plate|$2|" \
      -e "s|set End time *=.*|set End time = 3.5|" \
      -e "s|^\(  set History output interval.*\)$|\1\n  set Checkpoint interval = 1.3\n  set Restart from checkpoint = $3|" \
      -e "s|set Field output interval *=.*|set Field output interval = 0|" \
      -e "s|^\(    set Dynamic friction coefficient.*\)$|\1\n    set Segment reuse slip = $4|" \
      "$source_dir/parameter_files/block_sliding_on_plate.prm" > "$1.prm"
  grep -q "Segment reuse slip = $4" "$1.prm" ||
    { echo "$1.prm: no Segment reuse slip"; exit 1; }
}
for reuse in 0 0.01; do
  make_prm "full_$reuse" "full_$reuse" false "$reuse"
  make_prm "part_$reuse" "part_$reuse" false "$reuse"
  make_prm "resume_$reuse" "part_$reuse" true "$reuse"
  crash_and_restart "full_$reuse" "part_$reuse" "resume_$reuse" 3.0 2.6
  awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
    $c["time"] > 2.6 && $c["sliding_slipping_nodes"] > 0 { slipping = 1 }
    END { exit !slipping }' "full_$reuse/time_history.csv" ||
    { echo "reuse $reuse: the block does not slide after 2.6 ms"; exit 1; }
  cmp "full_$reuse/time_history.csv" "part_$reuse/time_history.csv" ||
    { echo "reuse $reuse: the restarted run differs from the uninterrupted one"; exit 1; }
  echo "Segment reuse slip $reuse: killed at 3.0 ms while sliding, restarted from 2.6 ms: time_history.csv identical ($(wc -l < "full_$reuse/time_history.csv") lines)"
done
