#!/usr/bin/env bash
# A run killed with SIGKILL between two checkpoints, then restarted (twice
# in a row), writes exactly the uninterrupted run's time_history.csv, byte
# for byte, on 2 ranks, with a fixed boundary (the drop-test cylinder's
# base), mass scaling and a rigid plate pressing and sliding on its top
# with friction, the first restart from a checkpoint left under its old
# name by a kill between the renames of its switch; both restarts keep their
# ParaView series; a truncated
# checkpoint and one whose pieces belong to different steps are refused,
# naming the file or the steps.
# Usage: kill_and_restart.sh EXECUTABLE SOURCE_DIR
set -euo pipefail
exe=$1; source_dir=$2
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
rm -rf full part early_checkpoint good_checkpoint ./*.prm ./*.log

write_prm() { # name directory restart
  cat > "$1.prm" <<PRM
set Study = Model
subsection Mesh
  set Mesh file = $source_dir/parameter_files/meshes/drop_test_cylinder.msh
end
subsection Parts
  set Names = rubber
  subsection rubber
    set Material ids = 1
  end
end
subsection Boundary conditions
  set Names = base
  subsection base
    set Boundary ids = 2
    set Type         = fixed
  end
end
subsection Rigid surfaces
  set Names = press
  subsection press
    set Point                = 0, 0, 24
    set Direction            = 0, 0, -1
    set Velocity function    = 0.2; 0; -0.4
    set Boundary ids         = 3
    set Friction coefficient = 0.3
  end
end
subsection Time integration
  set End time               = 6
  set Mass scaling time step = 0.004
end
subsection Output
  set Output directory        = $2
  set History output interval = 0.05
  set Field output interval   = 0.5
  set Checkpoint interval     = 0.6
  set Restart from checkpoint = $3
end
PRM
}
write_prm full full false
write_prm part part false
write_prm resume part true

run() { mpirun --oversubscribe -np 2 "$exe" "$1.prm" > "$1.log" 2>&1; }

# Run $1.prm until the first step at or after $2 ms, where every rank kills
# itself with SIGKILL (--simulate-crash-at, doc/restarts.md): a
# machine that dies between two checkpoints with rows still in the stream
# buffers, at a known moment (killing the run from outside raced with the
# run on a loaded machine). The last committed checkpoint must be the one
# at $3 ms.
run_and_kill() {
  if mpirun --oversubscribe -np 2 \
       "$exe" --simulate-crash-at "$2" "$1.prm" > "$1.killed.log" 2>&1; then
    echo "the run was to be killed at $2 ms but ended normally:"; cat "$1.killed.log"; exit 1
  fi
  local t
  t=$(awk '$1 == "time" { print $2 }' part/checkpoint/study.txt)
  if ! awk -v t="$t" -v want="$3" 'BEGIN { exit !(t >= want - 1e-9 && t < want + 0.3) }'; then
    echo "killed at $2 ms, the last checkpoint is at $t ms, not $3 ms:"; cat "$1.killed.log"; exit 1
  fi
  echo "killed at $2 ms, after the checkpoint at $t ms"
}

run full
run_and_kill part 1.5 1.2
cp -r part/checkpoint early_checkpoint
# The first kill as if it had struck between the two renames of a
# checkpoint switch (doc/restarts.md): the complete checkpoint at 1.2 ms
# under checkpoint.old/, an unfinished checkpoint.new/ (one piece, no
# study.txt), no checkpoint/. The restart must take checkpoint.old/ (a
# refusal would leave no part/checkpoint/study.txt at 2.4 ms below, and the
# rows would differ).
mv part/checkpoint part/checkpoint.old
mkdir -p part/checkpoint.new
head -c 100 part/checkpoint.old/rank_0.bin > part/checkpoint.new/rank_0.bin
run_and_kill resume 2.7 2.4
[ ! -e part/checkpoint.old ] ||
  { echo "part/checkpoint.old was left behind by the next checkpoint"; exit 1; }
echo "restarted from checkpoint.old after a kill between the renames"
run resume
grep -q "Restarted from the checkpoint at t = " resume.log ||
  { echo "the second run did not restart:"; cat resume.log; exit 1; }
if ! cmp full/time_history.csv part/time_history.csv; then
  diff full/time_history.csv part/time_history.csv | head -20
  echo "the restarted run differs from the uninterrupted one"; exit 1
fi
# Times strictly increase (no row written twice).
awk -F, 'NR > 2 && $1 <= previous { print "row " NR " repeats time " $1; bad = 1 } { previous = $1 } END { exit bad }' part/time_history.csv
for series in solution.pvd solution_restart_1.pvd solution_restart_2.pvd; do
  [ -f "part/$series" ] || { echo "part/$series is missing"; exit 1; }
done
echo "killed twice and restarted: time_history.csv identical to the uninterrupted run's ($(wc -l < full/time_history.csv) lines); three ParaView series kept"

# A truncated piece is refused, naming it.
cp -r part/checkpoint good_checkpoint
head -c 1000 good_checkpoint/rank_1.bin > part/checkpoint/rank_1.bin
if mpirun --oversubscribe -np 2 "$exe" resume.prm > truncated.log 2>&1 ||
   ! grep -q "rank_1.bin" truncated.log; then
  echo "a truncated checkpoint must be refused naming rank_1.bin:"; cat truncated.log; exit 1
fi
echo "truncated: $(grep -o 'rank_1.bin.*' truncated.log | head -1)"
# Pieces of different steps are refused.
cp good_checkpoint/rank_1.bin part/checkpoint/rank_1.bin
cp early_checkpoint/rank_0.bin part/checkpoint/rank_0.bin
if mpirun --oversubscribe -np 2 "$exe" resume.prm > torn.log 2>&1 ||
   ! grep -q "different steps" torn.log; then
  echo "a torn checkpoint must be refused:"; cat torn.log; exit 1
fi
echo "torn: $(grep -o 'the pieces.*' torn.log | head -1)"
