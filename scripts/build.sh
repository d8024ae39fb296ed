#!/usr/bin/env bash
# One entry point for a fresh Debian 12 machine:
#   scripts/build.sh run    install missing Debian packages, build (Release)
#                           and run the default study
#   scripts/build.sh test   the same set-up, then the whole test suite (ctest)
#   scripts/build.sh build  set-up and build only
# Idempotent: installed packages and an existing build/ are reused.
set -euo pipefail

cd "$(dirname "$0")/.."
SOURCE_DIR=$(pwd)
BUILD_DIR=${RUBBERDYN_BUILD_DIR:-$SOURCE_DIR/build}
JOBS=${RUBBERDYN_JOBS:-$(nproc)}
ACTION=${1:-build}

# libopenblas0-serial: an optimised BLAS/LAPACK (Debian's alternatives
# system puts it before the reference BLAS). The quasi-static solver's
# direct solver (MUMPS) spends most of its time in dgemm/dtrsm: 3.3 times
# faster on bolted_plates.prm's load path (benchmarks/README.md). Serial:
# the MPI ranks are the parallelism. python3 (standard library only): the
# script tests that read the ParaView output (tests/model/hertz_profile.py,
# radius_profile.py).
PACKAGES=(cmake make g++ lld libdeal.ii-dev numdiff ccache openmpi-bin perl
          libopenblas0-serial python3)

install_missing_packages() {
  local missing=()
  for package in "${PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" ||
      missing+=("$package")
  done
  if [ ${#missing[@]} -eq 0 ]; then
    return
  fi
  echo "Installing Debian packages: ${missing[*]}"
  local sudo=""
  if [ "$(id -u)" -ne 0 ]; then
    sudo=sudo
  fi
  $sudo apt-get update -q
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
}

# build [TARGET...]: configure if needed, then build 'all' and the targets.
build() {
  if [ ! -f "$BUILD_DIR/CMakeCache.txt" ]; then
    cmake -S "$SOURCE_DIR" -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release
  fi
  cmake --build "$BUILD_DIR" -j "$JOBS" --target all "$@"
}

# ccache keys on the absolute paths of the compile commands: with the
# source tree as its base directory they are relative, so that a fresh
# clone in another folder (CI's) finds the objects an earlier build of the
# same sources left in the cache.
export CCACHE_BASEDIR=${CCACHE_BASEDIR:-$SOURCE_DIR}

# Open MPI refuses to run as root without these (CI runs as root).
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

install_missing_packages
case "$ACTION" in
  test)
    # The unit tests' executables in the same parallel build, not one by
    # one inside ctest (see tests/CMakeLists.txt).
    build rubberdyn_test_executables
    ;;
  *) build ;;
esac
case "$ACTION" in
  build) ;;
  run)
    mkdir -p "$SOURCE_DIR/output"
    cd "$SOURCE_DIR"
    "$BUILD_DIR/rubberdyn" --default
    ;;
  test)
    # ctest runs two tests at once on two cores, and each MPI test's ranks
    # spin while they wait for a message unless told to yield: two 2-rank
    # tests are four spinning processes on two cores, whose waits last
    # until the spinning partner is descheduled. Yielding changes no result.
    export OMPI_MCA_mpi_yield_when_idle=${OMPI_MCA_mpi_yield_when_idle:-1}
    ctest --test-dir "$BUILD_DIR" -j "$JOBS" --output-on-failure
    ;;
  *)
    echo "usage: scripts/build.sh [build|run|test]" >&2
    exit 1
    ;;
esac
