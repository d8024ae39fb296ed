#!/usr/bin/env bash
# Quasi-static contact with a rigid surface
# (parameter_files/uniaxial_compression_rigid_plate.prm): the octant Yeoh
# block of uniaxial_compression_quasi_static (10 mm, three symmetry planes,
# K/G = 1000, F-bar) compressed by a frictionless rigid plane that moves
# down 6 t mm. Frictionless plates leave the deformation homogeneous, so at
# every converged load step (20 steps of 0.05):
# - the plate's force plate_force_z against the reference study's eq. 4.8
#   (/work/shared/seed-notes.md, incompressible Yeoh), F = A0 2 (lambda -
#   lambda^-2) [C10 + 2 C20 (I1 - 3) + 3 C30 (I1 - 3)^2], I1 = lambda^2 +
#   2 / lambda, A0 = 100 mm^2, with the stretch the block really has,
#   lambda = 1 + u_z / 10 from the top corner node (the plate's travel less
#   the penetration of the penalty springs): within 0.2 % (as the
#   displacement-driven test: the compressible law departs by O(G/K));
# - the penetration (travel + u_z) is positive and below 3 % of the travel;
# - the plate is where its Velocity function integrated over the pseudo-time
#   puts it, z = 10 - 6 t, to 1e-12 mm;
# - equilibrium: the plate's force equals the z = 0 plane's reaction to
#   1e-7 relative, and the x = 0 and y = 0 planes carry no normal force
#   (below 1e-6 of it);
# - quadratic convergence from the log, as uniaxial_compression_quasi_static
#   (the contact tangent is exact for the penalty held), in at most 4
#   iterations per step but the last, which takes 11 (at most 12 checked):
#   the last state is brought into equilibrium with the penalty of its own
#   geometry, each update of the penalty costing one or two iterations (it
#   grows as 1/lambda^2 while the block is squashed; doc/quasi_static.md,
#   "Contact penalty and the geometry").
# On 2 ranks the history must equal the 1-rank run's to 1e-8 relative.
# Usage: uniaxial_compression_rigid_plate.sh EXECUTABLE SOURCE_DIR NPROC
set -euo pipefail
exe=$1; source_dir=$2; nproc=$3
name=uniaxial_compression_rigid_plate
bash "$source_dir/tests/model/run_example.sh" "$exe" "$source_dir" \
  $name 1 0 "$nproc" > log.txt
awk -F, '
  NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
  $c["time"] > 0 {
    C10 = 0.55e-3; C20 = -0.05e-3; C30 = 0.015e-3; A0 = 100
    t = $c["time"]; uz = $c["top_corner_displacement_z"]
    lambda = 1 + uz / 10; I = lambda^2 + 2 / lambda - 3
    F = A0 * 2 * (lambda - lambda^-2) * (C10 + 2 * C20 * I + 3 * C30 * I^2)
    f = -$c["plate_force_z"]; e = f / F - 1; if (e < 0) e = -e
    if (e > worst) { worst = e; worst_t = t }
    travel = 6 * t; penetration = travel + uz
    if (penetration <= 0 || penetration > 0.03 * travel) bad_penetration = 1
    place = $c["plate_position_z"] - (10 - travel); if (place < 0) place = -place
    if (place > worst_place) worst_place = place
    printf "t %.2f lambda %.4f penetration %.4f mm: F %.6g kN, eq. 4.8 %.6g kN, %+.4f %%\n", t, lambda, penetration, f, F, 100 * (f / F - 1)
    balance = ($c["symmetry_z_force_z"] - $c["plate_force_z"]) / F; if (balance < 0) balance = -balance
    if (balance > worst_balance) worst_balance = balance
    lateral = sqrt($c["symmetry_x_force_x"]^2 + $c["symmetry_y_force_y"]^2) / (F < 0 ? -F : F)
    if (lateral > worst_lateral) worst_lateral = lateral
    ++rows
  }
  END {
    printf "%d load steps; largest deviation from eq. 4.8 %.4f %% (t = %.2f); plate place %.1e mm; balance %.2e; lateral %.2e\n", rows, 100 * worst, worst_t, worst_place, worst_balance, worst_lateral
    exit (rows != 20 || worst > 0.002 || bad_penetration || worst_place > 1e-12 || worst_balance > 1e-7 || worst_lateral > 1e-6)
  }' $name/time_history.csv
bash "$source_dir/tests/model/check_newton_log.sh" log.txt 1e-2 10 12
if [ "$nproc" -gt 1 ]; then
  mkdir -p serial && cd serial
  bash "$source_dir/tests/model/run_example.sh" "$exe" "$source_dir" \
    $name 1 0 1 > log.txt
  cd ..
  bash "$source_dir/tests/model/compare_columns.sh" \
    serial/$name/time_history.csv $name/time_history.csv 1e-8 1e-12 \
    time plate_force_z symmetry_z_force_z internal_energy \
    top_corner_displacement_z
fi
