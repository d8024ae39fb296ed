#!/usr/bin/env bash
# The bonded tube in torsion (doc/verification/reference_solutions.md §3) in CalculiX 2.20 and
# in rubberdyn on the same mesh, against the exact torque: time and result
# side by side. Not a test (ccx is not a test dependency).
#   apt-get install calculix-ccx      # once
#   benchmarks/calculix/run_calculix_tube.sh [N] [BUILD_DIR] [WORK_DIR]
# N: the mesh parameter_files/meshes/tube_N.msh (default 8). Needs the
# targets rubberdyn and tube_exact_torque in BUILD_DIR (default build).
# Writes WORK_DIR/comparison.md (default /tmp/calculix_tube_N): per load
# step the exact torque, rubberdyn's F-bar and CalculiX's C3D8, C3D8R and
# C3D8I (each as far as it converges), and the wall time of each run.
set -euo pipefail
source_dir=$(cd "$(dirname "$0")/../.." && pwd)
n=${1:-8}
build=$(cd "${2:-$source_dir/build}" && pwd)
work=${3:-/tmp/calculix_tube_$n}
mesh=$source_dir/parameter_files/meshes/tube_$n.msh
script=$source_dir/benchmarks/calculix/tube_torsion.py
mkdir -p "$work" && cd "$work"
cmake --build "$build" --target rubberdyn tube_exact_torque > /dev/null

# rubberdyn: the example on this mesh (its 10 load steps are the same
# rotations as the deck's 10 steps).
sed -e "s|set Mesh file *=.*|set Mesh file = $mesh|" \
    -e "s|set Output directory *=.*|set Output directory = rubberdyn|" \
    "$source_dir/parameter_files/tube_torsion.prm" > tube.prm
rm -rf rubberdyn
t_rubberdyn=$( { /usr/bin/time -f "%e" "$build/rubberdyn" tube.prm > rubberdyn.log; } 2>&1 | tail -1)
awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
  $c["time"] > 0 { printf "%.6f,%s\n", 1.039247 * $c["time"], $c["outer_moment_z"] }' \
  rubberdyn/time_history.csv > rubberdyn.csv

declare -A t_ccx
for element in C3D8 C3D8R C3D8I; do
  python3 "$script" "$mesh" $element $element.inp
  t_ccx[$element]=$( { /usr/bin/time -f "%e" ccx -i $element > $element.log || true; } 2>&1 | tail -1)
  python3 "$script" --torque "$mesh" $element.dat | tail -n +2 > $element.csv
done

"$build/tests/verification/tube_exact_torque" $(cut -d, -f1 rubberdyn.csv) > exact.txt
{
  echo "# The bonded tube in torsion, tube_$n: torque (kN mm) and its error"
  echo
  echo "| φ (rad) | exact | rubberdyn F-bar | CalculiX C3D8 | CalculiX C3D8R | CalculiX C3D8I |"
  echo "|---|---|---|---|---|---|"
  awk -F'[ ,]' '
    FILENAME == "exact.txt" { exact[FNR] = $2; phi[FNR] = $1; n = FNR; next }
    { value[FILENAME, FNR] = $2 }
    END {
      split("rubberdyn.csv C3D8.csv C3D8R.csv C3D8I.csv", files, " ")
      for (k = 1; k <= n; ++k) {
        printf "| %.3f | %.4f |", phi[k], exact[k]
        for (f = 1; f <= 4; ++f) {
          v = value[files[f], k]
          if (v == "") printf " (no convergence) |"
          else printf " %.4f (%+.2f %%) |", v, 100 * (v / exact[k] - 1)
        }
        printf "\n"
      }
    }' exact.txt rubberdyn.csv C3D8.csv C3D8R.csv C3D8I.csv
  echo
  echo "Wall time (s): rubberdyn $t_rubberdyn, CalculiX C3D8 ${t_ccx[C3D8]}, C3D8R ${t_ccx[C3D8R]}, C3D8I ${t_ccx[C3D8I]}."
} > comparison.md
cat comparison.md
