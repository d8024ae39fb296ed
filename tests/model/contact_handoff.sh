#!/usr/bin/env bash
# The hand-off (Time integration/Scheme = quasi-static then explicit) keeps
# the contact state: a Yeoh cube (meshes/uniaxial_block.msh, no boundary
# condition) under a 0.3 MPa follower pressure on its top, held only by a
# rigid floor with Coulomb friction 0.8. Its lateral bulge leaves every
# floor node with a tangential (radial) friction force; the preload's
# converged state, with those forces and their reference points, starts a
# 0.5 ms explicit run with no further load. If the explicit run forgot the
# friction state, the released tangential springs would make the cube ring
# (kinetic energy ~1e-3 of the strain energy, measured when it did).
# Checked over the explicit run:
# - kinetic energy / internal energy <= 1e-12;
# - the energy balance (its initial energy: the preload's strain energy
#   and the floor's penalty-spring energy) holds to 1e-10 (energy_error);
# - the floor's force stays the preload's last one to 1e-10 relative, and
#   friction does no work (|friction_work| <= 1e-14 J);
# - a restart from the preload checkpoint (Output/Restart from checkpoint,
#   another End time) starts from the same state: no load step, and the
#   same first row of energies and forces.
# Usage: contact_handoff.sh EXECUTABLE SOURCE_DIR NPROC
set -euo pipefail
exe=$1; source_dir=$2; nproc=$3
source "$source_dir/tests/model/script_helpers.sh"
write_prm() { # END_TIME RESTART
  cat > handoff.prm <<PRM
set Study = Model
subsection Mesh
  set Mesh file = $source_dir/parameter_files/meshes/uniaxial_block.msh
end
subsection Parts
  set Names = rubber
  subsection rubber
    set Material ids        = 1
    set Element formulation = F-bar
    set Model               = Yeoh
    set Constants from      = coefficients
    set C10                 = 0.00055
    set C20                 = -0.00005
    set C30                 = 0.000015
    set Volumetric model    = bulk modulus
    set Bulk modulus        = 1.1
    set Density             = 1.1e-6
  end
end
subsection Boundary conditions
  set Names = load
  subsection load
    set Boundary ids        = 4
    set Type                = pressure
    set Function expression = 0.0003
  end
end
subsection Rigid surfaces
  set Names = floor
  subsection floor
    set Shape                = plane
    set Point                = 0, 0, 0
    set Direction            = 0, 0, 1
    set Boundary ids         = 3
    set Friction coefficient = 0.8
  end
end
subsection Time integration
  set Scheme                = quasi-static then explicit
  set End time              = $1
  set Quasi-static end time = 1
  subsection Quasi-static
    set Linear solver = direct
  end
end
subsection Output
  set Output directory          = handoff
  set History output interval   = 0.01
  set Field output interval     = 0
  set Restart from checkpoint   = $2
end
PRM
}
rm -rf handoff
write_prm 0.5 false
run_prm handoff.prm log.txt
grep "^Finished" log.txt
handoff_at_rest handoff/time_history.csv floor_force_z 1e-10 1e-14
first_row=$(sed -n 2p handoff/time_history.csv | cut -d, -f3-)

# Another explicit run from the same preload.
write_prm 0.2 true
restart_from_preload handoff.prm \
  handoff_at_rest handoff/time_history.csv floor_force_z 1e-10 1e-14
