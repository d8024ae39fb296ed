# Sourced by the script tests of this directory (they set exe, nproc).

# run_prm PRM LOG: the executable $exe on the parameter file PRM on $nproc
# ranks (mpirun for more than one), its standard output to LOG; its status
# is the run's.
run_prm() {
  if [ "$nproc" -gt 1 ]; then
    mpirun --oversubscribe -np "$nproc" "$exe" "$1" > "$2"
  else
    "$exe" "$1" > "$2"
  fi
}

# study_rubber_part: the reference study's Yeoh rubber (C10, C20, C30 of
# seed-notes.md, nu = 0.499, F-bar) as the subsection of the part "rubber"
# on material id 1, for a Parts subsection.
study_rubber_part() {
  cat <<PRM
  subsection rubber
    set Material ids        = 1
    set Element formulation = F-bar
    set Model               = Yeoh
    set Constants from      = coefficients
    set C10                 = 0.00055
    set C20                 = -0.00005
    set C30                 = 0.000015
    set Poisson's ratio     = 0.499
    set Density             = 1.1e-6
  end
PRM
}

# steel_bar_model [INITIAL_VELOCITY]: the top of a Model parameter file
# for meshes/bar.msh (100 x 10 x 10 mm along x, 20 x 2 x 2 cells; $source_dir
# set): the study, the mesh and the part "bar" of elastic steel (E 210 GPa,
# nu 0.3, 7.85e-6 kg/mm^3), optionally with an initial velocity (mm/ms).
steel_bar_model() {
  cat <<PRM
set Study = Model
subsection Mesh
  set Mesh file = $source_dir/parameter_files/meshes/bar.msh
end
subsection Parts
  set Names = bar
  subsection bar
    set Material ids        = 1
    set Element formulation = F-bar
    set Model               = Elastic
    set Young's modulus     = 210
    set Poisson's ratio     = 0.3
    set Density             = 7.85e-6
    set Initial velocity    = ${1:-0, 0, 0}
  end
end
PRM
}

# elastic_steel_part NAME MATERIAL_ID: a Parts subsection of elastic steel
# (E 210 GPa, nu 0.3, 7.85e-6 kg/mm^3).
elastic_steel_part() {
  cat <<PRM
  subsection $1
    set Material ids    = $2
    set Model           = Elastic
    set Young's modulus = 210
    set Poisson's ratio = 0.3
    set Density         = 7.85e-6
  end
PRM
}

# coulomb_pair NAME SLAVE_IDS MASTER_IDS MU: the Contact pairs section with
# the one Coulomb pair NAME (static and dynamic friction coefficient MU).
coulomb_pair() {
  cat <<PRM
subsection Contact pairs
  set Names = $1
  subsection $1
    set Slave boundary ids           = $2
    set Master boundary ids          = $3
    set Type                         = Coulomb
    set Static friction coefficient  = $4
    set Dynamic friction coefficient = $4
  end
end
PRM
}

# bonded_block_parts MOTION: the Parts subsection of meshes/bonded_block.msh
# with the study's rubber (material id 1) and the steel plate (id 2) as a
# rigid part in equilibrium on the load path, free in MOTION (Rigid motion).
bonded_block_parts() {
  cat <<PRM
subsection Parts
  set Names = rubber, steel
$(study_rubber_part)
  subsection steel
    set Material ids        = 2
    set Model               = Rigid
    set Rigid motion        = $1
    set Quasi-static motion = equilibrium
    set Young's modulus     = 210
    set Poisson's ratio     = 0.3
    set Density             = 7.85e-6
  end
end
PRM
}

# crash_and_restart FULL PART RESUME CRASH_AT RESTART_AT: run FULL.prm
# uninterrupted, PART.prm killed at CRASH_AT ms (SIGKILL from inside,
# --simulate-crash-at, doc/restarts.md) and RESUME.prm (PART's with
# Restart from checkpoint = true), on $nproc ranks through mpirun; fails
# unless the crash happened and the resumed run restarted from the
# checkpoint at RESTART_AT ms. Logs FULL.log, PART.log, RESUME.log.
crash_and_restart() {
  mpirun --oversubscribe -np "$nproc" "$exe" "$1.prm" > "$1.log" 2>&1
  if mpirun --oversubscribe -np "$nproc" \
       "$exe" --simulate-crash-at "$4" "$2.prm" > "$2.log" 2>&1; then
    echo "the run was to be killed at $4 ms"; cat "$2.log"; return 1
  fi
  mpirun --oversubscribe -np "$nproc" "$exe" "$3.prm" > "$3.log" 2>&1
  grep -q "Restarted from the checkpoint at t = $5" "$3.log" ||
    { echo "no restart from $5 ms:"; cat "$3.log"; return 1; }
}

# handoff_at_rest CSV FORCE_COLUMN ENERGY_BOUND WORK_BOUND: the explicit run
# of a hand-off (Scheme = quasi-static then explicit, output directory
# handoff) starts at rest in the preload's equilibrium: over CSV, kinetic /
# internal energy <= 1e-12, |energy_error| <= ENERGY_BOUND, FORCE_COLUMN
# equal to its last value in handoff/preload/time_history.csv to 1e-10
# relative, |friction_work| <= WORK_BOUND (J); at least 10 rows.
handoff_at_rest() {
  local preload
  preload=$(awk -F, -v column="$2" '
    NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
    { f = $c[column] } END { printf "%.17g", f }' handoff/preload/time_history.csv)
  awk -F, -v preload="$preload" -v column="$2" -v energy_bound="$3" \
      -v work_bound="$4" '
    function abs(x) { return x < 0 ? -x : x }
    NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
    {
      k = $c["kinetic_energy"] / $c["internal_energy"]; if (k > ke) ke = k
      e = abs($c["energy_error"]); if (e > err) err = e
      d = abs($c[column] / preload - 1); if (d > drift) drift = d
      w = abs($c["friction_work"]); if (w > work) work = w
      ++rows
    }
    END {
      printf "%d rows: kinetic / internal energy %.2e, energy error %.2e, %s vs the preload %.2e, friction work %.2e J\n", rows, ke, err, column, drift, work
      exit (rows < 10 || ke > 1e-12 || err > energy_bound || drift > 1e-10 || work > work_bound)
    }' "$1"
}

# restart_from_preload PRM CHECK...: run PRM (written by the caller to
# restart from the preload checkpoint of handoff/, with another End time)
# and require that it skips the load path and starts from the same state:
# the command CHECK... passes on its time history, and its first row
# equals the one of the run before (saved by the caller in first_row).
restart_from_preload() {
  local prm=$1; shift
  run_prm "$prm" restart_log.txt
  grep -q "Starting from the preload" restart_log.txt
  if grep -q "Step to" restart_log.txt; then
    echo "the restart ran the load path again"; return 1
  fi
  "$@"
  [ "$(sed -n 2p handoff/time_history.csv | cut -d, -f3-)" = "$first_row" ] ||
    { echo "the restart starts from another state"; return 1; }
  echo "the restart starts from the same state"
}
