#!/usr/bin/env bash
# Figures 4.4-4.6 of the drop-test study and the energy fit of G, from the
# CSV files that doc/scripts/drop_test_matrix.sh writes:
#   doc/scripts/drop_test_plots.sh [FIGURES_DIR]   (default doc/figures)
# Reads drop_test_matrix.csv and drop_test_fig44.csv; writes
# drop_test_energy_fit.csv and drop_test_fig44/45/46.png. Material constants
# as drop_test_case_summary.sh (environment C10, C20, C30 in MPa).
#
# Energy fit (reference study Fig. 4.6, eqs. 4.10-4.15): the energy density e
# of each case against w(lambda) = (lambda^2 + 2/lambda - 3)/2 (the
# incompressible neo-Hookean uniaxial energy W = G w), least squares through
# the origin, G = sum(e w) / sum(w^2), for
#   e        = (M V0^2/2 + M g d) / (A H)       potential term M g (H - h_max)
#   e_thesis = (M V0^2/2 + M g h_max) / (A H)   the thesis's term
#   W_yeoh(lambda)                              the material itself
#   U_FE / (A H)                                the FE rubber's strain energy
# and also a straight line with intercept, and the mean, smallest and largest
# of the per-case ratios e / w (secant moduli), which weigh the low-energy
# cases as much as the high-energy ones.
set -euo pipefail
repo=$(cd "$(dirname "$0")/../.." && pwd)
fig=${1:-$repo/doc/figures}
C10=${C10:-0.55}; C20=${C20:--0.05}; C30=${C30:-0.015}

awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
{ w = $c["w_neo_hooke"]; n++; sw += w; sww += w * w;
  y[1] = $c["energy_density_MPa"]; y[2] = $c["energy_density_thesis_MPa"];
  y[3] = $c["yeoh_energy_density_MPa"];
  y[4] = 1000 * $c["fe_internal_energy_J"] / ($c["mesh_area_mm2"] * 24);
  for (k = 1; k <= 4; ++k) { swy[k] += w * y[k]; sy[k] += y[k];
    s = y[k] / w; sr[k] += s;
    if (n == 1 || s < lo[k]) lo[k] = s; if (n == 1 || s > hi[k]) hi[k] = s } }
END {
  name[1] = "energy_density"; name[2] = "energy_density_thesis";
  name[3] = "yeoh_energy_density"; name[4] = "fe_strain_energy_density";
  what[1] = "(M V0^2/2 + M g (H - h_max))/(A H): right potential term";
  what[2] = "(M V0^2/2 + M g h_max)/(A H): the thesis term";
  what[3] = "exact uniaxial Yeoh W(lambda) at the cases stretches";
  what[4] = "FE internal energy of the rubber / (A H)";
  print "quantity,G_through_origin_MPa,G_with_intercept_MPa,intercept_MPa,mean_ratio_to_w_MPa,min_ratio_to_w_MPa,max_ratio_to_w_MPa,cases,description";
  for (k = 1; k <= 4; ++k) {
    b = (n * swy[k] - sw * sy[k]) / (n * sww - sw * sw); a = (sy[k] - b * sw) / n;
    printf "%s,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%d,%s\n", name[k], swy[k] / sww, b, a, sr[k] / n, lo[k], hi[k], n, what[k] } }' \
  "$fig/drop_test_matrix.csv" > "$fig/drop_test_energy_fit.csv"

G() { awk -F, -v q="$1" -v col="${2:-2}" '$1 == q { print $col }' "$fig/drop_test_energy_fit.csv"; }
first() { awk -F, -v q="$1" 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i }
                             NR == 2 { print $c[q] }' "$fig/drop_test_matrix.csv"; }
cells=$(first cells); area=$(first mesh_area_mm2)

gnuplot <<GP
set terminal pngcairo size 800,560 font "Sans,11" noenhanced
set datafile separator ","
set key autotitle columnhead
C10 = $C10; C20 = $C20; C30 = $C30
xi(l) = l*l + 2/l - 3
w(l) = xi(l)/2
Wy(l) = C10*xi(l) + C20*xi(l)**2 + C30*xi(l)**3
P(l) = -2*(l - 1/l**2)*(C10 + 2*C20*xi(l) + 3*C30*xi(l)**2)/1000
A = $area; An = pi*25**2/4
m = "$fig/drop_test_matrix.csv"

set output "$fig/drop_test_fig44.png"
set title "Fig. 4.4: M = 5 kg, V0 = 2 m/s ($cells cells)"
set xlabel "time (ms)"
set ylabel "impactor force (kN)"
set y2label "displacement, compression positive (mm)"
set ytics nomirror; set y2tics
set key below
set y2range [-4:16]
plot "$fig/drop_test_fig44.csv" using 1:4 with lines lw 2 lc 1 title "impactor force", \
     "" using 1:2 axes x1y2 with lines lw 2 lc 2 title "impactor displacement", \
     "" using 1:3 axes x1y2 with lines lw 2 dt 2 lc 3 title "rubber compression (top - bottom face)"
unset y2label; unset y2tics; set ytics mirror; set autoscale y2; set key default

set terminal pngcairo size 1280,560 font "Sans,11" noenhanced
set output "$fig/drop_test_fig45.png"
set multiplot layout 1,2 title "Fig. 4.5: force at maximum compression, FE ($cells cells) against eq. 4.8"
set title "force"
set xlabel "stretch lambda = h_max / H (-)"
set ylabel "force (kN)"
set key top right
set xrange [0.4:1]
set yrange [0:*]
v(V) = (column("impact_velocity_mm_per_ms") == V ? column("stretch") : 1/0)
plot sample [l=0.4:1] '+' using (l):(P(l)*A) with lines lw 2 lc 1 title sprintf("eq. 4.8, mesh area %.1f mm^2", A), \
     [l=0.4:1] '+' using (l):(P(l)*An) with lines lw 1 dt 2 lc 1 title sprintf("eq. 4.8, nominal area %.1f mm^2", An), \
     m using (v(0.5)):"fe_force_kN" with points pt 7 ps 1.3 lc 2 title "FE, V0 = 0.5 m/s", \
     m using (v(1)):"fe_force_kN" with points pt 5 ps 1.3 lc 3 title "FE, V0 = 1 m/s", \
     m using (v(1.5)):"fe_force_kN" with points pt 9 ps 1.5 lc 4 title "FE, V0 = 1.5 m/s", \
     m using (v(2)):"fe_force_kN" with points pt 13 ps 1.5 lc 7 title "FE, V0 = 2 m/s"
set title "FE / eq. 4.8 - 1"
set ylabel "relative difference (%)"
set yrange [-6:3]
set key bottom right
plot m using "stretch":(100*column("fe_vs_eq48_mesh_area")) with points pt 7 ps 1.3 lc 1 title "eq. 4.8 with the mesh area", \
     m using "stretch":(100*column("fe_vs_eq48_nominal_area")) with points pt 6 ps 1.3 lc 7 title "eq. 4.8 with the nominal area pi D^2/4", \
     0 with lines lc 0 dt 3 notitle
unset multiplot
set autoscale x; set autoscale y

set terminal pngcairo size 1280,560 font "Sans,11" noenhanced
set output "$fig/drop_test_fig46.png"
set multiplot layout 1,2 title "Fig. 4.6: energy at maximum compression against w(lambda) = (lambda^2 + 2/lambda - 3)/2, W = G w ($cells cells)"
Gr = $(G energy_density); Gt = $(G energy_density_thesis); Gy = $(G yeoh_energy_density)
set title "energy density e = (M V0^2/2 + potential term)/(A H)"
set xlabel "w(lambda) (-)"
set ylabel "energy density (MPa = mJ/mm^3)"
set key top left Left reverse
set xrange [0:1]
set yrange [0:*]
plot m using "w_neo_hooke":"energy_density_thesis_MPa" with points pt 6 ps 1.3 lc 7 title "M g h_max (the thesis)", \
     x*Gt with lines lw 1 dt 2 lc 7 title sprintf("fit through 0: G = %.3f MPa", Gt), \
     m using "w_neo_hooke":"energy_density_MPa" with points pt 7 ps 1.3 lc 1 title "M g (H - h_max) (right)", \
     x*Gr with lines lw 1 lc 1 title sprintf("fit through 0: G = %.3f MPa", Gr), \
     [l=0.4:1] '+' using (w(l)):(Wy(l)) with lines lw 2 lc 2 title sprintf("Yeoh W(lambda), exact (fit at the cases: %.3f MPa)", Gy), \
     x*1.1 with lines lw 1 dt 3 lc 0 title "G = 2 C10 = 1.1 MPa"
set key default
set title "secant modulus e / w of each case"
set ylabel "e / w (MPa)"
set key top right
set yrange [0.9:2.8]
plot m using "w_neo_hooke":(column("energy_density_thesis_MPa")/column("w_neo_hooke")) with points pt 6 ps 1.3 lc 7 title "M g h_max (the thesis)", \
     m using "w_neo_hooke":(column("energy_density_MPa")/column("w_neo_hooke")) with points pt 7 ps 1.3 lc 1 title "M g (H - h_max) (right)", \
     m using "w_neo_hooke":(column("yeoh_energy_density_MPa")/column("w_neo_hooke")) with points pt 4 ps 1.3 lc 2 title "Yeoh W / w at the cases", \
     2*C10 + 4*C20*x + 8*C30*x**2 with lines lw 2 lc 2 title "Yeoh: W / w = 2 C10 + 4 C20 w + 8 C30 w^2", \
     1.1 with lines lw 1 dt 3 lc 0 title "2 C10 = 1.1 MPa"
unset multiplot
GP
cat "$fig/drop_test_energy_fit.csv"
