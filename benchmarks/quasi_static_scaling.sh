#!/usr/bin/env bash
# Cost of the quasi-static solver against the problem size (issue 9's
# benchmark): per run the cells, dofs, load steps, Newton and linear
# iterations, wall and CPU (user + sys) time, peak memory (MB, the maximum
# resident set) and kB per dof, for three refinements of a 3D block and of
# the bonded tube, with the direct solver MUMPS (Amesos, the default
# `Direct solver`), with AMG (CG + Trilinos ML, six rigid-body modes), and
# with the direct solver KLU on the smallest size of each model only (KLU
# has no nested-dissection ordering: 970 s on block 16^3). Per series the
# growth exponent p of the wall and of the CPU time, t ~ N^p (least squares
# on log t against log N over the sizes that finished), the CPU time per
# Newton iteration, and the growth of the peak memory per dof between the
# smallest and the largest size (the libraries alone take about 170 MB).
#   benchmarks/quasi_static_scaling.sh [BUILD_DIR] [WORK_DIR] [RANKS] [LIMIT]
# Each run is stopped after LIMIT seconds of CPU time (default 900, ulimit
# -t; and after 3 LIMIT of wall time, for a loaded machine) and reported as
# dropped: MUMPS on block 32^3 (107 811 dofs) is, with the reference BLAS.
# Needs gmsh (Debian package gmsh) for the meshes beyond the shipped ones;
# one thread per process (OMP_NUM_THREADS=1). Results: benchmarks/README.md.
# - block: parameter_files/uniaxial_compression_quasi_static.prm (the
#   octant on three symmetry planes, F-bar) on compression_block_n,
#   n = 8, 16, 32 (n^3 cells), compressed by 30 % in its 20 load steps;
# - tube: parameter_files/tube_torsion.prm (F-bar) on tube_n, n = 4, 8, 16
#   (n cells through the wall, 8 n around, one along the axis: 8 n^2
#   cells), its 10 load steps to gamma(a) = 2.
# Writes WORK_DIR/scaling.md (default /tmp/quasi_static_scaling).
set -euo pipefail
source_dir=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${1:-$source_dir/build}" && pwd)
work=${2:-/tmp/quasi_static_scaling}
ranks=${3:-1}
limit=${4:-900}
mkdir -p "$work" && cd "$work"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMP_NUM_THREADS=1
meshes=$source_dir/parameter_files/meshes

mesh() { # mesh GEO N: the .msh of GEO at parameter n = N, made once
  local out=$work/$1_$2.msh
  if [ ! -f "$out" ]; then
    if [ -f "$meshes/$1_$2.msh" ]; then cp "$meshes/$1_$2.msh" "$out"
    else gmsh -3 -format msh22 -setnumber n "$2" "$meshes/$1.geo" -o "$out" > /dev/null
    fi
  fi
  echo "$out"
}

echo "| run | cells | dofs | solver | load steps | Newton | linear | wall (s) | CPU (s) | CPU per Newton (s) | memory (MB) | kB per dof |" > rows.md
echo "|---|---|---|---|---|---|---|---|---|---|---|---|" >> rows.md
run() { # run NAME PRM MESH SOLVER [SED]; SOLVER = MUMPS, KLU or AMG
  local name=$1 prm=$2 msh=$3 solver=$4 extra=${5:-}
  local linear=direct direct=$solver
  [ "$solver" = AMG ] && linear=AMG direct=MUMPS
  sed -e "s|set Mesh file *=.*|set Mesh file = $msh|" \
      -e "s|set Output directory *=.*|set Output directory = $name|" \
      -e "/set Linear solver *=/d" -e "/set Direct solver *=/d" \
      -e "s|^  subsection Quasi-static\$|  subsection Quasi-static\n    set Linear solver = $linear\n    set Direct solver = $direct|" \
      ${extra:+-e "$extra"} "$prm" > "$name.prm"
  rm -rf "$name"
  local launcher=()
  [ "$ranks" -gt 1 ] && launcher=(mpirun --oversubscribe -np "$ranks")
  local status=0
  ( ulimit -S -t "$limit"
    /usr/bin/time -f "%e %U %S %M" -o "$name.time" \
      timeout $((3 * limit)) "${launcher[@]}" "$build/rubberdyn" "$name.prm" ) > "$name.log" 2>&1 || status=$?
  local wall user sys memory cells dofs summary
  read -r wall user sys memory < <(tail -1 "$name.time")
  cells=$(grep -o "[0-9]* cells" "$name.log" | head -1 | cut -d' ' -f1 || true)
  dofs=$(grep -o "[0-9]* dofs" "$name.log" | head -1 | cut -d' ' -f1 || true)
  summary=$(grep "^Finished" "$name.log" || true)
  if [ $status -ne 0 ] || [ -z "$summary" ]; then
    local why="failed (exit $status)"
    [ $status -eq 124 ] || [ $status -eq 152 ] || grep -q "signal \(24\|9\)$" "$name.time" &&
      why="dropped: stopped after $limit s"
    echo "| $name | $cells | $dofs | $solver | $why | | | | | | | |" >> rows.md
    return 0
  fi
  echo "$summary" | awk -v n="$name" -v c="$cells" -v d="$dofs" -v s="$solver" \
    -v w="$wall" -v u="$user" -v y="$sys" -v m="$memory" -v r="$ranks" '{
    for (i = 1; i <= NF; ++i) {
      if ($(i + 1) == "load") steps = $i
      if ($(i + 1) == "Newton") newton = $i
      if ($(i + 1) == "linear") linear = $i
    }
    # (memory: the peak resident set of one process, times the ranks)
    printf "| %s | %d | %d | %s | %d | %d | %d | %.1f | %.1f | %.3f | %.0f | %.2f |\n",
      n, c, d, s, steps, newton, linear, w, u + y, (u + y) / newton, m * r / 1024, m * r / d
    printf "%s %d %s %s %d %d\n", n, d, w, u + y, newton, m * r > "/dev/stderr"
  }' >> rows.md 2>> times.txt
}

rm -f times.txt && touch times.txt
for n in 8 16 32; do
  for solver in MUMPS AMG KLU; do
    [ $solver = KLU ] && [ $n != 8 ] && continue
    run block_${n}_$solver "$source_dir/parameter_files/uniaxial_compression_quasi_static.prm" \
      "$(mesh compression_block $n)" $solver \
      "s|set Function expression = -6 \* t|set Function expression = -3 * t|"
  done
done
for n in 4 8 16; do
  for solver in MUMPS AMG KLU; do
    [ $solver = KLU ] && [ $n != 4 ] && continue
    run tube_${n}_$solver "$source_dir/parameter_files/tube_torsion.prm" \
      "$(mesh tube $n)" $solver
  done
done
{
  echo "# Quasi-static solver: cost against size ($ranks rank(s), $(date -u +%F), limit $limit s of CPU a run)"
  echo
  cat rows.md
  echo
  echo "Growth exponents, t ~ N^p (least squares over the sizes that finished), CPU time per Newton iteration, and the growth of the peak memory between the smallest and the largest size (the libraries alone take about 170 MB):"
  echo
  for model in block tube; do
    for solver in MUMPS AMG; do
      { grep "^${model}_[0-9]*_$solver " times.txt || true; } | awk -v m=$model -v s=$solver '{
        x = log($2); sx += x; sxx += x * x; ++n
        y = log($3); sy += y; sxy += x * y
        z = log($4); sz += z; sxz += x * z
        per = per sprintf("%s%.3g", n > 1 ? ", " : "", $4 / $5)
        if (n == 1) { d0 = $2; m0 = $6 } d1 = $2; m1 = $6 }
        END {
          if (n < 2) { printf "- %s, %s: fewer than two sizes\n", m, s; exit }
          d = n * sxx - sx * sx
          printf "- %s, %s (%d sizes): wall p = %.2f, CPU p = %.2f; CPU per Newton iteration %s s; memory growth %.1f kB per dof\n",
            m, s, n, (n * sxy - sx * sy) / d, (n * sxz - sx * sz) / d, per, (m1 - m0) / (d1 - d0) }'
    done
  done
} > scaling.md
cat scaling.md
