#!/usr/bin/env bash
# Load-step control of the quasi-static solver: the rubber block bonded to a
# steel plate (parameter_files/meshes/bonded_block.msh), base fixed, the
# plate pushed 3 mm down and 2 mm sideways, hyperelastic laws. With steps of
# 0.25 Newton cannot converge the step to t = 0.5 (nor, later, to t = 1) in
# 15 iterations; the solver must cut back (halve from the last converged
# state) and still reach t = 1. Hyperelastic equilibrium does not depend on
# the load path, so the end state must equal that of a run with steps of
# 0.0625 throughout: the plate's reactions and the strain energy at t = 1
# to 1e-6 relative (both runs converge to 1e-8 of the reactions).
# Usage: quasi_static_cut_back.sh EXECUTABLE SOURCE_DIR NPROC
set -euo pipefail
exe=$1; source_dir=$2; nproc=$3
write_prm() { # STEP OUTPUT
  cat <<PRM
set Study = Model
subsection Mesh
  set Mesh file = $source_dir/parameter_files/meshes/bonded_block.msh
end
subsection Parts
  set Names = rubber, steel
  subsection rubber
    set Material ids     = 1
    set Model            = Yeoh
    set Constants from   = coefficients
    set C10              = 0.00055
    set C20              = -0.00005
    set C30              = 0.000015
    set Volumetric model = bulk modulus
    set Bulk modulus     = 1.1
    set Density          = 1.1e-6
  end
  subsection steel
    set Material ids    = 2
    set Model           = Elastic
    set Young's modulus = 210
    set Poisson's ratio = 0.3
    set Density         = 7.85e-6
  end
end
subsection Boundary conditions
  set Names = base, press
  subsection base
    set Boundary ids = 1
    set Type         = fixed
  end
  subsection press
    set Boundary ids        = 2
    set Type                = displacement
    set Components          = x, z
    set Function expression = 2 * t; -3 * t
  end
end
subsection Time integration
  set Scheme = quasi-static
  subsection Quasi-static
    set Initial step = $1
    set Maximum step = $1
  end
end
subsection Output
  set Output directory        = $2
  set History output interval = 0
end
PRM
}
source "$(dirname "$0")/script_helpers.sh"
write_prm 0.25 coarse > coarse.prm
write_prm 0.0625 fine > fine.prm
rm -rf coarse fine
run_prm coarse.prm coarse.log
run_prm fine.prm fine.log
cutbacks=$(grep -c "Cut back: no convergence in 15 iterations" coarse.log || true)
echo "cut-backs with steps of 0.25: $cutbacks"
grep -q "Finished: .* load steps to t = 1," coarse.log
[ "$cutbacks" -ge 1 ]
! grep -q "Cut back" fine.log
# The last rows (t = 1) of the two histories.
tail -n 1 coarse/time_history.csv > coarse_end.csv
tail -n 1 fine/time_history.csv > fine_end.csv
head -n 1 coarse/time_history.csv | cat - coarse_end.csv > a.csv
head -n 1 fine/time_history.csv | cat - fine_end.csv > b.csv
bash "$source_dir/tests/model/compare_columns.sh" a.csv b.csv 1e-6 1e-12 \
  time press_force_x press_force_z base_force_x base_force_z internal_energy
