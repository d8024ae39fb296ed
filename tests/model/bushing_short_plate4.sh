#!/usr/bin/env bash
# The shortened drop-tower test 1 of the bushing (4 mm plate, V0 =
# 9.905 mm/ms; tests/model/bushing_short_common.sh has the shortening and
# the checks), with its own preload.
# Usage: bushing_short_plate4.sh EXECUTABLE SOURCE_DIR NPROC
set -euo pipefail
exe=$1; source_dir=$2; nproc=$3
source "$source_dir/tests/model/script_helpers.sh"
source "$source_dir/tests/model/bushing_short_common.sh"

run_short 1
check_short 1 9.905
