#!/usr/bin/env bash
# Quasi-static uniaxial compression of a Yeoh block to 60 % with the mixed
# u-p element (Q2 displacement, condensed P1 pressure and dilatation; issue
# 9): parameter_files/uniaxial_compression_quasi_static.prm with its part
# switched to 'Element formulation = mixed u-p' (appended to the file, so
# the model, loads and steps are the F-bar test's: 3 x 3 x 3 hexahedra on
# three symmetry planes, the top pushed down 6 mm, K/G = 1000), checked by
# tests/model/uniaxial_compression_quasi_static.sh with the same criteria:
# at every one of the 20 load steps the top's reaction within 0.2 % of the
# reference study's eq. 4.8, the z = 0 plane's reaction equal and opposite
# to 1e-7, no normal force on the x = 0 and y = 0 planes (1e-6), quadratic
# Newton convergence read from the log (r_k <= 10 r_{k-1}^2 + 1e-11 once
# r_{k-1} < 1e-2, on at least 20 iterations, at most 6 iterations a step),
# and on 2 ranks the 1-rank history to 1e-8. In addition: the run must use
# the Q2 dofs (3 (2 n + 1)^3 = 1029 dofs on the 3 x 3 x 3 mesh).
# Usage: uniaxial_compression_mixed_up.sh EXECUTABLE SOURCE_DIR NPROC
set -euo pipefail
export EXAMPLE_APPEND='subsection Parts
  subsection rubber
    set Element formulation = mixed u-p
  end
end'
bash "$(dirname "$0")/uniaxial_compression_quasi_static.sh" "$@"
grep -q "27 cells, 1029 dofs" log.txt ||
  { echo "not the Q2 dofs of the mixed u-p element:"; head -3 log.txt; exit 1; }
echo "mixed u-p: 27 cells, 1029 dofs"
