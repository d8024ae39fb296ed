#!/usr/bin/env bash
# Compare the drop test's force at maximum compression with eq. 4.8 of the
# reference study, from a time_history.csv:
#   doc/scripts/drop_test_eq48.sh OUTPUT_DIR [H D C10 C20 C30]
# (defaults: H = 24 mm, D = 25 mm, chapter-4 constants in MPa).
# The rubber's height at maximum compression is the impactor position
# corrected for the penetration of the two penalty contacts: with a common
# force F, their stored energy is E_c = F delta / 2, so delta = 2 E_c / F.
set -euo pipefail
dir=$1; H=${2:-24}; D=${3:-25}; C10=${4:-0.55}; C20=${5:--0.05}; C30=${6:-0.015}
awk -F, -v H="$H" -v D="$D" -v C10="$C10" -v C20="$C20" -v C30="$C30" '
NR == 1 { for (i = 1; i <= NF; ++i) col[$i] = i; next }
{ d = $col["impactor_displacement"]; if (d > dmax) { dmax = d; row = $0 } }
END {
  split(row, v, ",");
  F  = v[col["impactor_force"]]; Ec = v[col["contact_work"]];
  delta = (F > 0 ? 2 * Ec / F : 0);
  h = H - dmax + delta; l = h / H; I1 = l * l + 2 / l; x = I1 - 3;
  A = 3.14159265358979 * D * D / 4;
  P = 2 * (l - 1 / (l * l)) * (C10 + 2 * C20 * x + 3 * C30 * x * x); # MPa
  Fa = -P * A / 1000;                                                  # kN
  printf "time %.3f ms: impactor displacement %.3f mm, penetration %.3f mm, stretch %.4f\n", v[col["time"]], dmax, delta, l;
  printf "FE force %.4f kN, eq. 4.8 %.4f kN, FE / eq. 4.8 - 1 = %+.2f %%\n", F, Fa, 100 * (F / Fa - 1);
}' "$dir/time_history.csv"
