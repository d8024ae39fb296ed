#!/usr/bin/env bash
# Runs the drop test (reference study, chapter 4) in the peer code CalculiX
# (ccx 2.20, Debian package calculix-ccx) and in rubberdyn on the same mesh,
# and compares the two. See benchmarks/calculix/README.md.
#
#   benchmarks/calculix/run_calculix_drop_test.sh [REFINEMENT [BUILD_DIR [WORK_DIR]]]
#
#   REFINEMENT  global refinement of the cylinder (default 2 = 640 cells,
#               3 = 5120 cells)
#   BUILD_DIR   rubberdyn's CMake build directory (default ./build); the
#               targets export_drop_test_mesh and rubberdyn are built there
#   WORK_DIR    where everything is written (default
#               /tmp/calculix_drop_test_rREFINEMENT)
#
# Environment: END_TIME (ms, default 30) shortens both runs; ELEMENT (C3D8,
# the default, C3D8R or C3D8I) is CalculiX's element type (the output
# interval assumes C3D8's stable increment); SKIP_RUBBERDYN=1
# reuses WORK_DIR/rubberdyn, SKIP_CCX=1 reuses WORK_DIR/ccx (to redo the
# comparison only).
#
# Writes WORK_DIR/ccx/time_history.csv (time,impactor_displacement,
# impactor_force,... in ms, mm, kN, compression positive),
# WORK_DIR/rubberdyn{,_matched}/{time_history.csv,run_summary.json},
# WORK_DIR/comparison.md and WORK_DIR/drop_test_force.png.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
source_dir=$(cd "$here/../.." && pwd)
refinement=${1:-2}
build=$(realpath "${2:-build}")
work=${3:-/tmp/calculix_drop_test_r$refinement}
mkdir -p "$work/ccx" "$work/rubberdyn"
work=$(realpath "$work")

# Model constants shared by both codes (parameter_files/drop_test_cylinder.prm).
H=24          # cylinder height (mm)
D=25          # cylinder diameter (mm)
M=5           # impactor mass (kg)
g=9.81e-3     # gravity (mm/ms^2)
C10=0.00055; C20=-0.00005; C30=0.000015   # GPa
nu=0.499
penalty_scale=0.1                         # rubberdyn's default
end_time=${END_TIME:-30}                  # ms
element=${ELEMENT:-C3D8}

cmake --build "$build" --target export_drop_test_mesh rubberdyn -- -j1 \
  > "$work/build.log"

# ------------------------------------------------------------------ CalculiX
if [[ "${SKIP_CCX:-0}" != 1 ]]; then
  cd "$work/ccx"
  "$build/benchmarks/export_drop_test_mesh" "$refinement" drop_test_mesh.inp \
    "$element"
  echo "$element" > element_type.txt
  # rubberdyn's penalty: pressure slope s K / h with h the end layer's height
  # (24 mm / (2 * 2^r)), K = 2G(1+nu)/(3(1-2nu)), G = 2 C10.
  # Output every N increments, N ~ 0.05 ms / stable increment, the latter
  # 1.5065e-3 ms at refinement 2 and halving with each refinement.
  read -r slope every < <(awk -v r="$refinement" -v H="$H" -v C10="$C10" \
    -v nu="$nu" -v s="$penalty_scale" 'BEGIN {
      G = 2 * C10; K = 2 * G * (1 + nu) / (3 * (1 - 2 * nu));
      h = H / (2 * 2 ^ r); dt = 1.5065e-3 * 2 ^ (2 - r);
      n = int(0.05 / dt + 0.5); if (n < 1) n = 1;
      printf "%.7g %d\n", s * K / h, n }')
  awk -v slope="$slope" -v every="$every" -v T="$end_time" '
    prev ~ /driver: penalty slope/ { $0 = slope ", 1.e-9" }
    prev ~ /^\*DYNAMIC, EXPLICIT/ { $0 = "0.001, " T }
    prev ~ /driver: N = / { sub(/FREQUENCY=[0-9]+/, "FREQUENCY=" every) }
    { print; prev = $0 }' "$here/drop_test.inp" > drop_test.inp
  echo "CalculiX: refinement $refinement, penalty slope $slope GPa/mm," \
       "output every $every increments"
  start=$(date +%s.%N)
  /usr/bin/time -f "%U" -o cpu_seconds.txt ccx -i drop_test > ccx.log 2>&1 ||
    { tail -20 ccx.log; echo "ccx failed, see $work/ccx/ccx.log"; exit 1; }
  end=$(date +%s.%N)
  awk -v a="$start" -v b="$end" 'BEGIN { printf "%.2f\n", b - a }' \
    > wall_seconds.txt
  grep -q "Job finished" ccx.log || { echo "ccx did not finish"; exit 1; }

  # The impactor's displacement and velocity (reference node), the bottom
  # plate's reaction, and the rubber's end faces (for its height at maximum
  # compression) from drop_test.dat. ccx has no output of the node-to-face
  # contact force in explicit steps, so the impactor force is its momentum
  # balance, F = M (dv/dt + g), dv/dt the mean acceleration between two
  # outputs: the mean contact force over that interval, exact for a rigid
  # body. Columns: compression positive.
  awk -v M="$M" -v g="$g" 'BEGIN { t_prev = 0; v_prev = -2 }
    /displacements .* set IMPACTOR_REF/ { t = $NF; what = "u"; next }
    /velocities .* set IMPACTOR_REF/    { what = "v"; next }
    /displacements .* set TOP_NODES/    { what = "top"; ntop = 0; stop = 0; next }
    /displacements .* set BOTTOM_NODES/ { what = "bot"; nbot = 0; sbot = 0; next }
    /total force .* BOTTOM_PLATE_NODES/ { what = "rf"; next }
    NF == 0 { next }
    what == "u"   && NF == 4 { u = -$4; what = "" }
    what == "v"   && NF == 4 { v = $4; what = "" }
    what == "top" && NF == 4 { ++ntop; stop += $4 }
    what == "bot" && NF == 4 { ++nbot; sbot += $4 }
    what == "rf"  && NF == 3 {
      rf = $3; what = "";
      # The bottom reaction is printed last: one output is complete.
      F = M * ((v - v_prev) / (t - t_prev) + g);
      printf "%.7g,%.7g,%.7g,%.7g,%.7g,%.7g\n", t, u, F, rf, v,
             (stop / ntop - sbot / nbot);
      t_prev = t; v_prev = v }
    ' drop_test.dat > rows.csv
  {
    echo "time,impactor_displacement,impactor_force,bottom_plate_force,impactor_velocity,mean_end_face_approach"
    # The start: impactor at rest on the top face, no force.
    echo "0,0,0,0,-2,0"
    cat rows.csv
  } > time_history.csv
  rm rows.csv
fi

# ----------------------------------------------------------------- rubberdyn
# Two runs: rubberdyn as shipped (F-bar hexahedra, bulk viscosity), and the
# model nearest to CalculiX's (plain 2x2x2 displacement hexahedra as C3D8,
# no bulk viscosity, which ccx's explicit solver does not have).
run_rubberdyn() {
  local dir=$1; shift
  mkdir -p "$work/$dir" && cd "$work/$dir"
  sed -e "s|^\( *set Global refinement *=\).*|\1 $refinement|" \
      -e "s|^\( *set Output directory *=\).*|\1 $work/$dir|" \
      -e "s|^\( *set Field output interval *=\).*|\1 0|" \
      -e "s|^\( *set End time *=\).*|\1 $end_time|" \
      "$@" "$source_dir/parameter_files/drop_test_cylinder.prm" > drop_test.prm
  /usr/bin/time -f "%U" -o cpu_seconds.txt "$build/rubberdyn" drop_test.prm \
    > rubberdyn.log 2>&1 ||
    { tail -20 rubberdyn.log; echo "rubberdyn failed in $work/$dir"; exit 1; }
}
if [[ "${SKIP_RUBBERDYN:-0}" != 1 ]]; then
  run_rubberdyn rubberdyn
  run_rubberdyn rubberdyn_matched -e "s|^\( *set Element formulation *=\).*|\1 displacement\n  set Bulk viscosity linear = 0\n  set Bulk viscosity quadratic = 0|"
fi

# ---------------------------------------------------------------- comparison
cd "$work"
# Largest force and compression, their times, end of contact (first output
# after the largest force with a force at most 0.1 % of it), and the largest
# 1 ms moving average of the force (the same filter for both codes: the
# contact force rings at the rubber's wave periods, and CalculiX's force is
# a 0.05 ms mean while rubberdyn's is sampled), and the coefficient of
# restitution: the impactor's upward speed at the end of contact over the
# impact speed, from its free flight after it (mean speed between 0.5 ms
# after the end of contact and the end of the run, corrected for gravity).
stats() {
  awk -F, -v g="$g" -v V0=2 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
    { ++n; t[n] = $c["time"]; f[n] = $c["impactor_force"]
      d[n] = $c["impactor_displacement"]
      if (f[n] > fmax) { fmax = f[n]; k = n }
      if (d[n] > dmax) { dmax = d[n]; td = t[n] } }
    END { for (i = k + 1; i <= n && !te; ++i) if (f[i] <= 1e-3 * fmax) te = t[i]
          for (i = 1; i <= n; ++i) {
            s = 0; m = 0
            for (j = 1; j <= n; ++j)
              if (t[j] >= t[i] - 0.5 && t[j] <= t[i] + 0.5) { s += f[j]; ++m }
            if (s / m > fsmooth) { fsmooth = s / m; ts = t[i] } }
          e = "none"
          for (i = 1; i <= n && te; ++i) if (t[i] >= te + 0.5) break
          if (te && t[n] - t[i] > 1) {
            w = -(d[n] - d[i]) / (t[n] - t[i]) + g * ((t[i] + t[n]) / 2 - te)
            e = sprintf("%.3f", w / V0) }
          printf "%.4f %.3f %.4f %.2f %.3f %.3f %s %s\n", fmax, t[k], fsmooth,
                 ts, dmax, td, (te ? sprintf("%.2f", te) : "none"), e }' "$1"
}
# Eq. 4.8 of the reference study at a stretch lambda: F = A 2 (l - l^-2)
# (C10 + 2 C20 (I1 - 3) + 3 C30 (I1 - 3)^2), A the original cross-section.
eq48() {
  awk -v l="$1" -v D="$D" -v C10="$C10" -v C20="$C20" -v C30="$C30" 'BEGIN {
    I1 = l * l + 2 / l; x = I1 - 3; A = 3.14159265358979 * D * D / 4;
    printf "%.4f\n", -A * 2 * (l - 1 / (l * l)) * (C10 + 2 * C20 * x + 3 * C30 * x * x) }'
}
# One column of the table: statistics, stretch and force at the largest
# compression, eq. 4.8 there, steps, time step, wall and CPU seconds.
# CalculiX: the stretch from the mean approach of the rubber's end faces (its
# penetration into the plates excluded); rubberdyn: from the impactor
# position corrected by the penalty energy (doc/scripts/drop_test_eq48.sh).
column() {
  local dir=$1 l f48 steps dt wall
  read -r fmax tf fs ts dmax td te e < <(stats "$dir/time_history.csv")
  if [[ $dir == ccx ]]; then
    l=$(awk -F, -v H="$H" 'NR > 1 && $2 > d { d = $2; a = $6 } END { printf "%.4f", 1 + a / H }' ccx/time_history.csv)
    f48=$(awk -F, 'NR > 1 && $2 > d { d = $2; f = $3 } END { printf "%.4f", f }' ccx/time_history.csv)
    # ccx keeps its initial stable increment here (equally spaced output)
    # and reports no increment count for explicit steps.
    dt=$(awk -F: '/initial stable time increment/ { print $NF + 0 }' ccx/ccx.log)
    steps=$(awk -v T="$end_time" -v dt="$dt" 'BEGIN { n = T / dt; print (n == int(n) ? n : int(n) + 1) }')
    dt=$(awk -v dt="$dt" 'BEGIN { printf "%.4g", dt }')
    wall=$(cat ccx/wall_seconds.txt)
  else
    local eq
    eq=$("$source_dir/doc/scripts/drop_test_eq48.sh" "$dir")
    l=$(echo "$eq" | sed -n 's/.*stretch \([0-9.]*\).*/\1/p')
    f48=$(echo "$eq" | sed -n 's/^FE force \([0-9.]*\) kN.*/\1/p')
    dt=$(awk -F, 'NR == 2 { printf "%.4g", $2 }' "$dir/time_history.csv")
    steps=$(awk -F'[:,]' '/time_steps/ { print $2 + 0 }' "$dir/run_summary.json")
    wall=$(awk -F'[:,]' '/wall_seconds/ { printf "%.2f", $2 }' "$dir/run_summary.json")
  fi
  echo "$fmax $tf $fs $ts $dmax $td $te $e $l $f48 $(eq48 "$l") $steps $dt $wall $(cat "$dir/cpu_seconds.txt")"
}
read -r -a c < <(column ccx)
read -r -a r < <(column rubberdyn)
read -r -a m < <(column rubberdyn_matched)
cells=$(awk -F'[:,]' '/"cells"/ { print $2 + 0 }' rubberdyn/run_summary.json)
labels=("largest impactor force (kN)" "time of largest force (ms)"
        "largest 1 ms mean force (kN)" "its time (ms)"
        "largest compression (mm)" "time of largest compression (ms)"
        "end of contact (ms)" "coefficient of restitution"
        "stretch at largest compression"
        "force at largest compression (kN)" "eq. 4.8 at that stretch (kN)"
        "time steps" "first time step (ms)" "wall time (s)" "CPU time (s)")
{
  echo "Drop test to $end_time ms, refinement $refinement ($cells cells):" \
       "CalculiX $(ccx -v 2>/dev/null | awk '/Version/ { print $NF }')," \
       "rubberdyn (F-bar, bulk viscosity) and rubberdyn matched to ccx" \
       "(plain 2x2x2 hexahedra, no bulk viscosity)"
  echo
  echo "| quantity | CalculiX $(cat ccx/element_type.txt) | rubberdyn F-bar | rubberdyn matched |"
  echo "|---|---|---|---|"
  for i in "${!labels[@]}"; do
    echo "| ${labels[$i]} | ${c[$i]} | ${r[$i]} | ${m[$i]} |"
  done
} | tee comparison.md

if command -v gnuplot > /dev/null; then
  gnuplot <<EOF
set terminal pngcairo size 900,560 noenhanced
set output "$work/drop_test_force.png"
set datafile separator ","
set key top right
set xlabel "time (ms)"
set ylabel "impactor force (kN)"
set y2label "impactor displacement (mm)"
set y2tics
set ytics nomirror
set grid
set title "Drop test, 5 kg at 2 m/s on the rubber cylinder, $cells cells"
plot "$work/rubberdyn/time_history.csv" every ::1 using 1:11 with lines lw 2 lc rgb "#1f4e9c" title "rubberdyn force (F-bar)", \
     "$work/rubberdyn_matched/time_history.csv" every ::1 using 1:11 with lines lw 1 lc rgb "#2ca02c" title "rubberdyn force (plain hex, no bulk viscosity)", \
     "$work/ccx/time_history.csv" every ::1 using 1:3 with lines lw 2 lc rgb "#d62728" title "CalculiX force ($(cat "$work/ccx/element_type.txt"))", \
     "$work/rubberdyn/time_history.csv" every ::1 using 1:10 axes x1y2 with lines dt 2 lc rgb "#1f4e9c" title "rubberdyn displacement", \
     "$work/ccx/time_history.csv" every ::1 using 1:2 axes x1y2 with lines dt 2 lc rgb "#d62728" title "CalculiX displacement"
EOF
  echo "Plot: $work/drop_test_force.png"
fi
