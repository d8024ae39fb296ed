#!/usr/bin/env bash
# check_newton_log.sh LOG START CONSTANT MAX_ITERATIONS [FLOOR]: second-order
# convergence of the quasi-static solver, read from its log (one
# "  Step to" line per load step, one "    iteration k: ..., relative r,
# ..." line per Newton iteration, and "    penalty stiffness of this
# state: ..., relative r" where a contact's penalty, updated to the
# converged state, left the residual r to iterate on from): in every
# step, once the relative
# residual r_{k-1} is below START, r_k <= CONSTANT r_{k-1}^2 + FLOOR (the
# round-off floor of the force sums; default 1e-11, 1000 times below the
# default Residual tolerance; a model whose reactions are small against its
# internal forces sits higher); no step takes more than MAX_ITERATIONS iterations; and at
# least 20 iterations were checked (a log without them proves nothing).
# Prints the number checked, the largest r_k / r_{k-1}^2 and the most
# iterations of a step; exits 1 if any check fails.
set -euo pipefail
awk -v start="$2" -v constant="$3" -v max_iterations="$4" -v floor="${5:-1e-11}" '
  /^  Step to/ { k = 0; next }
  /^    penalty stiffness of this state/ {
    for (i = 1; i <= NF; ++i) if ($i == "relative") previous = $(i + 1) + 0
    next
  }
  /^    iteration/ {
    ++k
    for (i = 1; i <= NF; ++i) if ($i == "relative") r = $(i + 1) + 0
    if (k > 1 && previous < start) {
      ++checked
      if (r > constant * previous^2 + floor) { printf "not quadratic: %.3e after %.3e\n", r, previous; bad = 1 }
      if (r > floor && r / previous^2 > largest) largest = r / previous^2
    }
    if (k > max_iterations) { printf "more than %d iterations in a step\n", max_iterations; bad = 1 }
    if (k > most) most = k
    previous = r
  }
  END {
    printf "second order checked on %d iterations (r_k <= %g r_{k-1}^2 once r_{k-1} < %g): largest r_k / r_{k-1}^2 %.3g; at most %d iterations per step\n", checked, constant, start, largest, most
    exit (bad || checked < 20) }' "$1"
