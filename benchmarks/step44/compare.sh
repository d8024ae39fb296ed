#!/usr/bin/env bash
# deal.II's tutorial step-44 (three-field Q2-DGP1-DGP1 u-p-J element,
# nearly incompressible neo-Hooke, Newton) on its default problem next to
# rubberdyn on the same problem: dofs, Newton iterations (of the converged
# load steps, and of all attempts with the cut-back ones), wall and CPU
# (user + sys) time, peak memory, and the vertical displacement of the top
# centre (0, 1, 0) after each load step.
#   benchmarks/step44/compare.sh [BUILD_DIR] [WORK_DIR]
# - step-44: copied from the Debian package libdeal.ii-doc
#   (/usr/share/doc/libdeal.ii-doc/examples/step-44) into WORK_DIR/step-44,
#   patched only to print u_y of the top centre after each step, built
#   (Release) and run on its parameters.prm (Global refinement 2: 4^3
#   cells; degree 2; 10 load steps; Use static condensation = false, CG +
#   SSOR on the Schur complement), and once more with Use static
#   condensation = true (the condensed u system, CG + SSOR);
# - rubberdyn, mixed u-p (Q2-P1-P1 condensed per cell, direct solver
#   MUMPS) on the same 4^3 cells: the driver step44_mixed (target
#   step44_mixed of BUILD_DIR; the Model study refuses tractions with
#   the mixed element);
# - rubberdyn, F-bar, the Model study with step44.prm on 8^3 cells (the
#   nodes of step-44's Q2 mesh), and the driver with F-bar on the same
#   mesh as a check of the driver's load.
# One thread per process (DEAL_II_NUM_THREADS=1 for step-44's WorkStream,
# OMP_NUM_THREADS=1), one process at a time. Needs gmsh, cmake, python3.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source_dir=$(cd "$here/../.." && pwd)
build=$(cd "${1:-$source_dir/build}" && pwd)
work=${2:-/tmp/step44_compare}
examples=${STEP44_DIR:-/usr/share/doc/libdeal.ii-doc/examples/step-44}
mkdir -p "$work" && cd "$work"
export OMP_NUM_THREADS=1 DEAL_II_NUM_THREADS=1
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
timed() { # timed NAME COMMAND...: NAME.log, NAME.time (wall user sys KB)
  local name=$1; shift
  /usr/bin/time -f "%e %U %S %M" -o "$name.time" "$@" > "$name.log" 2>&1
}

# step-44, with one print added after `solution_n += solution_delta;`.
if [ ! -x step-44/step-44 ]; then
  rm -rf step-44 && cp -r "$examples" step-44
  python3 - step-44/step-44.cc <<'PY'
import sys
p = sys.argv[1]
s = open(p).read()
old = "        solution_n += solution_delta;\n"
new = old + """        {
          Point<dim> top_centre;
          top_centre[1] = parameters.scale;
          bool printed = false;
          for (const auto &cell : dof_handler.active_cell_iterators())
            for (const unsigned int v : cell->vertex_indices())
              if (!printed &&
                  cell->vertex(v).distance(top_centre) < 1e-9 * parameters.scale)
                {
                  std::cout << "Top centre u_y at t = " << time.current()
                            << ": " << std::setprecision(8)
                            << solution_n(cell->vertex_dof_index(v, 1))
                            << " m" << std::endl;
                  printed = true;
                }
        }
"""
assert s.count(old) == 1
open(p, "w").write(s.replace(old, new))
PY
  (cd step-44 && cmake -DCMAKE_BUILD_TYPE=Release . > cmake.log 2>&1 && make > make.log 2>&1)
fi
(cd step-44 && timed ../step44_default ./step-44)
sed "s|set Use static condensation = false|set Use static condensation = true|" \
  step-44/parameters.prm > step-44/condensed.prm
(cd step-44 && cp parameters.prm default.prm && cp condensed.prm parameters.prm &&
 timed ../step44_condensed ./step-44; cp default.prm parameters.prm)

# rubberdyn
for n in 4 8; do
  [ -f step44_cube_$n.msh ] ||
    gmsh -3 -format msh22 -setnumber n $n "$here/step44_cube.geo" -o step44_cube_$n.msh > /dev/null
done
make -C "$build" step44_mixed rubberdyn > make_rubberdyn.log
STEP44_LOG=1 timed mixed_4 "$build/benchmarks/step44_mixed" step44_cube_4.msh mixed
STEP44_LOG=1 timed fbar_driver_8 "$build/benchmarks/step44_mixed" step44_cube_8.msh F-bar
sed -e "s|set Mesh file *=.*|set Mesh file = $work/step44_cube_8.msh|" \
    -e "s|set Output directory *=.*|set Output directory = $work/step44_fbar|" \
    "$here/step44.prm" > step44_fbar.prm
timed fbar_8 "$build/rubberdyn" step44_fbar.prm

# The table.
row() { # row LABEL ELEMENT CELLS DOFS STEPS NEWTON LINEAR UY TIMEFILE
  local w u s m
  read -r w u s m < <(tail -1 "$9")
  printf "| %s | %s | %s | %s | %s | %s | %s | %s | %.2f | %.2f | %.0f |\n" \
    "$1" "$2" "$3" "$4" "$5" "$6" "$7" "$8" "$w" "$(echo "$u + $s" | bc)" "$(echo "$m / 1024" | bc)"
}
step44_row() { # step44_row LABEL NAME
  local log=$2.log
  local dofs newton steps uy
  dofs=$(grep -o "Number of degrees of freedom: [0-9]*" "$log" | grep -o "[0-9]*$")
  newton=$(grep -c "SLV" "$log")
  steps=$(grep -c "^Top centre" "$log")
  uy=$(grep "^Top centre" "$log" | tail -1 | awk '{ printf "%.5f", $(NF - 1) * 1000 }')
  row "$1" "Q2-DGP1-DGP1" 64 "$dofs" \
    "$steps" "$newton ($newton)" "$(grep "SLV" "$log" | awk -F'|' '{ s += $2 } END { print s }') (CG)" "$uy" "$2.time"
}
rubberdyn_row() { # rubberdyn_row LABEL NAME ELEMENT: from the driver's summary
  local log=$2.log
  local head cells dofs summary steps newton linear uy
  head=$(head -1 "$log")
  cells=$(echo "$head" | grep -o "[0-9]* cells" | cut -d' ' -f1)
  dofs=$(echo "$head" | grep -o "[0-9]* dofs" | cut -d' ' -f1)
  summary=$(grep "^Finished" "$log")
  steps=$(echo "$summary" | awk '{ print $2 }')
  newton=$(echo "$summary" | awk '{ print $5 }')
  linear=$(echo "$summary" | awk '{ print $8 }')
  uy=$(echo "$summary" | awk '{ printf "%.5f", $(NF - 1) }')
  row "$1" "$3" "$cells" "$dofs" "$steps" "$newton ($(grep -c "^ *iteration [0-9]*:" "$log"))" "$linear" "$uy" "$2.time"
}
{
  echo "# step-44 next to rubberdyn ($(date -u +%F))"
  echo
  echo "| run | element | cells | dofs | load steps | Newton (all attempts) | linear | top centre u_y (mm) | wall (s) | CPU (s) | memory (MB) |"
  echo "|---|---|---|---|---|---|---|---|---|---|---|"
  step44_row "step-44, default (Schur complement, CG + SSOR)" step44_default
  step44_row "step-44, static condensation (CG + SSOR)" step44_condensed
  rubberdyn_row "rubberdyn mixed u-p (driver, MUMPS)" mixed_4 "Q2-P1-P1"
  rubberdyn_row "rubberdyn F-bar (driver, MUMPS)" fbar_driver_8 "Q1 F-bar"
  read -r cells dofs < <(grep -o "[0-9]* cells, [0-9]* dofs" fbar_8.log | head -1 | awk '{ print $1, $3 }')
  summary=$(grep "^Finished" fbar_8.log)
  uy=$(python3 -c "
import csv
rows = list(csv.DictReader(open('$work/step44_fbar/time_history.csv')))
print('%.5f' % float(rows[-1]['top_centre_displacement_y']))")
  row "rubberdyn F-bar (Model study, step44.prm)" "Q1 F-bar" "$cells" "$dofs" \
    "$(echo "$summary" | grep -o "[0-9]* load steps" | cut -d' ' -f1)" \
    "$(echo "$summary" | grep -o "[0-9]* Newton" | cut -d' ' -f1) ($(grep -c "^ *iteration [0-9]*:" fbar_8.log))" \
    "$(echo "$summary" | grep -o "[0-9]* linear" | cut -d' ' -f1)" "$uy" fbar_8.time
  echo
  echo "u_y of the top centre (mm) at t = 0.1, 0.2, ..., 1 (rubberdyn's cut-back steps in between left out):"
  echo
  python3 - "$work" <<'PY'
import csv, re, sys
w = sys.argv[1]
def step44(name):
    out = {}
    for line in open(f"{w}/{name}.log"):
        m = re.match(r"Top centre u_y at t = (\S+): (\S+) m", line)
        if m:
            out[round(float(m.group(1)), 6)] = 1000. * float(m.group(2))
    return out
def driver(name):
    out = {}
    for line in open(f"{w}/{name}.log"):
        m = re.match(r"t = (\S+) .* top centre u_y (\S+) mm", line)
        if m:
            out[round(float(m.group(1)), 6)] = float(m.group(2))
    return out
model = {round(float(r["time"]), 6): float(r["top_centre_displacement_y"])
         for r in csv.DictReader(open(f"{w}/step44_fbar/time_history.csv"))}
columns = [step44("step44_default"), step44("step44_condensed"),
           driver("mixed_4"), driver("fbar_driver_8"), model]
print("| t | step-44 | step-44 condensed | rubberdyn mixed u-p | F-bar (driver) | F-bar (Model study) |")
print("|---|---|---|---|---|---|")
for k in range(1, 11):
    t = round(0.1 * k, 6)
    print(f"| {t:g} | " + " | ".join(
        f"{c[t]:.5f}" if t in c else "–" for c in columns) + " |")
PY
} > comparison.md
cat comparison.md
