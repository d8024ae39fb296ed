#!/usr/bin/env bash
# The contact patch test, quasi-static, through the mortar contact pair's
# consistent tangent (parameter_files/contact_patch_test.prm: two blocks
# 10 x 10 x 5 mm stacked with non-matching meshes, 5 x 5 faces on 4 x 4,
# 0.05 mm apart; Taylor, Papadopoulos, Int. J. Numer. Meth. Engng 29 (1990)
# 123 for the test; the bounds). Three variants:
#  a. the example: the upper block steel, the lower one ten times softer
#     (E = 210 and 21 GPa, nu = 0.3), all sides symmetry planes (uniaxial
#     strain), the top pushed down by 0.15 mm, the finer upper face the
#     slave;
#  b. the same with slave and master swapped (the coarser face the slave);
#  c. finite strain: both blocks of the reference study's Yeoh rubber
#     (K/G = 1000), the sides x = 10 and y = 10 free (uniaxial stress),
#     compressed by 10 % (1 mm of the 10 mm after the gap closes).
# Checked at every converged load step in contact (the gap closes at
# t = 1/3 in a and b, 0.05 / 1.05 in c):
#  - uniform pressure: (max_pressure - min_pressure) / max_pressure
#    below 1e-6, and it equals the normal force over the contact area to
#    1e-8;
#  - equilibrium: the normal force equals the top's and the base's
#    reactions to 1e-8 relative;
#  - both blocks' strains uniform (so their stresses): the history nodes'
#    displacements are linear in their coordinates, to 1e-8 mm (columns of
#    9 digits) and, in c, the lateral stretch u_x / x and u_y / y the same
#    at every node of both blocks to 1e-7 relative;
#  - c: the top's force against the reference study's eq. 4.8 (shared/
#    seed-notes.md, incompressible Yeoh; the stretch lambda from the upper
#    block's nodes) within 0.3 % (the compressible law at K/G = 1000 and
#    the contact's stiffness differ from it by O(G/K));
#  - Newton converges quadratically (check_newton_log.sh: the consistent
#    contact tangent; a frozen-segment tangent converges linearly), also
#    after each update of the penalty to the converged geometry, down to
#    the residual's round-off floor, 1e-10 relative (c reaches 2e-11 in
#    converged steps).
# On 2 ranks variant a's columns must equal a 1-rank run's to 1e-8 relative
# (the interface is split between the ranks).
# Usage: contact_patch_test.sh EXECUTABLE SOURCE_DIR NPROC
set -euo pipefail
exe=$1; source_dir=$2; nproc=$3
example="$source_dir/parameter_files/contact_patch_test.prm"

# newton NAME: check_newton_log.sh on the steps in contact (before, the
# upper block only moves: residuals of round-off, ~1e-15 kN, with no
# reaction to measure them by).
newton() {
  awk '/^  Step to/ { step = $0; next }
       /^    iteration 1:/ { keep = ($4 + 0 > 1e-12); if (keep) print step }
       keep' "$1.log" > "$1.contact.log"
  bash "$source_dir/tests/model/check_newton_log.sh" "$1.contact.log" 1e-2 10 6 1e-10
}

# run NAME NPROC SED_ARGS...: the example, changed, in directory NAME.
run() {
  local name=$1 ranks=$2; shift 2
  sed "$@" \
      -e "s|set Mesh file *= *\(meshes/.*\)|set Mesh file = $source_dir/parameter_files/\1|" \
      -e "s|set Output directory *=.*|set Output directory = $name|" \
      "$example" > "$name.prm"
  rm -rf "$name"
  if [ "$ranks" -gt 1 ]; then
    mpirun --oversubscribe -np "$ranks" "$exe" "$name.prm" > "$name.log"
  else
    "$exe" "$name.prm" > "$name.log"
  fi
}

# check NAME YEOH: the checks above on NAME/time_history.csv.
check() {
  awk -F, -v name="$1" -v yeoh="$2" '
    function abs(x) { return x < 0 ? -x : x }
    function col(n) { return $c[n] }
    function z(n) { return col(n "_displacement_z") }
    function fail(what) { printf "%s: t = %s: %s\n", name, col("time"), what; bad = 1 }
    NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
    col("interface_active_nodes") > 0 {
      ++rows
      p = col("interface_max_pressure"); N = col("interface_normal_force")
      spread = (p - col("interface_min_pressure")) / p
      if (spread > worst_spread) worst_spread = spread
      if (spread > 1e-6) fail("pressure not uniform: " spread)
      if (abs(N / col("interface_contact_area") - p) > 1e-8 * p) fail("p != N / A")
      if (abs(N + col("press_force_z")) > 1e-8 * N || abs(N - col("base_force_z")) > 1e-8 * N)
        fail("no equilibrium")
      # Lower block: base at z = 0, interface at 5 (l1..l3), mid-height
      # 2.5 (l4, l5).
      top = z("l1")
      e = 0
      e += abs(z("l2") - top) + abs(z("l3") - top)
      e += abs(z("l4") - top / 2) + abs(z("l5") - top / 2)
      # Upper block: bottom at 5.05 (u1..u3), thirds (u4, u5; u6), top
      # 10.05 (u7).
      b = z("u1"); t = z("u7")
      e += abs(z("u2") - b) + abs(z("u3") - b)
      e += abs(z("u4") - (b + (t - b) / 3)) + abs(z("u5") - (b + (t - b) / 3))
      e += abs(z("u6") - (b + 2 * (t - b) / 3))
      if (e > worst_linear) worst_linear = e
      if (e > 1e-8) fail("strain not uniform: " e " mm")
      if (yeoh) {
        # The lateral stretch: u_x / x (u_y / y) the same everywhere.
        s = col("l2_displacement_x") / 10
        split("l2:10:10 l3:5:2.5 l4:7.5:7.5 l5:2.5:5 u2:10:10 u3:4:6 u4:6:2 u5:2:8 u6:8:4 u7:10:0", nodes, " ")
        for (k in nodes) {
          split(nodes[k], xyz, ":")
          d = abs(col(xyz[1] "_displacement_x") - s * xyz[2]) + abs(col(xyz[1] "_displacement_y") - s * xyz[3])
          if (d > 1e-7 * abs(s) * 10 + 1e-9) fail("lateral stretch not uniform at " xyz[1])
        }
        C10 = 0.55e-3; C20 = -0.05e-3; C30 = 0.015e-3; A0 = 100
        lambda = 1 + (t - b) / 5; I = lambda^2 + 2 / lambda - 3
        F = A0 * 2 * (lambda - lambda^-2) * (C10 + 2 * C20 * I + 3 * C30 * I^2)
        dev = col("press_force_z") / F - 1
        if (abs(dev) > worst_yeoh) { worst_yeoh = abs(dev); worst_lambda = lambda }
        if (abs(dev) > 0.003) fail("force against eq. 4.8: " dev)
      }
    }
    END {
      printf "%s: %d steps in contact; pressure spread %.2e, strain linearity %.2e mm", name, rows, worst_spread, worst_linear
      if (yeoh) printf ", eq. 4.8 %.3f %% (lambda %.3f)", 100 * worst_yeoh, worst_lambda
      printf "\n"
      exit (bad || rows < 5)
    }' "$1/time_history.csv"
}

run a 1
check a 0
newton a

run b 1 -e "s|set Slave boundary ids *= 3|set Slave boundary ids = 2|" \
        -e "s|set Master boundary ids *= 2|set Master boundary ids = 3|"
check b 0
newton b

yeoh_part='    set Model = Yeoh\n    set Constants from = coefficients\n    set C10 = 0.00055\n    set C20 = -0.00005\n    set C30 = 0.000015\n    set Volumetric model = bulk modulus\n    set Bulk modulus = 1.1\n    set Density = 1.1e-6'
run c 1 -e "s|set Model *= Elastic|$yeoh_part|" \
        -e "/set Young's modulus/d" -e "/set Poisson's ratio/d" -e "/set Density *= 7.85e-6/d" \
        -e "s|set Names = base, symmetry_x0, symmetry_y0, symmetry_x1, symmetry_y1, press|set Names = base, symmetry_x0, symmetry_y0, press|" \
        -e "/subsection symmetry_[xy]1/,/end/d" \
        -e "s|set Function expression = -0.15 \* t|set Function expression = -1.05 * t|" \
        -e "s|set Initial step *=.*|set Initial step = 0.04|" \
        -e "s|set Maximum step *=.*|set Maximum step = 0.04|"
check c 1
newton c

if [ "$nproc" -gt 1 ]; then
  run a2 "$nproc"
  check a2 0
  bash "$source_dir/tests/model/compare_columns.sh" a/time_history.csv \
    a2/time_history.csv 1e-8 1e-12 time press_force_z base_force_z \
    interface_normal_force interface_max_pressure interface_min_pressure \
    interface_contact_area interface_max_penetration u1_displacement_z \
    u4_displacement_z l4_displacement_z
fi
