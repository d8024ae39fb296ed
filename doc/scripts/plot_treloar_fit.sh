#!/usr/bin/env bash
# Regenerates doc/figures/treloar_yeoh_fit.{csv,png}: the Yeoh fit to
# Treloar's data (needs a built rubberdyn in build/ and gnuplot).
set -euo pipefail
cd "$(dirname "$0")/../.."
build/rubberdyn --fit-yeoh uniaxial=data/treloar/uniaxial.csv \
  equibiaxial=data/treloar/equibiaxial.csv pure_shear=data/treloar/pure_shear.csv \
  --curves doc/figures/treloar_yeoh_fit.csv
gnuplot <<'GP'
set terminal pngcairo size 800,560 font "Sans,11"
set output "doc/figures/treloar_yeoh_fit.png"
set datafile separator ","
set key top left
set xlabel "stretch (-)"
set ylabel "nominal stress (MPa)"
set title "Yeoh fit to Treloar (1944), all three modes at once"
f = "doc/figures/treloar_yeoh_fit.csv"
plot f using ($2):(strcol(1) eq "uniaxial" ? $3 : 1/0) with points pt 7 lc 1 title "uniaxial, measured", \
     f using ($2):(strcol(1) eq "uniaxial" ? $4 : 1/0) with lines lc 1 title "uniaxial, Yeoh", \
     f using ($2):(strcol(1) eq "equibiaxial" ? $3 : 1/0) with points pt 5 lc 2 title "equibiaxial, measured", \
     f using ($2):(strcol(1) eq "equibiaxial" ? $4 : 1/0) with lines lc 2 title "equibiaxial, Yeoh", \
     f using ($2):(strcol(1) eq "pure_shear" ? $3 : 1/0) with points pt 9 lc 3 title "pure shear, measured", \
     f using ($2):(strcol(1) eq "pure_shear" ? $4 : 1/0) with lines lc 3 title "pure shear, Yeoh"
GP
