#!/usr/bin/env bash
# The three verification set-ups of the quasi-static solver, as
# doc/verification/reference_solutions.md states them, are valid Models on every shipped
# refinement: 'rubberdyn --check' (reads the mesh with the Model's reader,
# builds the parts, the conditions and the model, runs nothing) accepts each
# and reports the expected number of cells.
# - tube_N (N = 4, 8, 16; N x 8N x 1 cells): inner fixed, outer rotated
#   about z (a displacement of x and y), ends fixed in z. The ends' nodes on
#   the inner and outer surfaces are prescribed twice in z with the same
#   zero, which must be accepted.
# - cook_membrane_N (N = 2 ... 64; N^2 cells): clamped x = 0, both z faces
#   fixed in z (plane strain), a y traction on x = 48; neo-Hooke, so C20 and
#   C30 set to 0 (their defaults are the study's).
# - compression_block_N (N = 4, 8; N^3 cells): one symmetry condition per
#   plane (a symmetry condition takes the faces of one plane), the top
#   pressed down in z.
# Usage: verification_setups.sh EXECUTABLE SOURCE_DIR NPROC (serial: NPROC
# is ignored, the check reads the same mesh on every rank)
set -euo pipefail
exe=$1; source_dir=$2; nproc=$3
meshes=$source_dir/parameter_files/meshes

# check NAME CELLS: run --check on NAME.prm, expect CELLS cells.
check() {
  local out
  if ! out=$("$exe" --check "$1.prm" 2>&1); then
    echo "$out"
    echo "FAILED: --check refused $1.prm"
    exit 1
  fi
  if ! grep -q "^Model: $2 cells," <<< "$out" ||
     ! grep -q "is a valid 'Model' study" <<< "$out"; then
    echo "$out"
    echo "FAILED: $1.prm: expected a valid Model of $2 cells"
    exit 1
  fi
  echo "$1: valid, $2 cells"
}

rubber() {
  cat <<PRM
subsection Parts
  set Names = rubber
  subsection rubber
    set Material ids        = 1
    set Element formulation = F-bar
    set Model               = Yeoh
    set C10                 = $1
    set C20                 = $2
    set C30                 = $3
    set Poisson's ratio     = $4
    set Density             = 1.1e-6
  end
end
subsection Time integration
  set End time = 1
end
subsection Output
  set Output directory = output
end
PRM
}

for n in 4 8 16; do
  {
    echo "set Study = Model"
    echo "subsection Mesh"
    echo "  set Mesh file = $meshes/tube_$n.msh"
    echo "end"
    rubber 0.00055 -5e-5 1.5e-5 0.4996
    cat <<'PRM'
subsection Boundary conditions
  set Names = inner, outer, ends
  subsection inner
    set Boundary ids = 1
    set Type         = fixed
  end
  subsection outer
    set Boundary ids        = 2
    set Type                = displacement
    set Components          = x, y, z
    set Function expression = x * (cos(p * t) - 1) - y * sin(p * t); \
                              x * sin(p * t) + y * (cos(p * t) - 1); 0
    set Function constants  = p = 1.039247
    set Moment point        = 0, 0, 0
  end
  subsection ends
    set Boundary ids = 3, 4
    set Type         = fixed
    set Components   = z
  end
end
PRM
  } > "tube_$n.prm"
  check "tube_$n" $((8 * n * n))
done

for n in 2 4 8 16 32 64; do
  {
    echo "set Study = Model"
    echo "subsection Mesh"
    echo "  set Mesh file = $meshes/cook_membrane_$n.msh"
    echo "end"
    rubber 0.0400969 0 0 0.4999
    cat <<'PRM'
subsection Boundary conditions
  set Names = clamped, plane, load
  subsection clamped
    set Boundary ids = 1
    set Type         = fixed
  end
  subsection plane
    set Boundary ids = 3, 4
    set Type         = fixed
    set Components   = z
  end
  subsection load
    set Boundary ids        = 2
    set Type                = traction
    set Components          = y
    set Function expression = 0.00625 * t
  end
end
PRM
  } > "cook_membrane_$n.prm"
  check "cook_membrane_$n" $((n * n))
done

for n in 4 8; do
  {
    echo "set Study = Model"
    echo "subsection Mesh"
    echo "  set Mesh file = $meshes/compression_block_$n.msh"
    echo "end"
    rubber 0.00055 -5e-5 1.5e-5 0.4996
    cat <<'PRM'
subsection Boundary conditions
  set Names = symmetry_x, symmetry_y, symmetry_z, press
  subsection symmetry_x
    set Boundary ids = 1
    set Type         = symmetry
  end
  subsection symmetry_y
    set Boundary ids = 2
    set Type         = symmetry
  end
  subsection symmetry_z
    set Boundary ids = 3
    set Type         = symmetry
  end
  subsection press
    set Boundary ids        = 4
    set Type                = displacement
    set Components          = z
    set Function expression = -6 * t
  end
end
PRM
  } > "compression_block_$n.prm"
  check "compression_block_$n" $((n * n * n))
done
echo "all verification set-ups are valid Models"
