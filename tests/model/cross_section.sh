#!/usr/bin/env bash
# Cross sections for output (Cross sections/<name>, doc/model.md; the
# bushing's bolt_axial_force and bolt_bending_moment, issue 10) against
# statics, which they must satisfy exactly: in equilibrium the internal
# forces of the uncut elements cancel (each element's forces have zero
# resultant and zero moment), so the resultant of the cut elements' forces
# at their nodes on the Normal's side equals the resultant and moment of
# the external forces on that side.
#
# 1. A steel cantilever (meshes/bar.msh: 100 x 10 x 10 mm along x, 20 x 2 x
#    2 cells) clamped at x = 0, loaded at x = 100 by a traction of
#    resultant (2, 1.5, -1) kN (axial, two shears: bending about y and z
#    and, through the offset of the traction's centre, no torque), brought
#    to equilibrium on a quasi-static load path and handed to an explicit
#    run (`quasi-static then explicit`), which starts at rest in that
#    equilibrium. Two sections, at x = 52.5 (normal +x) and x = 22.5
#    (normal -x, so that its resultant is the clamp side's). In the first
#    row of the explicit run: the section at 52.5 carries minus the clamp's
#    reaction R and its moment (M_R about the clamp's Moment point p,
#    moved to the section's centre c: M_R + (p - c) x R); the section at
#    22.5 with the opposite normal carries plus them. Bound 1e-6 of |R| and
#    of |R| times the lever 50 mm (Newton's tolerance on the reactions is
#    1e-8; measured in the log below).
# 2. The bolt of parameter_files/bolted_plates.prm, preloaded to 84 kN by
#    its pretension section: a cross section in the same plane gives the
#    same axial force as the pretension section's <name>_force (the same
#    elements and forces: to 1e-9 relative), and, the joint being
#    symmetric, a shear force and a bending moment below 1e-6 of the axial
#    force (kN) and of the axial force times the shank radius (kN mm).
# 3. Bad input, one line naming the entry: a plane that cuts no element of
#    its part.
# Usage: cross_section.sh EXECUTABLE SOURCE_DIR NPROC
set -euo pipefail
exe=$1; source_dir=$2; nproc=$3
source "$source_dir/tests/model/script_helpers.sh"

# ---- 1. The cantilever.
cantilever() {
  cat <<PRM
$(steel_bar_model)
subsection Boundary conditions
  set Names = clamp, load
  subsection clamp
    set Boundary ids = 1
    set Type         = fixed
    set Moment point = 0, 5, 5
  end
  subsection load
    set Boundary ids        = 2
    set Type                = traction
    # (2, 1.5, -1) kN over the 100 mm^2 end, constant: the load path and
    # the explicit run start from the same value (the hand-off rule).
    set Function expression = 0.02; 0.015; -0.01
  end
end
subsection Cross sections
  set Names = middle, near_clamp
  subsection middle
    set Part   = bar
    set Point  = 52.5, 0, 0
    set Normal = 1, 0, 0
  end
  subsection near_clamp
    set Part   = bar
    set Point  = 22.5, 0, 0
    set Normal = -1, 0, 0
  end
end
subsection Time integration
  set Scheme                = quasi-static then explicit
  set Quasi-static end time = 1
  set End time              = 0.001
  subsection Quasi-static
    set Initial step = 0.5
    set Maximum step = 0.5
  end
end
subsection Output
  set Output directory        = cantilever
  set History output interval = 0.001
  set Field output interval   = 0
end
PRM
}
cantilever > cantilever.prm
rm -rf cantilever
run_prm cantilever.prm cantilever.log
awk -F, '
  function col(name) { if (!(name in c)) { print "no column " name; exit 1 } return $c[name] }
  function abs(x) { return x < 0 ? -x : x }
  NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
  NR == 2 {
    split("x y z", axis, " ")
    for (k = 1; k <= 3; ++k) {
      R[k] = col("clamp_force_" axis[k]); MR[k] = col("clamp_moment_" axis[k]) }
    p[1] = 0; p[2] = 5; p[3] = 5
    norm = sqrt(R[1]^2 + R[2]^2 + R[3]^2)
    worst_f = 0; worst_m = 0
    for (s = 1; s <= 2; ++s) {
      name = s == 1 ? "middle" : "near_clamp"; sign = s == 1 ? -1 : 1
      for (k = 1; k <= 3; ++k) {
        F[k] = col(name "_force_" axis[k]); M[k] = col(name "_moment_" axis[k])
        centre[k] = col(name "_centre_" axis[k]); d[k] = p[k] - centre[k] }
      # The reaction moment about the section centre: M_R + (p - c) x R.
      Mc[1] = MR[1] + d[2] * R[3] - d[3] * R[2]
      Mc[2] = MR[2] + d[3] * R[1] - d[1] * R[3]
      Mc[3] = MR[3] + d[1] * R[2] - d[2] * R[1]
      for (k = 1; k <= 3; ++k) {
        ef = abs(F[k] - sign * R[k]) / norm; if (ef > worst_f) worst_f = ef
        em = abs(M[k] - sign * Mc[k]) / (50 * norm); if (em > worst_m) worst_m = em }
      printf "%s: force %.6f %.6f %.6f kN, moment %.4f %.4f %.4f kN mm about (%.3f, %.3f, %.3f) mm; axial %.6f kN, shear %.6f kN, torque %.3g kN mm, bending %.4f kN mm\n", name, F[1], F[2], F[3], M[1], M[2], M[3], centre[1], centre[2], centre[3], col(name "_axial_force"), col(name "_shear_force"), col(name "_torque"), col(name "_bending_moment")
    }
    printf "cantilever: |R| = %.6f kN; sections against the clamp reaction: force %.2g, moment %.2g (relative)\n", norm, worst_f, worst_m
    exit (worst_f > 1e-6 || worst_m > 1e-6 || !(norm > 2.6))
  }' cantilever/time_history.csv

# ---- 2. The bolt: cross section = pretension section.
sed -e "s|set Mesh file *= *\(meshes/.*\)|set Mesh file = $source_dir/parameter_files/\1|" \
    -e "s|set End time *=.*|set End time = 0.001|" \
    -e "s|set History output interval *=.*|set History output interval = 0.001|" \
    -e "s|set Field output interval *=.*|set Field output interval = 0|" \
    -e "s|set Output directory *=.*|set Output directory = bolt|" \
    "$source_dir/parameter_files/bolted_plates.prm" > bolt.prm
cat >> bolt.prm <<PRM
subsection Cross sections
  set Names = shank
  subsection shank
    set Part   = bolt
    set Point  = 0, 0, 3.75
    set Normal = 0, 0, 1
  end
end
PRM
rm -rf bolt
run_prm bolt.prm bolt.log
awk -F, '
  function abs(x) { return x < 0 ? -x : x }
  NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
  NR == 2 {
    N = $c["bolt_section_force"]; A = $c["shank_axial_force"]
    S = $c["shank_shear_force"]; B = $c["shank_bending_moment"]
    printf "bolt: pretension section %.9f kN, cross section axial %.9f kN (%.2g relative), shear %.3g kN, bending %.3g kN mm, torque %.3g kN mm\n", N, A, abs(A / N - 1), S, B, $c["shank_torque"]
    exit (abs(A / N - 1) > 1e-9 || S > 1e-6 * N || B > 1e-6 * 8 * N || abs(N - 84) > 1e-3)
  }' bolt/time_history.csv

# ---- 3. A plane that misses the part.
sed -e "s|set Point  = 52.5, 0, 0|set Point  = 150, 0, 0|" \
    -e "s|Output directory        = cantilever|Output directory        = missed|" \
    cantilever.prm > missed.prm
if run_prm missed.prm missed.log 2> missed.err; then
  echo "a plane outside the part was accepted"; exit 1
fi
grep -h "Cross sections/middle/Point" missed.log missed.err | head -n 1
