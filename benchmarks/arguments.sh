# Sourced by the benchmark scripts called as SCRIPT [BUILD_DIR] [WORK_DIR]
# [RANKS...]: sets build (absolute, default build), ranks (default "1 2")
# and source_dir, and changes into WORK_DIR (default a new temporary
# directory).
build=$(cd "${1:-build}" && pwd)
work=${2:-$(mktemp -d)}
# (Both optional: shift what was given, so that the ranks stay empty.)
shift $(( $# < 2 ? $# : 2 ))
ranks=${*:-1 2}
source_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
mkdir -p "$work"
cd "$work"
