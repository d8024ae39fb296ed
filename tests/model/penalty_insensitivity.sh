#!/usr/bin/env bash
# The drop test is insensitive to the contact penalty (issue 8, with the
# penalty of the current geometry, doc/contact.md section 1 and
# doc/drop_test.md, "The contact penalty"): the shipped cylinder
# (parameter_files/drop_test_cylinder.prm: 5 kg at 2 m/s, 5120 cells,
# frictionless rigid plates) and its deep compression
# (drop_test_deep_compression.prm: 3.2 m/s, about 70 %), without gravity,
# at Penalty scale factor 0.1 (the default, LS-DYNA's) and 1. At the
# maximum of the impactor's travel:
#  - the travel, the vertex of a parabola fitted to the impactor's
#    displacement over +-0.25 ms (rows 0.01 ms apart);
#  - the force, the impactor's mass times the parabola's curvature (its
#    deceleration: the mean contact force, free of the chatter of the end
#    nodes on their springs, which a single row catches anywhere between 92
#    and 105 % of it at the scale 0.1);
#  - the penetration, the travel less the rubber's own compression
#    (rubber_top_displacement - rubber_bottom_displacement, fitted alike):
#    both plates' springs.
# Checked, the bounds: from 0.1 to 1 the travel changes by less
# than 0.5 % in both cases and the force by less than 0.5 % in the shipped
# case; the penetration at 0.1 is below 1 % of the compression in both.
# Measured (2026-12-03): shipped case force -0.30 %, travel +0.26 %,
# penetration 0.37 % of the compression (with the reference geometry's
# penalty before: -2.6 %, +0.81 %, 1.8 %); deep compression travel +0.33 %,
# penetration 0.52 % (before +2.3 %, 4.7 %, force -16 %). The deep case's
# force changes by -1.2 % (printed, not
# checked: the 0.5 % does not hold there): at 70 % compression the
# Yeoh force grows as the compression to the power 8.6, so the 0.14 %
# more compression the springs of scale 1 allow moves it by 1.2 %. Over
# the scales 0.1 to 10 (doc/drop_test.md, "The contact penalty") it
# converges as 1 / scale to 8.628 kN: -1.36 % at 0.1, -0.43 % at 0.3,
# -0.11 % at 1.
# Usage: penalty_insensitivity.sh EXECUTABLE SOURCE_DIR NPROC
set -euo pipefail
exe=$1; source_dir=$2; nproc=$3
source "$source_dir/tests/model/script_helpers.sh"

# run CASE SCALE END_TIME: the example without gravity, in CASE_SCALE/.
run() {
  local name=$1_$2
  sed -e "s|set Gravity *=.*|set Gravity = 0|" \
      -e "s|set End time *=.*|set End time = $3|" \
      -e "s|set Field output interval *=.*|set Field output interval = 0|" \
      -e "s|set History output interval *=.*|set History output interval = 0.01|" \
      -e "s|set Output directory *=.*|set Output directory = $name|" \
      "$source_dir/parameter_files/drop_test_$1.prm" > "$name.prm"
  printf 'subsection Contact\n  set Penalty scale factor = %s\nend\n' "$2" >> "$name.prm"
  rm -rf "$name"
  run_prm "$name.prm" "$name.log"
}

# at_maximum CSV: "travel force compression" at the largest travel.
at_maximum() {
  awk -F, '
    # Least-squares parabola y = c0 + c1 s + c2 s^2 through the rows n0..n1
    # (s = t - t_max): c2 and the vertex value.
    function fit(y, n0, n1,    r, s, S0, S1, S2, S3, S4, Y0, Y1, Y2, D, c0, c1, c2) {
      for (r = n0; r <= n1; ++r) {
        s = t[r] - t[m]; S0 += 1; S1 += s; S2 += s * s; S3 += s^3; S4 += s^4
        Y0 += y[r]; Y1 += s * y[r]; Y2 += s * s * y[r]
      }
      D = S0 * (S2 * S4 - S3 * S3) - S1 * (S1 * S4 - S3 * S2) + S2 * (S1 * S3 - S2 * S2)
      c0 = (Y0 * (S2 * S4 - S3 * S3) - S1 * (Y1 * S4 - S3 * Y2) + S2 * (Y1 * S3 - S2 * Y2)) / D
      c1 = (S0 * (Y1 * S4 - Y2 * S3) - Y0 * (S1 * S4 - S3 * S2) + S2 * (S1 * Y2 - Y1 * S2)) / D
      c2 = (S0 * (S2 * Y2 - S3 * Y1) - S1 * (S1 * Y2 - Y1 * S2) + Y0 * (S1 * S3 - S2 * S2)) / D
      curvature = c2
      return c0 - c1 * c1 / (4 * c2)
    }
    NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
    # (Both displacements downwards positive.)
    { n = NR - 1; t[n] = $c["time"]; u[n] = $c["impactor_displacement"]
      h[n] = $c["rubber_top_displacement"] - $c["rubber_bottom_displacement"]
      if (n == 1 || u[n] > u[m]) m = n }
    END {
      for (n0 = m; n0 > 1 && t[n0 - 1] >= t[m] - 0.25; --n0);
      for (n1 = m; n1 < n && t[n1 + 1] <= t[m] + 0.25; ++n1);
      travel = fit(u, n0, n1); force = -5 * 2 * curvature
      compression = fit(h, n0, n1)
      printf "%.10g %.10g %.10g\n", travel, force, compression
    }' "$1"
}

status=0
for case in cylinder:10 deep_compression:7.5; do
  name=${case%%:*}; end=${case##*:}
  run "$name" 0.1 "$end"
  run "$name" 1 "$end"
  read -r u_soft F_soft c_soft < <(at_maximum "${name}_0.1/time_history.csv")
  read -r u_stiff F_stiff c_stiff < <(at_maximum "${name}_1/time_history.csv")
  awk -v name="$name" -v u0="$u_soft" -v F0="$F_soft" -v c0="$c_soft" \
      -v u1="$u_stiff" -v F1="$F_stiff" -v c1="$c_stiff" 'BEGIN {
    du = u0 / u1 - 1; dF = F0 / F1 - 1; pen = (u0 - c0) / c0
    printf "%s: scale 0.1: travel %.4f mm, force %.4f kN, compression %.4f mm; scale 1: travel %.4f mm, force %.4f kN, compression %.4f mm\n", name, u0, F0, c0, u1, F1, c1
    printf "%s: scale 0.1 against 1: travel %+.3f %%, force %+.3f %%; penetration at 0.1 %.3f %% of the compression\n", name, 100 * du, 100 * dF, 100 * pen
    bad = (du > 0.005 || du < -0.005 || pen > 0.01 || pen < 0)
    if (name == "cylinder") bad = bad || dF > 0.005 || dF < -0.005
    exit bad
  }' || status=1
done
exit $status
