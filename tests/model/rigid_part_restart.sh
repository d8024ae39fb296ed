#!/usr/bin/env bash
# A rigid part survives a crash: parameter_files/rigid_drop.prm (a rigid
# steel block dropped on a rubber block) checkpointed every 1.3 ms, killed
# (SIGKILL from inside, RUBBERDYN_SIMULATE_CRASH_AT, doc/restarts.md) at
# 3.0 ms, in the middle of the impact, and restarted from the checkpoint at
# 2.6 ms: time_history.csv, with the block's position, velocity, rotation,
# angular velocity, force and moment, is byte for byte the uninterrupted
# run's.
# Usage: rigid_part_restart.sh EXECUTABLE SOURCE_DIR NPROC
set -euo pipefail
exe=$1; source_dir=$2; nproc=$3
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
run() { mpirun --oversubscribe -np "$nproc" "$@"; }
run "$exe" full.prm > full.log 2>&1
if RUBBERDYN_SIMULATE_CRASH_AT=3.0 run -x RUBBERDYN_SIMULATE_CRASH_AT "$exe" part.prm > part.log 2>&1; then
  echo "the run was to be killed at 3.0 ms"; cat part.log; exit 1
fi
run "$exe" resume.prm > resume.log 2>&1
grep -q "Restarted from the checkpoint at t = 2.6" resume.log ||
  { echo "no restart from 2.6 ms:"; cat resume.log; exit 1; }
grep -q "block_angular_velocity_z" full/time_history.csv ||
  { echo "the rigid part's columns are missing"; exit 1; }
cmp full/time_history.csv part/time_history.csv ||
  { echo "the restarted run differs from the uninterrupted one"; exit 1; }
echo "killed at 3.0 ms, restarted from 2.6 ms: time_history.csv identical ($(wc -l < full/time_history.csv) lines)"
