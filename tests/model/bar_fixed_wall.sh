#!/usr/bin/env bash
# A steel bar hitting a fixed wall with its own velocity v0 = 10 m/s
# (parameter_files/bar_fixed_wall.prm): one-dimensional wave theory gives
# the wall's reaction rho c A v0 (c = sqrt(E / rho) = 5172 mm/ms, A = 100
# mm^2: 40.61 kN) until the wave reflected at the free end returns at
# 2 L / c = 0.03867 ms, where the reaction changes sign. Checked: the mean
# reaction over the middle half of [0, 2 L / c] within 2 % of rho c A v0
# (the coarse mesh rings about the plateau), the sign change, interpolated
# between rows, within 2 % of 2 L / c, and the lateral reactions zero
# (the bar's Poisson expansion is free). The free end's motion, from the
# History node 'free_end' at (100, 0, 0) (Output/History nodes in the
# explicit run): it moves on at -v0 until the wave reaches it at L / c, and
# the reflection at the free end doubles the velocity jump, so it moves
# back at +v0 until 2 L / c: u_x = -v0 t, then -v0 (2 L / c - t). Checked:
# |u_x + v0 t| within 2 % of v0 L / c for t <= 0.8 L / c, and the mean u_x
# over [1.2, 1.8] L / c, -v0 L / (2 c), within 3 % (the coarse mesh rings
# behind the front; measured -1.5 %).
# Usage: bar_fixed_wall.sh EXECUTABLE SOURCE_DIR NPROC
set -euo pipefail
exe=$1; source_dir=$2; nproc=$3
EXAMPLE_APPEND='subsection Output
  set History nodes = free_end: 100, 0, 0
end' bash "$source_dir/tests/model/run_example.sh" "$exe" "$source_dir" \
  bar_fixed_wall 0.045 0 "$nproc" > log.txt
awk -F, '
  NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
  { t[NR] = $c["time"]; f[NR] = $c["wall_force_x"]; n = NR
    u[NR] = $c["free_end_displacement_x"]
    lateral = ($c["wall_force_y"] < 0 ? -$c["wall_force_y"] : $c["wall_force_y"])
    if (lateral > max_lateral) max_lateral = lateral }
  END {
    E = 210; rho = 7.85e-6; A = 100; v0 = 10; L = 100
    cbar = sqrt(E / rho); F = rho * cbar * A * v0; T = 2 * L / cbar
    for (r = 2; r <= n; ++r)
      if (t[r] >= 0.25 * T && t[r] <= 0.75 * T) { sum += f[r]; ++count }
    plateau = sum / count
    for (r = 3; r <= n; ++r)
      if (f[r - 1] > 0 && f[r] <= 0) { change = t[r - 1] + (t[r] - t[r - 1]) * f[r - 1] / (f[r - 1] - f[r]); break }
    printf "plateau %.4g kN (rho c A v0 = %.4g kN, %+.2f %%)\n", plateau, F, 100 * (plateau / F - 1)
    printf "sign change at %.5g ms (2 L / c = %.5g ms, %+.2f %%)\n", change, T, 100 * (change / T - 1)
    printf "largest lateral reaction %.3g kN\n", max_lateral
    for (r = 2; r <= n; ++r) {
      if (t[r] <= 0.4 * T) { d = u[r] + v0 * t[r]; if (d < 0) d = -d; if (d > free_error) free_error = d }
      if (t[r] >= 0.6 * T && t[r] <= 0.9 * T) { stand += u[r]; ++m }
    }
    stand /= m; reach = v0 * T / 2
    printf "free end: |u + v0 t| at most %.3g mm before L / c (%.2f %% of v0 L / c); mean after %.5g mm (-v0 L / (2 c) = %.5g, %+.2f %%)\n", free_error, 100 * free_error / reach, stand, -reach / 2, 100 * (-stand / (reach / 2) - 1)
    bad = (plateau / F - 1 > 0.02 || plateau / F - 1 < -0.02)
    bad = bad || (change / T - 1 > 0.02 || change / T - 1 < -0.02)
    bad = bad || max_lateral > 1e-6 * F
    bad = bad || free_error > 0.02 * reach || (-stand / (reach / 2) - 1 > 0.03 || -stand / (reach / 2) - 1 < -0.03)
    exit bad
  }' bar_fixed_wall/time_history.csv
