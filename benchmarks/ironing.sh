#!/usr/bin/env bash
# Ironing (Puso & Laursen 2004, example 2; Yang, Laursen & Meng 2005), the
# set-up of LLNL smith's die-on-slab driver (shared/references/
# contact-and-implicit.md, sect. (iii)), plane strain, quasi-static:
# parameter_files/ironing.prm presses a stiff curved die (R = 3) 1.4 into a
# neo-Hookean slab (E = 1, nu = 0.3) and slides it along +x, mu = 0.3,
# through a mortar Coulomb pair (slave: the die's hull);
# parameter_files/ironing_rigid_die.prm does the same with a rigid
# cylinder and node-to-surface contact, the comparison curve.
#
# Steady sliding: from a slide of 1.5 (t = 0.6875; every active slave node
# slips from a slide of 1.08 on) to the end of the load path (t = 1.3, a
# slide of 3.385: both variants stall at a slide of 3.585, where the
# contact nears the slab's free end x = 9; see the .prm's header). There
# the die's reaction ratio R = |press_force_x| / |press_force_z| is mu plus
# ploughing (the pressure on the die's leading flank, inclined against
# the slide; reference sect. (iii): "Fx/Fz -> mu + ploughing, so above
# 0.3") and drifts smoothly with the die's distance from the slab's ends
# (0.3185 to 0.3321). Checked, in every steady row of the mortar run:
#  - every active slave node slips and the pair's tangential / normal
#    force is mu to 1e-7 relative (measured 4.7e-9: the return mapping puts
#    each slipping node on the Coulomb cone; the CSV prints 9 digits);
#  - the die is in equilibrium: press_force + the pair's force on the die
#    (ironing_force, of the master side on the slave side) = 0 to 1e-7 of
#    |press_force_z| (measured: equal to the printed digits; Newton's
#    tolerance is 1e-8 of the reactions);
#  - mu < mean R < 1.15 mu: friction plus a positive, modest ploughing term
#    (measured 0.32870, mu + 9.6 %: ploughing adds 0.029; with mu = 0.35
#    in the pair R is 0.374 to 0.385 from a slide of 1.5 to 2.2, outside;
#    mu = 0.2 or a frictionless pair would need a ploughing of 0.1);
#  - smoothness: R less its least-squares cubic in the slide (the drift)
#    has max - min below 2 % of the mean R (the issue's bound on the
#    oscillation; measured 0.072 %). The raw max - min of R, drift
#    included, is printed: 4.13 %, above the issue's 2 %; it is the
#    smooth end effect of a 9 long slab under a die whose contact is 5
#    wide, not an oscillation (doc/figures/ironing_force_ratio.png);
#  - Newton: at most 10 iterations per step (measured 9, 5 to 7 while it
#    slides, no cut-back); second order checked once the relative residual is
#    below 1e-4 (the earlier iterations of a step change the contact's active
#    set and stick/slip states), with r_k <= 1e4 r_{k-1}^2 + 1e-9: measured
#    largest r_k / r_{k-1}^2 = 1.0e3 on 166 iterations (a wrong tangent
#    converges linearly: at a rate of 0.1, r_k / r_{k-1}^2 reaches 1e5 at the
#    residuals of 1e-6 the iterations pass); the floor 1e-9 is the residual's
#    round-off, 5e-11 kN against reactions of 0.1 kN, set by the die's stiff
#    elements (E = 1000).
# The node-to-surface run: the same statistics are printed (not bounded:
# it is the comparison curve; measured mean 0.32967, +0.30 % of the
# mortar's, raw max - min 4.13 %, about its cubic trend 0.14 %, twice the
# mortar's wobble; at most 9 Newton iterations, r_k / r_{k-1}^2 <= 7.2);
# checked only that it reaches the end of the load path and that its mean
# R is within 2 % of the mortar run's (the same physics and ploughing, a
# full rigid cylinder instead of the die's 5.2 wide plate).
# Run time (one core each on a 2-core machine shared with other jobs):
# mortar 290 to 520 s, node-to-surface 255 to 326 s.
# A verification run rather than a CI test: both runs take about 5 minutes
# each on one idle core (10-14 minutes under load), beyond the test suite's
# budget. It does not pass issue 8's ironing acceptance as worded (the
# die's reaction is mu plus ploughing, 9.6 % above mu, and drifts by 4.1 %
# with the die's distance from the slab's ends; doc/verification/contact.md, "Quasi-static: ironing").
# The longer slab (SLAB_LENGTH, e.g. 18; the default 9 is the reference's):
# both meshes are made with gmsh from meshes/ironing.geo and
# ironing_slab.geo with the same 0.1 elements (gmsh -setnumber L, nx) in
# the working directory, and the load path runs to its end, t = 1.5 (a
# slide of 4.0, the reference's); the die's leading edge then stops 8.9
# short of the slab's right end. Without that end the ratio does not
# drift back down: it rises towards its steady value as the ploughing
# builds up, by steps that shrink geometrically (measured on L = 18, every
# 0.154 of slide: +0.0018 at a slide of 1.6, +0.0006 at 2.7, +0.0002 at
# 3.9; 0.3296 at a slide of 1.6, 0.3396 at 3.9), so the steady phase is
# taken from a slide of 3.0 (t = 1.175) to 4.0, and there the raw
# max - min of the ratio, drift included, is bounded by the issue's 2 % of
# the mean as well. Newton: at most 12 iterations per step (the pressing
# step at t = 0.15 takes 11 on the longer slab).
# Usage (in an empty directory):
#   benchmarks/ironing.sh EXECUTABLE SOURCE_DIR [NPROC] [SLAB_LENGTH]
set -euo pipefail
exe=$1; source_dir=$2; nproc=${3:-1}; slab_length=${4:-9}
t_end=1.3; t_start=0.6875; raw_bound=1e9; newton_cap=10
if [ "$slab_length" != 9 ]; then
  t_end=1.5; t_start=1.175; raw_bound=0.02; newton_cap=12
  elements=$(awk -v L="$slab_length" 'BEGIN { printf "%d", L * 10 + 0.5 }')
  for geo in ironing ironing_slab; do
    # The shipped meshes' gmsh options (parameter_files/meshes/regenerate.sh).
    HOME=$(mktemp -d) gmsh "$source_dir/parameter_files/meshes/$geo.geo" -3 \
      -nopopup -v 1 -nt 1 -format msh22 -setnumber Mesh.Binary 0 \
      -setnumber Mesh.SaveAll 0 -setnumber Mesh.SaveParametric 0 \
      -setnumber L "$slab_length" -setnumber nx "$elements" -o "$PWD/$geo.msh"
  done
fi
# example_append MESH: the lines that put the longer slab's MESH and end
# time into a run_example.sh run (none for the reference's slab).
example_append() {
  if [ "$slab_length" != 9 ]; then
    printf 'subsection Mesh\n  set Mesh file = %s\nend\n' "$PWD/$1.msh"
    printf 'subsection Time integration\n  set Quasi-static end time = %s\nend\n' "$t_end"
  fi
}

# statistics CSV FX FZ: mean, raw (max - min) / mean and (max - min) / mean
# of the residual about a least-squares cubic in the slide, over the steady
# phase, of |FX| / |FZ|; exits 1 if the run did not reach t_end.
statistics() {
  awk -F, -v fx="$2" -v fz="$3" -v t_end="$t_end" -v t_start="$t_start" '
    BEGIN { n = 0 }
    NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
    { t_last = $1 }
    $1 >= t_start - 1e-9 {
      s[n] = 4 * ($1 - 0.2) / 1.3
      r[n] = ($c[fx] < 0 ? -$c[fx] : $c[fx]) / ($c[fz] < 0 ? -$c[fz] : $c[fz])
      sum += r[n]; ++n }
    END {
      if (n < 2 || t_last < t_end - 1e-9) { printf "the run ended at t = %s\n", t_last; exit 1 }
      mean = sum / n; lo = hi = r[0]
      for (k = 0; k < n; ++k) { if (r[k] < lo) lo = r[k]; if (r[k] > hi) hi = r[k] }
      # Normal equations of the cubic fit in x = slide - 2.44, by Gauss.
      for (k = 0; k < n; ++k) { x = s[k] - 2.44; p = 1
        for (i = 0; i < 7; ++i) { m[i] += p; if (i < 4) b[i] += p * r[k]; p *= x } }
      for (i = 0; i < 4; ++i) { for (j = 0; j < 4; ++j) a[i, j] = m[i + j]; a[i, 4] = b[i] }
      for (i = 0; i < 4; ++i) for (j = i + 1; j < 4; ++j) {
        f = a[j, i] / a[i, i]; for (q = i; q < 5; ++q) a[j, q] -= f * a[i, q] }
      for (i = 3; i >= 0; --i) { v = a[i, 4]
        for (j = i + 1; j < 4; ++j) v -= a[i, j] * coef[j]; coef[i] = v / a[i, i] }
      for (k = 0; k < n; ++k) { x = s[k] - 2.44
        e = r[k] - (coef[0] + x * (coef[1] + x * (coef[2] + x * coef[3])))
        if (k == 0 || e < elo) elo = e; if (k == 0 || e > ehi) ehi = e }
      printf "%d %.6f %.6f %.6f %.6f %.6f\n", n, mean, lo, hi, (hi - lo) / mean, (ehi - elo) / mean }' "$1"
}

SECONDS=0
EXAMPLE_APPEND=$(example_append ironing) \
  bash "$source_dir/tests/model/run_example.sh" "$exe" "$source_dir" \
  ironing 1 0 "$nproc" > log.txt
mortar_seconds=$SECONDS
stats=$(statistics ironing/time_history.csv press_force_x press_force_z) ||
  { echo "mortar: $stats"; exit 1; }
read -r n mean lo hi raw detrended <<< "$stats"
awk -v n="$n" -v mean="$mean" -v lo="$lo" -v hi="$hi" -v raw="$raw" -v d="$detrended" -v s="$mortar_seconds" -v raw_bound="$raw_bound" 'BEGIN {
  printf "mortar (%d s): %d steady rows, |Fx|/|Fz| mean %.5f (mu %+.2f %%), min %.5f, max %.5f, max - min %.2f %% of the mean, about its cubic trend %.3f %%\n", s, n, mean, 100 * (mean / 0.3 - 1), lo, hi, 100 * raw, 100 * d
  exit !(mean > 0.3 && mean < 1.15 * 0.3 && d < 0.02 && raw < raw_bound) }' || { echo "mortar: the die's reaction ratio fails"; exit 1; }
awk -F, -v t_start="$t_start" '
  function abs(x) { return x < 0 ? -x : x }
  NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
  $1 >= t_start - 1e-9 {
    N = $c["ironing_normal_force"]; T = $c["ironing_tangential_force"]
    active = $c["ironing_active_nodes"]; slipping = $c["ironing_slipping_nodes"]
    e = abs(T / N / 0.3 - 1); if (e > worst) worst = e
    if (e > 1e-7) { printf "t = %s: T / N = %.9f\n", $1, T / N; bad = 1 }
    if (slipping != active || active == 0) { printf "t = %s: %d of %d nodes slip\n", $1, slipping, active; bad = 1 }
    q = (abs($c["press_force_x"] + $c["ironing_force_x"]) + abs($c["press_force_z"] + $c["ironing_force_z"])) / abs($c["press_force_z"])
    if (q > qworst) qworst = q
    if (q > 1e-7) { printf "t = %s: the die is out of balance by %.3g\n", $1, q; bad = 1 }
  }
  END {
    printf "mortar pair: T / N = mu to %.2g relative, every active node slipping; die out of balance by %.2g of Fz\n", worst, qworst
    exit bad }' ironing/time_history.csv
bash "$source_dir/tests/model/check_newton_log.sh" log.txt 1e-4 1e4 "$newton_cap" 1e-9

SECONDS=0
EXAMPLE_APPEND=$(example_append ironing_slab) \
  bash "$source_dir/tests/model/run_example.sh" "$exe" "$source_dir" \
  ironing_rigid_die 1 0 "$nproc" > log_rigid.txt
stats=$(statistics ironing_rigid_die/time_history.csv die_force_x die_force_z) ||
  { echo "node-to-surface: $stats"; exit 1; }
read -r n2 mean2 lo2 hi2 raw2 detrended2 <<< "$stats"
awk -v n="$n2" -v mean="$mean2" -v lo="$lo2" -v hi="$hi2" -v raw="$raw2" -v d="$detrended2" -v s="$SECONDS" -v mortar="$mean" 'BEGIN {
  printf "node-to-surface (%d s): %d steady rows, |Fx|/|Fz| mean %.5f (mu %+.2f %%, mortar %+.2f %%), min %.5f, max %.5f, max - min %.2f %% of the mean, about its cubic trend %.3f %%\n", s, n, mean, 100 * (mean / 0.3 - 1), 100 * (mean / mortar - 1), lo, hi, 100 * raw, 100 * d
  exit !(mean > 0.98 * mortar && mean < 1.02 * mortar) }' || { echo "node-to-surface: mean ratio off the mortar run's by more than 2 %"; exit 1; }
