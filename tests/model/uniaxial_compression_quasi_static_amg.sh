#!/usr/bin/env bash
# The quasi-static uniaxial compression of uniaxial_compression_quasi_static
# .sh with Linear solver = AMG (CG with Trilinos ML, near-null space = the
# six rigid-body modes passed through the Teuchos list) on NPROC ranks: the
# history equals the direct solver's on 1 rank to 1e-8 relative (both
# converge Newton to the same tolerances; the linear tolerance 1e-10 is far
# below them), every Newton iteration reports at least one CG iteration, and
# the log names the solver.
# Usage: uniaxial_compression_quasi_static_amg.sh EXECUTABLE SOURCE_DIR NPROC
set -euo pipefail
exe=$1; source_dir=$2; nproc=$3
name=uniaxial_compression_quasi_static
mkdir -p direct amg
(cd direct && bash "$source_dir/tests/model/run_example.sh" "$exe" \
  "$source_dir" $name 1 0 1 > log.txt)
cd amg
sed -e "s|set Mesh file *= *\(meshes/.*\)|set Mesh file = $source_dir/parameter_files/\1|" \
    -e "s|set Output directory *=.*|set Output directory = $name|" \
    -e "s|set Linear solver *=.*|set Linear solver = AMG|" \
    "$source_dir/parameter_files/$name.prm" > $name.prm
rm -rf $name
if [ "$nproc" -gt 1 ]; then
  mpirun --oversubscribe -np "$nproc" "$exe" $name.prm > log.txt
else
  "$exe" $name.prm > log.txt
fi
grep -q "linear solver CG with ML AMG (6 rigid-body modes)" log.txt
awk '/^    iteration/ { ++n; for (i = 1; i <= NF; ++i) if ($i == "linear") it = $(i + 2) + 0
                       if (it < 1) bad = 1 }
     END { printf "%d Newton iterations, each with CG iterations: %s\n", n, bad ? "no" : "yes"; exit (bad || n == 0) }' log.txt
cd ..
bash "$source_dir/tests/model/compare_columns.sh" \
  direct/$name/time_history.csv amg/$name/time_history.csv 1e-8 1e-12 \
  time press_force_z symmetry_z_force_z internal_energy
