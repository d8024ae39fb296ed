#!/usr/bin/env bash
# A rigid part survives a crash: parameter_files/rigid_drop.prm (a rigid
# steel block dropped on a rubber block) checkpointed every 1.3 ms, killed
# (SIGKILL from inside, --simulate-crash-at, doc/restarts.md) at
# 3.0 ms, in the middle of the impact, and restarted from the checkpoint at
# 2.6 ms: time_history.csv, with the block's position, velocity, rotation,
# angular velocity, force and moment, is byte for byte the uninterrupted
# run's.
# Usage: rigid_part_restart.sh EXECUTABLE SOURCE_DIR NPROC
set -euo pipefail
exe=$1; source_dir=$2; nproc=$3
source "$source_dir/tests/model/script_helpers.sh"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
rm -rf full part ./*.prm ./*.log
ln -sfn "$source_dir/parameter_files/meshes" meshes
make_prm() { # name directory restart
  sed -e "s|output/rigid_drop|$2|" \
      -e "s|^\(  set History output interval.*\)$|\1\n  set Field output interval = 0\n  set Checkpoint interval = 1.3\n  set Restart from checkpoint = $3|" \
      -e '/set Field output interval   = 0.25/d' \
      "$source_dir/parameter_files/rigid_drop.prm" > "$1.prm"
}
make_prm full full false
make_prm part part false
make_prm resume part true
crash_and_restart full part resume 3.0 2.6
grep -q "block_angular_velocity_z" full/time_history.csv ||
  { echo "the rigid part's columns are missing"; exit 1; }
cmp full/time_history.csv part/time_history.csv ||
  { echo "the restarted run differs from the uninterrupted one"; exit 1; }
echo "killed at 3.0 ms, restarted from 2.6 ms: time_history.csv identical ($(wc -l < full/time_history.csv) lines)"
