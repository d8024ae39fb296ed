#!/usr/bin/env bash
# compare_columns.sh A.csv B.csv RELATIVE ABSOLUTE "colA=colB[*scale+offset]" ...
# Compares columns of two CSV files with headers row by row: |a - b| <=
# RELATIVE * max(|a|, |b|) + ABSOLUTE, where b may be a column of B scaled
# and shifted ("impactor_displacement=impactor_position_z*-1+24"). Prints
# the largest relative difference per column and exits 1 on any violation or
# if the row counts differ.
set -euo pipefail
a=$1; b=$2; rel=$3; abs=$4; shift 4
awk -F, -v rel="$rel" -v abs="$abs" -v specs="$*" '
  FNR == 1 { for (i = 1; i <= NF; ++i) col[FILENAME == ARGV[1] ? "a" : "b", $i] = i; next }
  FILENAME == ARGV[1] { rows_a = FNR - 1; for (i = 1; i <= NF; ++i) A[FNR - 1, i] = $i; next }
  { rows_b = FNR - 1; for (i = 1; i <= NF; ++i) B[FNR - 1, i] = $i }
  END {
    if (rows_a != rows_b || rows_a == 0) { printf "row counts differ: %d and %d\n", rows_a, rows_b; exit 1 }
    n = split(specs, spec, " "); bad = 0
    for (k = 1; k <= n; ++k) {
      split(spec[k], side, "="); name_a = side[1]; expr = (side[2] == "" ? side[1] : side[2])
      scale = 1; offset = 0; name_b = expr
      if (match(expr, /\*[-0-9.e]+/)) { scale = substr(expr, RSTART + 1, RLENGTH - 1) + 0; name_b = substr(expr, 1, RSTART - 1) }
      if (match(expr, /\+[-0-9.e]+$/)) offset = substr(expr, RSTART + 1) + 0
      if (!(("a", name_a) in col) || !(("b", name_b) in col)) { printf "missing column %s or %s\n", name_a, name_b; bad = 1; continue }
      ia = col["a", name_a]; ib = col["b", name_b]; worst = 0
      for (r = 1; r <= rows_a; ++r) {
        x = A[r, ia] + 0; y = B[r, ib] * scale + offset
        d = x - y; if (d < 0) d = -d
        m = (x < 0 ? -x : x); my = (y < 0 ? -y : y); if (my > m) m = my
        if (d > rel * m + abs) { printf "%s row %d: %.12g vs %.12g\n", name_a, r, x, y; bad = 1 }
        if (m > 0 && d / m > worst) worst = d / m
      }
      printf "%-28s largest relative difference %.2e\n", name_a, worst
    }
    exit bad
  }' "$a" "$b"
