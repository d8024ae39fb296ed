#!/usr/bin/env bash
# Cook's membrane by the quasi-static solver (parameter_files/
# cook_membrane.prm; doc/verification/reference_solutions.md §2): plane strain, nearly
# incompressible neo-Hooke (K/G = 5000), 100 N of shear on the free end, the
# top corner's vertical displacement (the History node 'tip') on the
# structured meshes of 2, 4, 8, 16 and 32 elements a side.
# Requirements (issue 9):
# - F-bar: the tip displacement increases monotonically with refinement;
#   at 32 x 32 it is within 1 % of the converged 6.908 mm (Elguedj,
#   Bazilevs, Calo, Hughes, CMAME 197 (2008) 2732, 128 x 128 NURBS) and
#   within 2 % of the published F-bar hexahedra at 20 to 30 elements a side,
#   6.86 to 6.89 mm (e.g. de Souza Neto, Peric, Owen, Computational Methods
#   for Plasticity (2008), section 15.4; Elguedj et al. table 2);
# - the plain displacement element locks visibly: at 32 x 32 its tip moves
#   less than half as far as F-bar's (measured: 2.86 against 6.88 mm);
# - equilibrium at every converged step: the clamped edge's reaction
#   clamped_force_y equals minus the applied load shear_force_y, 0.1 t kN,
#   to 1e-8 kN;
# - on 2 ranks, the 16 x 16 F-bar tip equals the 1-rank value to 1e-8
#   relative (NPROC = 2; the 1-rank run is repeated for the comparison;
#   time_history.csv has 9 significant digits, a resolution of 1.5e-9).
# Usage: cook_membrane_quasi_static.sh EXECUTABLE SOURCE_DIR NPROC
set -euo pipefail
exe=$1; source_dir=$2; nproc=$3

# run NAME N FORMULATION [RANKS]: the example on cook_membrane_N with the
# formulation; prints the tip's final y displacement, checks equilibrium.
run() {
  local name=$1 n=$2 formulation=$3 ranks=${4:-1}
  sed -e "s|set Mesh file *=.*|set Mesh file = $source_dir/parameter_files/meshes/cook_membrane_$n.msh|" \
      -e "s|set Element formulation *=.*|set Element formulation = $formulation|" \
      -e "s|set Output directory *=.*|set Output directory = $name|" \
      "$source_dir/parameter_files/cook_membrane.prm" > "$name.prm"
  rm -rf "$name"
  if [ "$ranks" -gt 1 ]; then
    mpirun --oversubscribe -np "$ranks" "$exe" "$name.prm" > "$name.log"
  else
    "$exe" "$name.prm" > "$name.log"
  fi
  awk -F, '
    NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
    {
      e = $c["clamped_force_y"] + $c["shear_force_y"]; if (e < 0) e = -e
      a = $c["shear_force_y"] - 0.1 * $c["time"]; if (a < 0) a = -a
      if (e > 1e-8 || a > 1e-12) { printf "equilibrium off at t = %s: %.3e, load %.3e\n", $c["time"], e, a; bad = 1 }
      tip = $c["tip_displacement_y"]; t = $c["time"]
    }
    END { if (bad || t != 1) exit 1; printf "%.15g\n", tip }' "$name/time_history.csv"
}

if [ "$nproc" -gt 1 ]; then
  serial=$(run serial_16 16 F-bar)
  parallel=$(run parallel_16 16 F-bar "$nproc")
  echo "16 x 16 F-bar tip: 1 rank $serial mm, $nproc ranks $parallel mm"
  awk -v a="$serial" -v b="$parallel" 'BEGIN {
    e = (b - a) / a; if (e < 0) e = -e
    printf "relative difference %.2e (bound 1e-8)\n", e; exit (e > 1e-8) }'
  exit
fi

previous=0
echo "elements a side, F-bar tip (mm)"
for n in 2 4 8 16 32; do
  tip=$(run fbar_$n $n F-bar)
  echo "$n $tip"
  awk -v a="$previous" -v b="$tip" 'BEGIN { if (b <= a) { print "not monotone"; exit 1 } }'
  previous=$tip
done
locked=$(run displacement_32 32 displacement)
echo "32 displacement element tip: $locked mm"
awk -v f="$previous" -v d="$locked" 'BEGIN {
  e = f / 6.908 - 1; if (e < 0) e = -e
  lo = f / 6.86 - 1; hi = f / 6.89 - 1
  printf "32 x 32 F-bar: %.4f mm, %.3f %% from 6.908, %+.3f %% / %+.3f %% from 6.86 / 6.89\n", f, 100 * e, 100 * lo, 100 * hi
  if (e > 0.01) { print "more than 1 % from 6.908"; exit 1 }
  if (lo > 0.02 || lo < -0.02 || hi > 0.02 || hi < -0.02) { print "more than 2 % from the published F-bar values"; exit 1 }
  if (d > 0.5 * f) { print "the displacement element does not lock"; exit 1 }
  print "displacement element / F-bar: " d / f
}'
