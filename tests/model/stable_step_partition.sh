#!/usr/bin/env bash
# The stable time step is a function of the model, not of the partition
# (issue 11, "Results that do not depend on the number of ranks"): the same
# Model on 1, 2, ..., NPROC ranks (NPROC = 3 in ctest) gives time_history.csv
# files whose `time` and `time_step` columns are identical, byte for byte,
# on every step (a row per step), and whose other columns agree to 1e-9
# relative (to a scale, see below) plus one unit in the 9th printed digit
# (the files print 9 significant digits; runs on different partitions add
# the same forces in another order, 1e-16 relative, and a printed value
# may round either way).
#
# The step is 0.9 / sqrt(1 / dt_e^2 + 1 / dt_c^2) with dt_e the smallest
# element step and dt_c the smallest penalty-spring step. Before the
# reshaping each rank combined its own two minima and the minimum over
# ranks was taken after, which differs from combining the model's minima
# whenever no rank holds both. So the cases put the two minima in
# different places:
#
# 1. `bar`: the rubber bar of meshes/bar.msh refined once (100 x 10 x 10 mm,
#    40 x 4 x 4 cells), its end x = 0 against a held rigid wall with springs
#    10 times stiffer than the default (Penalty scale factor 1), its end
#    x = 100 hit by a 1 kg rigid impactor at 3 m/s, to 0.2 ms.
#    - contact minimum: a node's spring step 2 sqrt(m / k) is fixed by the
#      reference mesh; the wall's springs are 10 times stiffer than the
#      impactor's, so the smallest contact step is on the end x = 0, and
#      only there;
#    - element minimum: l / (Q + sqrt(Q^2 + c^2)) with the current length l
#      and the bulk viscosity Q of compression, which is nonzero only where
#      the bar is being compressed: at the impactor from the first step,
#      then behind the front of the compression pulse, which travels at
#      the bar speed sqrt(3 G / rho) = 55 mm/ms, 11 mm in the 0.2 ms of the
#      run (only a precursor of 1e-12 kN reaches the wall, at the
#      dilatational speed 708 mm/ms). So the smallest element step is at
#      x > 85 throughout.
#    p4est cuts the bar across its axis: on 2 ranks x < 50 and x > 50, on 3
#    ranks x < 35, 30 < x < 70 and x > 65 (read from the ranks' pieces of
#    the ParaView output). So on 2 and 3 ranks the two minima are on
#    different ranks at every step.
# 2. `drop`: the drop test as a Model (parameter_files/drop_test_model.prm)
#    refined once (640 cells), a 10 kg impactor at 3 m/s, 1 ms, with the
#    bottom plate touching only the bottom face (boundary id 2) with springs
#    10 times stiffer (Penalty scale factor 1), so that the contact minimum
#    is on the face z = 0 and the element minimum under the impactor at
#    z = 24. p4est cuts this cylinder lengthwise on 2 ranks (each owns cells
#    from z = 0 to 24: the old code gives the same step there) and across
#    on 3 ranks (the first owns z < 12 only).
#
# Checked that the test fails on the old combination (restored in a
# scratch build: per rank 1 / sqrt(1 / dt_e^2 + 1 / dt_c^2), then the
# minimum over ranks): the time_step columns of `bar` differ from the
# third step on, on 2 and 3 ranks (84 steps on 1 rank, 80 on 2 and 3: the
# old step is 5 % too large), those of `drop` from the third step on, on 3
# ranks.
# Usage: stable_step_partition.sh EXECUTABLE SOURCE_DIR NPROC
set -euo pipefail
exe=$1; source_dir=$2; max_ranks=$3
run() {
  local case=$1 nproc=$2
  rm -rf "${case}_$nproc"
  sed -e "s|@DIR@|${case}_$nproc|" "$case.prm.in" > "${case}_$nproc.prm"
  if [ "$nproc" -gt 1 ]; then
    mpirun --oversubscribe -np "$nproc" "$exe" "${case}_$nproc.prm" > "${case}_$nproc.log"
  else
    "$exe" "${case}_$nproc.prm" > "${case}_$nproc.log"
  fi
}
rubber='    set Model               = Yeoh
    set Constants from      = coefficients
    set C10                 = 0.00055
    set C20                 = -0.00005
    set C30                 = 0.000015
    set Volumetric model    = Poisson'"'"'s ratio
    set Poisson'"'"'s ratio     = 0.499
    set Density             = 1.1e-6'
cat > bar.prm.in <<PRM
set Study = Model
subsection Mesh
  set Mesh file         = $source_dir/parameter_files/meshes/bar.msh
  set Global refinement = 1
end
subsection Parts
  set Names = bar
  subsection bar
    set Material ids        = 1
    set Element formulation = F-bar
$rubber
  end
end
subsection Rigid surfaces
  set Names = wall, impactor
  subsection wall
    set Shape                = plane
    set Point                = 0, 0, 0
    set Direction            = 1, 0, 0
    set Boundary ids         = 1
    set Penalty scale factor = 1
  end
  subsection impactor
    set Shape            = plane
    set Point            = 100, 0, 0
    set Direction        = -1, 0, 0
    set Mass             = 1
    set Free directions  = x
    set Initial velocity = -3, 0, 0
    set Boundary ids     = 2
  end
end
subsection Contact
  set Penalty scale factor = 0.1
end
subsection Time integration
  set End time = 0.2
end
subsection Output
  set Output directory        = @DIR@
  set Field output interval   = 0
  set History output interval = 1e-9
end
PRM
cat > drop.prm.in <<PRM
set Study = Model
subsection Model
  set Gravity = 0, 0, -9.81e-3
end
subsection Mesh
  set Mesh file         = $source_dir/parameter_files/meshes/drop_test_cylinder.msh
  set Global refinement = 1
end
subsection Parts
  set Names = Rubber
  subsection Rubber
    set Material ids        = 1
    set Element formulation = F-bar
$rubber
  end
end
subsection Rigid surfaces
  set Names = bottom_plate, impactor
  subsection bottom_plate
    set Shape                = plane
    set Point                = 0, 0, 0
    set Direction            = 0, 0, 1
    set Boundary ids         = 2
    set Penalty scale factor = 1
  end
  subsection impactor
    set Shape            = plane
    set Point            = 0, 0, 24
    set Direction        = 0, 0, -1
    set Mass             = 10
    set Free directions  = z
    set Initial velocity = 0, 0, -3
    set Boundary ids     = 1, 2, 3
  end
end
subsection Contact
  set Penalty scale factor = 0.1
end
subsection Time integration
  set End time = 1
end
subsection Output
  set Output directory        = @DIR@
  set Field output interval   = 0
  set History output interval = 1e-9
end
PRM
# All runs first. The two 1-rank runs at once: the test holds the cores
# of its largest run (PROCESSORS in tests/model/CMakeLists.txt), which one
# serial run after the other would leave half idle. Each run has its own
# input and directory; the checks below read the finished files.
run bar 1 &
bar_1=$!
run drop 1 &
drop_1=$!
wait "$bar_1"
wait "$drop_1"
for case in bar drop; do
  for nproc in $(seq 2 "$max_ranks"); do
    run "$case" "$nproc"
  done
done
status=0
for case in bar drop; do
# time and time_step: the same bytes on every row.
for nproc in $(seq 2 "$max_ranks"); do
  for column in time time_step; do
    index=$(head -1 ${case}_1/time_history.csv | tr , '\n' | grep -nx "$column" | cut -d: -f1)
    if cmp -s <(cut -d, -f"$index" ${case}_1/time_history.csv) \
              <(cut -d, -f"$index" "${case}_$nproc/time_history.csv"); then
      echo "$case, $column: 1 and $nproc ranks identical ($(($(wc -l < ${case}_1/time_history.csv) - 1)) rows)"
    else
      echo "$case, $column: 1 and $nproc ranks DIFFER, first at:"
      diff <(cut -d, -f"$index" ${case}_1/time_history.csv) \
           <(cut -d, -f"$index" "${case}_$nproc/time_history.csv") | head -3 || true
      status=1
    fi
  done
  # Every other column: |a - b| <= 1e-9 S + one unit in the 9th
  # significant digit of max(|a|, |b|), where the scale S is the largest
  # magnitude in either run of: for a force (`_force`, `_force_x/_y/_z`,
  # reactions and contact forces), every force column (a force that is
  # zero but for round-off, the wall's before the wave arrives, is
  # round-off of the forces that flow through the model); likewise for a
  # moment every moment column; for an energy or work (`..._energy`,
  # `..._work`: a contact energy of 1e-24 J is round-off of the energies
  # that flow) every energy column; for another component of a vector (`_x`,
  # `_y`, `_z`), its three components (a component zero by symmetry is
  # round-off of the vector's size); for energy_error and
  # energy_error_deformable 1 (they are already divided by an energy of the
  # run); else the column itself.
  awk -F, -v nproc="$nproc" -v label="$case" '
    function abs(x) { return x < 0 ? -x : x }
    function unit9(x) { return x == 0 ? 0 : 10 ^ (int(log(x) / log(10) + 100) - 100 - 8) }
    function family(s) {
      if (s ~ /_force(_[xyz])?$/) return "all forces"
      if (s ~ /_moment_[xyz]$/) return "all moments"
      if (s ~ /(energy|_work)$/) return "all energies"
      return s ~ /_[xyz]$/ ? substr(s, 1, length(s) - 2) : s
    }
    FNR == 1 { if (FILENAME == ARGV[1]) { n = NF; for (i = 1; i <= NF; ++i) name[i] = $i }
               else if (NF != n) { print "the column counts differ"; exit 1 }
               next }
    { r = FNR - 1; for (i = 1; i <= NF; ++i) { if (FILENAME == ARGV[1]) a[r, i] = $i; else b[r, i] = $i
                                               f = family(name[i]); if (abs($i) > scale[f]) scale[f] = abs($i) }
      if (FILENAME == ARGV[1]) rows = r }
    END {
      if (r != rows) { printf "row counts differ: %d and %d\n", rows, r; exit 1 }
      scale["energy_error"] = 1; scale["energy_error_deformable"] = 1
      bad = 0; worst = 0; worst_name = ""
      for (i = 1; i <= n; ++i) {
        if (name[i] == "time" || name[i] == "time_step") continue
        S = scale[family(name[i])]
        for (k = 1; k <= rows; ++k) {
          d = abs(a[k, i] - b[k, i]); m = abs(a[k, i]) > abs(b[k, i]) ? abs(a[k, i]) : abs(b[k, i])
          if (d > 1e-9 * S + unit9(m)) { if (bad < 5) printf "%s row %d: %.10g vs %.10g\n", name[i], k, a[k, i], b[k, i]; ++bad }
          if (S > 0 && d / S > worst) { worst = d / S; worst_name = name[i] }
        }
      }
      printf "%s, other columns: 1 and %d ranks agree, largest difference %.1e of the scale (%s)\n", label, nproc, worst, worst_name
      exit bad > 0
    }' ${case}_1/time_history.csv "${case}_$nproc/time_history.csv" || status=1
done
done
exit $status
