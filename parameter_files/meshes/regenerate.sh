#!/bin/bash
# Regenerate every .msh of this folder from its .geo with Gmsh, as Gmsh's
# ASCII format 2.2: bash parameter_files/meshes/regenerate.sh (a .geo
# listed in 'variants' below gives one .msh per resolution)
#
# The shipped files were made with Debian 12's gmsh 4.8.4 (apt-get install
# gmsh); with it, the output is byte-identical (check with git diff).
# Another Gmsh version may number nodes differently or round differently.
set -euo pipefail
cd "$(dirname "$0")"

if ! command -v gmsh > /dev/null; then
  echo "regenerate.sh: gmsh not found (Debian: apt-get install gmsh)" >&2
  exit 1
fi
version=$(gmsh --version 2>&1)
if [ "$version" != "4.8.4" ]; then
  echo "regenerate.sh: warning: gmsh $version, the shipped meshes were" \
    "made with 4.8.4; the output may differ" >&2
fi

# Gmsh reads the user's option files ($HOME/.gmshrc, $HOME/.gmsh-options):
# run it with an empty home so that they cannot change the output, and set
# every option the output depends on.
home=$(mktemp -d)
trap 'rm -rf "$home"' EXIT

# The verification meshes come from one .geo each at several resolutions:
# the values of its parameter n, each written to NAME_N.msh; "default"
# is the .geo's own default, written to NAME.msh (the bushing: the study's
# mesh as bushing.msh and a coarse one for tests as bushing_1.msh).
declare -A variants=(
  [tube]="4 8 16"
  [cook_membrane]="2 4 8 16 32 64"
  [compression_block]="4 8"
  [bushing]="default 1"
)

# mesh GEO MSH [gmsh options...]
mesh() {
  local geo=$1 msh=$2
  shift 2
  local log
  log=$(HOME="$home" gmsh "$geo" -3 -nopopup -v 4 -nt 1 \
    -format msh22 \
    -setnumber Mesh.Binary 0 \
    -setnumber Mesh.SaveAll 0 \
    -setnumber Mesh.SaveParametric 0 \
    "$@" \
    -o "$msh" 2>&1) || { echo "$log" >&2; exit 1; }
  if grep -q "Error" <<< "$log"; then
    echo "$log" >&2
    exit 1
  fi
  echo "$msh: $(grep -o '[0-9]* nodes [0-9]* elements' <<< "$log" | tail -1)"
}

for geo in *.geo; do
  name="${geo%.geo}"
  if [ -n "${variants[$name]+set}" ]; then
    for n in ${variants[$name]}; do
      if [ "$n" = default ]; then
        mesh "$geo" "$name.msh"
      else
        mesh "$geo" "${name}_${n}.msh" -setnumber n "$n"
      fi
    done
  else
    mesh "$geo" "$name.msh"
  fi
done

# The study's test 1 has a 4 mm plate (tests 2 to 4 the default 5 mm):
# parameter_files/bushing_test_1.prm and its coarse variant in the tests.
mesh bushing.geo bushing_plate4.msh -setnumber plate_thickness 4
mesh bushing.geo bushing_1_plate4.msh -setnumber n 1 \
  -setnumber plate_thickness 4
