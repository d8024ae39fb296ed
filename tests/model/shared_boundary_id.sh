#!/usr/bin/env bash
# Two conditions on one boundary id (doc/model.md, "Two conditions share a
# boundary id"): the rubber block of parameter_files/shear_block.prm, its
# bottom (id 1) fixed, its top (id 2) both held in x and y by 'guide'
# (displacement 0 in x, y) and pushed by 'press', a follower pressure
# p = 1e-4 GPa on the same faces, to 0.2 ms. Checked on every row of
# time_history.csv:
# - the run is accepted: a load and a kinematic condition on different
#   components of the same faces do not conflict;
# - press_force_z = -p A, A = 400 mm^2, to 1e-9 relative: the load is
#   -p n da on the current faces, and the z component of the integral of
#   n da over the top is its area projected on the x-y plane, which stays
#   the 20 x 20 mm square as long as the guide holds x and y of its nodes
#   (exactly, so only round-off remains);
# - guide_force_z = 0 exactly: the guide acts in x and y only;
# - press_force_x and press_force_y below 1e-9 |p A|: the block and its
#   load are symmetric about x = 10 and y = 10.
# Usage: shared_boundary_id.sh EXECUTABLE SOURCE_DIR NPROC
set -euo pipefail
exe=$1; source_dir=$2; nproc=$3
cat > shared_boundary_id.prm <<PRM
set Study = Model
subsection Mesh
  set Mesh file = $source_dir/parameter_files/meshes/shear_block.msh
end
subsection Parts
  set Names = rubber
  subsection rubber
    set Material ids        = 1
    set Model               = Yeoh
    set Constants from      = coefficients
    set C10                 = 0.00055
    set Poisson's ratio     = 0.499
    set Density             = 1.1e-6
  end
end
subsection Boundary conditions
  set Names = base, guide, press
  subsection base
    set Boundary ids = 1
    set Type         = fixed
  end
  subsection guide
    set Boundary ids        = 2
    set Type                = displacement
    set Components          = x, y
    set Function expression = 0; 0
  end
  subsection press
    set Boundary ids        = 2
    set Type                = pressure
    set Function expression = 1e-4
  end
end
subsection Time integration
  set End time = 0.2
end
subsection Output
  set Output directory        = shared_boundary_id
  set History output interval = 0.02
  set Field output interval   = 0
end
PRM
rm -rf shared_boundary_id
if [ "$nproc" -gt 1 ]; then
  mpirun --oversubscribe -np "$nproc" "$exe" shared_boundary_id.prm > log.txt
else
  "$exe" shared_boundary_id.prm > log.txt
fi
awk -F, '
  function abs(x) { return x < 0 ? -x : x }
  NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i
            for (k = split("press_force_x press_force_y press_force_z guide_force_z", need, " "); k > 0; --k)
              if (!(need[k] in c)) { printf "missing column %s\n", need[k]; exit 1 }
            next }
  { ++n; F = -1e-4 * 400
    ez = abs($c["press_force_z"] - F) / abs(F); if (ez > worst_z) worst_z = ez
    exy = (abs($c["press_force_x"]) + abs($c["press_force_y"])) / abs(F)
    if (exy > worst_xy) worst_xy = exy
    gz = abs($c["guide_force_z"]); if (gz > worst_guide) worst_guide = gz }
  END {
    if (n < 5) { printf "only %d rows\n", n; exit 1 }
    printf "%d rows: press_force_z = -p A to %.1e relative, press_force_x, _y %.1e of p A, guide_force_z at most %g kN\n", n, worst_z, worst_xy, worst_guide
    exit (worst_z > 1e-9 || worst_xy > 1e-9 || worst_guide != 0)
  }' shared_boundary_id/time_history.csv
