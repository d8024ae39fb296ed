#!/usr/bin/env bash
# Cook's membrane to n = 64 for the F-bar and the mixed u-p elements: the
# test tests/verification/cook_membrane (which stops at F-bar n = 32 and
# mixed u-p n = 8 to stay within the test budget) with both series run to
# n = 64, where it also asserts n = 32 within 1 % of 6.908 (Elguedj et al.
# 2008) and of its own n = 64 value. The mixed element's n = 64 (150 000
# dofs, direct solver MUMPS on OpenBLAS) takes 11 minutes on one core (its
# n = 32: 69 s); 1.4 GB.
# Prints the table (tip u_y per n, Newton iterations, wall time) to stderr
# and the test's summary from its file "output".
# Usage: benchmarks/cook_membrane.sh BUILD_DIR   (after
#   make -C BUILD_DIR verification.cook_membrane.release)
set -euo pipefail
build=${1:-build}
exe=$(ls "$build"/tests/verification/cook_membrane.release/cook_membrane.release)
dir=$(mktemp -d)
cd "$dir"
COOK_FBAR_MAX_N=64 COOK_MIXED_MAX_N=64 "$exe"
cat output
