#!/usr/bin/env bash
# The F-bar stabilisation in bending (doc/theory.md 8.1, doc/bushing.md "F-bar
# stabilisation in the bending parts"): Cook's membrane on 16 x 16 elements
# (parameter_files/cook_membrane.prm, plane strain, neo-Hooke with K/G = 5000,
# quasi-static), the top corner's vertical displacement ('tip') with the
# part's own 'F-bar stabilization' beta.
#  - The stabilisation gives back the locking F-bar removes: the tip
#    decreases strictly with beta = 0, 0.001, 0.01, 0.1, 1.
#  - beta = 1 is the displacement element: with kappa = K, the energy
#    K/2 e_0^2 + kappa/2 (e_q - e_0)^2 summed over the Gauss points equals
#    the displacement element's K/2 e_q^2 when the centre's volumetric strain
#    e_0 is the Gauss points' mean (exact on parallelepipeds at small
#    strain, doc/theory.md 8.1); both tips agree to 1e-5 relative (measured:
#    2e-7, the finite strain and the membrane's skewed cells).
#  - The part's entry overrides Time integration/F-bar stabilization, and the
#    same beta from either entry gives the same tip to every printed digit:
#    global 0.1 = part 0.1 (global 0), and global 0.1 with the part's 0 =
#    global 0.
# Usage: fbar_stabilization_bending.sh EXECUTABLE SOURCE_DIR NPROC
set -euo pipefail
exe=$1; source_dir=$2; nproc=$3
source "$source_dir/tests/model/script_helpers.sh"

# tip NAME FORMULATION GLOBAL_BETA [PART_BETA]: the final tip displacement
# (mm) of the membrane with these entries.
tip() {
  local name=$1 formulation=$2 global=$3 part=${4:-}
  sed -e "s|set Mesh file *=.*|set Mesh file = $source_dir/parameter_files/meshes/cook_membrane_16.msh|" \
      -e "s|set Element formulation *=.*|set Element formulation = $formulation\n    set F-bar stabilization = $part|" \
      -e "s|set Quasi-static end time *= 1|set Quasi-static end time = 1\n  set F-bar stabilization = $global|" \
      -e "s|set Output directory *=.*|set Output directory = $name|" \
      "$source_dir/parameter_files/cook_membrane.prm" > "$name.prm"
  grep -q "^    set F-bar stabilization = $part\$" "$name.prm" &&
    grep -q "^  set F-bar stabilization = $global\$" "$name.prm" ||
    { echo "$name.prm: the stabilization entries did not take" >&2; exit 1; }
  rm -rf "$name"
  run_prm "$name.prm" "$name.log"
  awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
           { t = $c["time"]; tip = $c["tip_displacement_y"] }
           END { if (t != 1) exit 1; print tip }' "$name/time_history.csv"
}

declare -A part
for beta in 0 0.001 0.01 0.1 1; do
  part[$beta]=$(tip "part_$beta" F-bar 0 "$beta")
  echo "part's beta $beta: tip ${part[$beta]} mm"
done
displacement=$(tip displacement displacement 0)
global_01=$(tip global_0.1 F-bar 0.1)
global_01_part_0=$(tip global_0.1_part_0 F-bar 0.1 0)
global_0=$(tip global_0 F-bar 0)
echo "displacement element: tip $displacement mm"
echo "Time integration's beta 0.1: $global_01 mm; with the part's 0: $global_01_part_0 mm; beta 0: $global_0 mm"

fail=0
previous=""
for beta in 0 0.001 0.01 0.1 1; do
  if [ -n "$previous" ] &&
     ! awk -v a="$previous" -v b="${part[$beta]}" 'BEGIN { exit !(b < a) }'; then
    echo "the tip does not decrease from beta below to $beta"; fail=1
  fi
  previous=${part[$beta]}
done
awk -v s="${part[1]}" -v d="$displacement" 'BEGIN {
  e = s / d - 1; if (e < 0) e = -e
  printf "beta 1 / displacement element - 1: %.2e (bound 1e-5)\n", e
  exit (e > 1e-5) }' || fail=1
[ "$global_01" = "${part[0.1]}" ] ||
  { echo "Time integration's 0.1 ($global_01) is not the part's 0.1 (${part[0.1]})"; fail=1; }
[ "$global_01_part_0" = "$global_0" ] ||
  { echo "the part's 0 under Time integration's 0.1 ($global_01_part_0) is not beta 0 ($global_0)"; fail=1; }
[ "$global_0" = "${part[0]}" ] ||
  { echo "Time integration's 0 ($global_0) is not the part's 0 (${part[0]})"; fail=1; }
exit $fail
