#!/usr/bin/env bash
# The hand-off (Time integration/Scheme = quasi-static then explicit) keeps
# a mortar Coulomb pair's friction state (contact::MortarContactPair::
# friction_state()): the steel block on the slope of meshes/block_on_slope
# (tan(alpha) = 0.1, mu = 0.3, the block's weight G = 1 kN as a constant
# traction) is pushed up the slope by 5 um on the load path and pulled
# back to where it started: it slides up (push F / G = 0.41236, statics
# 0.412371), then down (F / G = -0.19415, statics (tan(alpha) - mu) /
# (1 + mu tan(alpha)) = -0.194175), and ends held by the pull with every
# friction traction on the cone, pointing up the slope. A pair that
# rebuilt its tractions from the reference positions would find almost no
# tangential traction there (the block is back where it started): the
# explicit run would start out of equilibrium (measured so: kinetic /
# internal energy 1.7e-2, relative energy error 0.15, the pull's force
# drifting from -0.194 to -0.036 kN). Checked over the 0.1 ms explicit run:
# - kinetic energy / internal energy <= 1e-12 (measured 2e-17);
# - the relative energy error (energy_error) <= 1e-7 (measured 6e-9);
# - the pull's force stays the preload's last one to 1e-10 relative, and
#   friction does almost no work (|friction_work| <= 1e-12 J, measured
#   3e-15 J: the nodes on the cone keep flipping between slip and stick
#   at round-off);
# - the load path's sliding forces against statics within 0.1 %;
# - a restart from the preload checkpoint (Output/Restart from checkpoint,
#   another End time) starts from the same state: no load step, and the
#   same first row.
# Usage: contact_pair_handoff.sh EXECUTABLE SOURCE_DIR NPROC
set -euo pipefail
exe=$1; source_dir=$2; nproc=$3
source "$source_dir/tests/model/script_helpers.sh"
write_prm() { # END_TIME RESTART
  cat > handoff.prm <<PRM
set Study = Model
subsection Mesh
  set Mesh file = $source_dir/parameter_files/meshes/block_on_slope.msh
end
subsection Parts
  set Names = base, block
  subsection base
    set Material ids    = 1
    set Model           = Elastic
    set Young's modulus = 210
    set Poisson's ratio = 0.3
    set Density         = 7.85e-6
  end
  subsection block
    set Material ids    = 2
    set Model           = Elastic
    set Young's modulus = 210
    set Poisson's ratio = 0.3
    set Density         = 7.85e-6
  end
end
subsection Boundary conditions
  set Names = ground, weight, push
  subsection ground
    set Boundary ids = 1
    set Type         = fixed
  end
  subsection weight
    set Boundary ids        = 4
    set Type                = traction
    set Components          = z
    set Function expression = -0.01
  end
  subsection push
    set Boundary ids        = 5
    set Type                = displacement
    set Components          = x
    set Function expression = t < 0.2 ? 0 : (t < 0.6 ? d * (t - 0.2) / 0.4 : d * (1 - t) / 0.4)
    set Function constants  = d = 0.005
  end
end
subsection Contact pairs
  set Names = slope
  subsection slope
    set Slave boundary ids           = 3
    set Master boundary ids          = 2
    set Type                         = Coulomb
    set Static friction coefficient  = 0.3
    set Dynamic friction coefficient = 0.3
  end
end
subsection Time integration
  set Scheme                = quasi-static then explicit
  set End time              = $1
  set Quasi-static end time = 1
  subsection Quasi-static
    set Initial step  = 0.05
    set Maximum step  = 0.05
    set Linear solver = direct
  end
end
subsection Output
  set Output directory          = handoff
  set History output interval   = 0.005
  set Field output interval     = 0
  set Restart from checkpoint   = $2
end
PRM
}
rm -rf handoff
write_prm 0.1 false
run_prm handoff.prm log.txt
grep "^Finished" log.txt
# The load path: sliding up at t = 0.4 to 0.6, down from 0.75 on.
awk -F, '
  function abs(x) { return x < 0 ? -x : x }
  NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
  { t = $c["time"]; r = $c["push_force_x"] / -$c["weight_force_z"] }
  t > 0.39 && t < 0.61 { ++up; e = abs(r / 0.412371 - 1); if (e > worst) worst = e }
  t > 0.74 { ++down; e = abs(r / -0.194175 - 1); if (e > worst) worst = e }
  END {
    printf "load path: %d rows sliding up, %d down; largest deviation from statics %.4f %%\n", up, down, 100 * worst
    exit (up != 5 || down != 6 || worst > 1e-3)
  }' handoff/preload/time_history.csv
handoff_at_rest handoff/time_history.csv push_force_x 1e-7 1e-12
first_row=$(sed -n 2p handoff/time_history.csv | cut -d, -f3-)

# Another explicit run from the same preload.
write_prm 0.05 true
restart_from_preload handoff.prm \
  handoff_at_rest handoff/time_history.csv push_force_x 1e-7 1e-12
