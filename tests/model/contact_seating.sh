#!/usr/bin/env bash
# The convergence floor (issue 43; doc/quasi_static.md, "Convergence"): a
# steel block lowered onto a rubber block through a Coulomb mortar pair
# until the faces interfere by 0.4 um, with the default Quasi-static
# settings. meshes/tied_block.msh at Scale 2: the study's Yeoh rubber
# 40 x 40 x 20 mm (8 x 8 x 4 cells, h = 5 mm) with its base fixed, and an
# elastic steel block 40 x 40 x 4 mm (5 x 5 x 1 cells) 0.1 mm above it,
# whose top is moved down by 0.1004 t mm (mu 0.3, rubber top slave). The
# gap closes at t = 0.996; at t = 1 the pair carries 1.6e-4 kN.
# Measured before the floor: 1e-8 of the reactions is 1.6e-12 kN, below the
# 4e-12 to 6e-12 kN the forces' round-off leaves (the corrections' energy
# 1e-26 J: converged), so no iteration met the criterion and no cut-back
# could help (every attempt ends in the same lightly touching state): the
# run failed at t = 0.996173 after 15 iterations, naming the Minimum step.
# With the round-off floor r0 = eps (K + 4G/3) h^2 sqrt(N) of the steel
# (K + 4G/3 = 282.7 GPa, h = 6.35 mm, N = 1431 dofs: 9.6e-11 kN) the force
# criterion is met at the round-off, and the energy criterion decides.
# Checked:
#  - the run finishes, no cut-back, at most 15 (the default Maximum
#    iterations) Newton iterations in a step;
#  - the log names the floor and the part that sets it (the steel);
#  - statics, exact for any discretisation: with no load, the press's and
#    the base's forces z cancel to 1e-10 kN (measured 4e-12: round-off; the
#    floor allows 9.6e-11), and before the gap closes (t <= 0.9) the
#    press carries nothing (|F| <= 1e-20 kN);
#  - the seating force against Hooke's law for the interference
#    delta = 0.0004 mm over the rubber's height H = 20 mm on its area
#    A = 1600 mm^2: between the unconfined E A delta / H (E = 3 G =
#    3.3e-3 GPa: 1.06e-4 kN; the bonded base and the sticking top only
#    stiffen it) and the laterally confined (K + 4 G / 3) A delta / H
#    (K = E / (3 (1 - 2 nu)), nu 0.499: 1.76e-2 kN); measured 1.56e-4 kN.
# Usage: contact_seating.sh EXECUTABLE SOURCE_DIR NPROC
set -euo pipefail
exe=$1; source_dir=$2; nproc=$3
source "$source_dir/tests/model/script_helpers.sh"

cat > seating.prm <<PRM
set Study = Model
subsection Mesh
  set Mesh file = $source_dir/parameter_files/meshes/tied_block.msh
  set Scale     = 2
end
subsection Parts
  set Names = rubber, steel
$(study_rubber_part)
$(elastic_steel_part steel 2)
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
    set Function expression = 0; 0; -0.1004 * t
  end
end
$(coulomb_pair interface 4 5 0.3)
subsection Time integration
  set Scheme = quasi-static
end
subsection Output
  set Output directory        = seating
  set History output interval = 0
  set Field output interval   = 0
end
PRM
rm -rf seating
run_prm seating.prm log.txt
grep "^Finished" log.txt
grep -q "(round-off: eps (K + 4G/3) h^2 sqrt(dofs) of steel" log.txt
grep "Converged:" log.txt
awk -F, '
  function abs(x) { return x < 0 ? -x : x }
  NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
  {
    if ($c["newton_iterations"] > most) most = $c["newton_iterations"]
    s = abs($c["press_force_z"] + $c["base_force_z"]); if (s > sum) sum = s
    if ($c["time"] <= 0.9 + 1e-9 && abs($c["press_force_z"]) > free) free = abs($c["press_force_z"])
    t = $c["time"]; f = abs($c["press_force_z"])
  }
  END {
    lower = 3.3e-3 * 1600 * 4e-4 / 20
    K = 3.3e-3 / (3 * (1 - 2 * 0.499)); upper = (K + 4 * 1.1e-3 / 3) * 1600 * 4e-4 / 20
    printf "t = %s: seating force %.4g kN (Hooke %.3g to %.3g), press + base %.1e kN, press before contact %.1e kN, at most %d Newton iterations a step\n", t, f, lower, upper, sum, free, most
    exit (t != 1 || sum > 1e-10 || free > 1e-20 || f < lower || f > upper || most > 15)
  }' seating/time_history.csv
grep -q " 0 cut-backs" log.txt
