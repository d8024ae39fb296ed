#!/usr/bin/env bash
# Quasi-static uniaxial compression of a Yeoh block to 60 %
# (parameter_files/uniaxial_compression_quasi_static.prm): an octant on
# three symmetry planes, the top displaced by -6 t mm (height 10 mm, so
# lambda = 1 - 0.6 t), the outer sides free, K/G = 1000, F-bar.
# Checked at every converged load step (20 steps of 0.05):
# - the top's reaction press_force_z against the reference study's eq. 4.8
#   (/work/shared/seed-notes.md, incompressible Yeoh), F = A0 2 (lambda -
#   lambda^-2) [C10 + 2 C20 (I1 - 3) + 3 C30 (I1 - 3)^2], I1 = lambda^2 +
#   2 / lambda, A0 = 100 mm^2: within 0.2 % (the compressible law at
#   K/G = 1000 departs from it by O(G/K));
# - equilibrium: the z = 0 plane's reaction equals minus the top's to 1e-7
#   relative; uniaxial stress: the symmetry planes x = 0 and y = 0 carry no
#   normal force (sigma_xx = sigma_yy = 0 with free sides), below 1e-6 of
#   the top's force;
# - quadratic convergence from the log: in every step, each Newton
#   iteration's relative residual r_k (residual of the free dofs over the
#   reactions) satisfies r_k <= 10 r_{k-1}^2 + 1e-11 once r_{k-1} < 1e-2
#   (1e-11: the round-off floor of the force sums, ~1e-14 kN over reactions
#   from 0.01 kN, 1000 times below the Residual tolerance)
#   (a linearly converging Newton, e.g. with a tangent error of 1 %, gives
#   r_k ~ 1e-2 r_{k-1} and fails), and no step takes more than 6
#   iterations.
# On 2 ranks the history must equal the 1-rank run's to 1e-8 relative
# (the 1-rank run is repeated here for the comparison).
# Usage: uniaxial_compression_quasi_static.sh EXECUTABLE SOURCE_DIR NPROC
set -euo pipefail
exe=$1; source_dir=$2; nproc=$3
name=uniaxial_compression_quasi_static
bash "$source_dir/tests/model/run_example.sh" "$exe" "$source_dir" \
  $name 1 0 "$nproc" > log.txt
awk -F, '
  NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
  $c["time"] > 0 {
    C10 = 0.55e-3; C20 = -0.05e-3; C30 = 0.015e-3; A0 = 100
    t = $c["time"]; lambda = 1 - 0.6 * t; I = lambda^2 + 2 / lambda - 3
    F = A0 * 2 * (lambda - lambda^-2) * (C10 + 2 * C20 * I + 3 * C30 * I^2)
    f = $c["press_force_z"]; e = f / F - 1; if (e < 0) e = -e
    if (e > worst) { worst = e; worst_t = t }
    printf "t %.2f lambda %.2f: F %.6g kN, eq. 4.8 %.6g kN, %+.4f %%\n", t, lambda, f, F, 100 * (f / F - 1)
    balance = ($c["symmetry_z_force_z"] + f) / F; if (balance < 0) balance = -balance
    if (balance > worst_balance) worst_balance = balance
    lateral = $c["symmetry_x_force_x"]^2 + $c["symmetry_y_force_y"]^2
    if (sqrt(lateral) / (F < 0 ? -F : F) > worst_lateral) worst_lateral = sqrt(lateral) / (F < 0 ? -F : F)
    ++rows
  }
  END {
    printf "%d load steps; largest deviation from eq. 4.8 %.4f %% (t = %.2f); balance %.2e; lateral %.2e\n", rows, 100 * worst, worst_t, worst_balance, worst_lateral
    exit (rows != 20 || worst > 0.002 || worst_balance > 1e-7 || worst_lateral > 1e-6)
  }' $name/time_history.csv
bash "$source_dir/tests/model/check_newton_log.sh" log.txt 1e-2 10 6
if [ "$nproc" -gt 1 ]; then
  mkdir -p serial && cd serial
  bash "$source_dir/tests/model/run_example.sh" "$exe" "$source_dir" \
    $name 1 0 1 > log.txt
  cd ..
  bash "$source_dir/tests/model/compare_columns.sh" \
    serial/$name/time_history.csv $name/time_history.csv 1e-8 1e-12 \
    time press_force_z symmetry_z_force_z internal_energy
fi
