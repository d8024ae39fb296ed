#!/usr/bin/env bash
# Where the three volumetric functions of the Yeoh law differ, by the
# quasi-static solver (issue 9: "show on the uniaxial block where they
# differ"): the block of parameter_files/uniaxial_compression_quasi_static
# .prm confined laterally (its free sides, id 5, held in x and y: uniaxial
# strain) and pressed to 30 % (the top's u_z = -3 t mm), so that J = lambda
# = 1 - 0.3 t. The deformation is homogeneous and its Cauchy stress has a
# closed form for each U(J):
#   sigma_zz = U'(J) + (2 / J) W1(I1bar) (J^(4/3) - I1bar / 3),
#   I1bar = J^(-2/3) (J^2 + 2), W1 = C10 + 2 C20 (I1bar - 3)
#   + 3 C30 (I1bar - 3)^2,
# with U'(J) = K (J - 1) (polynomial, D2 = D3 = 0), K ln(J) / J (log
# squared) and (K / 2)(J - 1 / J) (Simo-Taylor), K = 1.1 GPa (K/G = 1000);
# the top's reaction is F = 100 mm^2 sigma_zz (the lateral stretches are 1).
# Requirements, at every load step and for each function:
# - press_force_z equals the closed form to 1e-7 relative (a homogeneous
#   state: the solver must reproduce it to its Newton tolerance and the
#   printed digits);
# - at J = 0.7 the three reactions differ by more than 10 % from each other
#   (measured: -33.1, -40.1, -56.1 kN): the choice matters in confined
#   compression; at small volume change all three have the same K and
#   differ only at second order: within 2.5 % of each other at J = 0.985
#   (measured at most 2.3 %), a difference that grows as 1.5 (1 - J).
# Usage: volumetric_functions_quasi_static.sh EXECUTABLE SOURCE_DIR NPROC
set -euo pipefail
exe=$1; source_dir=$2; nproc=$3
example=$source_dir/parameter_files/uniaxial_compression_quasi_static.prm
results=""
for function in polynomial "log squared" Simo-Taylor; do
  name=${function// /_}
  sed -e "s|set Mesh file *= *meshes/|set Mesh file = $source_dir/parameter_files/meshes/|" \
      -e "s|set Output directory *=.*|set Output directory = $name|" \
      -e "s|set Function expression = -6 \* t|set Function expression = -3 * t|" \
      -e "s|set Names = symmetry_x, symmetry_y, symmetry_z, press|set Names = symmetry_x, symmetry_y, symmetry_z, press, sides\n  subsection sides\n    set Boundary ids = 5\n    set Type = fixed\n    set Components = x, y\n  end|" \
      -e "s|set Density             = 1.1e-6|set Density = 1.1e-6\n    set Volumetric function = $function|" \
      "$example" > "$name.prm"
  rm -rf "$name"
  if [ "$nproc" -gt 1 ]; then
    mpirun --oversubscribe -np "$nproc" "$exe" "$name.prm" > "$name.log"
  else
    "$exe" "$name.prm" > "$name.log"
  fi
  final=$(awk -F, -v f="$function" '
    NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
    {
      K = 1.1; C10 = 0.55e-3; C20 = -0.05e-3; C30 = 0.015e-3
      J = 1 - 0.3 * $c["time"]; I = J^(-2 / 3) * (J^2 + 2) - 3
      W1 = C10 + 2 * C20 * I + 3 * C30 * I^2
      if (f == "polynomial") dU = K * (J - 1)
      else if (f == "log squared") dU = K * log(J) / J
      else dU = K / 2 * (J - 1 / J)
      F = 100 * (dU + 2 / J * W1 * (J^(4 / 3) - (I + 3) / 3))
      g = $c["press_force_z"]
      e = (F == 0 ? g : g / F - 1); if (e < 0) e = -e; if (e > worst) worst = e
      if ($c["time"] > 0.049 && $c["time"] < 0.051) early = g
      last = g; rows++
    }
    END {
      printf "%s: worst relative deviation from the closed form %.2e over %d rows\n", f, worst, rows > "/dev/stderr"
      if (worst > 1e-7 || rows != 21) exit 1
      printf "%.9g %.9g\n", early, last
    }' "$name/time_history.csv")
  echo "$function: F(J = 0.985) = ${final% *} kN, F(J = 0.7) = ${final#* } kN"
  results="$results ${final#* } ${final% *}"
done
awk -v r="$results" 'BEGIN {
  split(r, v, " ")   # last, early for each function
  for (i = 1; i <= 3; ++i) for (j = i + 1; j <= 3; ++j) {
    d = v[2 * i - 1] / v[2 * j - 1] - 1; if (d < 0) d = -d
    e = v[2 * i] / v[2 * j] - 1; if (e < 0) e = -e
    printf "functions %d and %d: %.1f %% apart at J = 0.7, %.2f %% at J = 0.985\n", i, j, 100 * d, 100 * e
    if (d < 0.10) bad = 1
    if (e > 0.025) bad = 1
  }
  exit bad }'
