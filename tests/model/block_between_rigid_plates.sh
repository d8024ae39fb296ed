#!/usr/bin/env bash
# A body held only by contact, with friction, quasi-static
# (parameter_files/block_between_rigid_plates.prm): a Yeoh cube with no
# boundary condition rests on a rigid floor (mu 0.8) and is pressed by a
# rigid plate (mu 0.05) that moves down 1 mm, then 3 mm sideways in x. Both
# touch the cube at t = 0 with a closed gap; the solver takes it as active
# (with friction's sticking stiffness), or the first load step's matrix
# would be singular (the cube free to float). Checked:
# - the run converges without a cut-back;
# - the plates are where their Velocity function integrated over the
#   pseudo-time puts them: z = 10 - t up to t = 1, then x = 3 (t - 1), to
#   1e-12 mm;
# - equilibrium of the cube: the floor's force is minus the plate's, in x
#   and z, to 1e-8 of the plate's normal force, and y forces vanish (1e-10);
# - Coulomb's law in steady sliding (t >= 1.4, the plate 1.2 mm past the
#   start of the slide): |plate_force_x| / plate_force_z = mu = 0.05 to
#   1e-6, while the floor holds (its ratio is the same 0.05 < 0.8);
# - before the slide no tangential force (symmetry): |force_x| < 1e-12 of
#   the normal force.
# And again with mu 0.2 on the plate: the top sticks longer, and the slide
# turns many nodes from stick to slip in one load step (the elastic range of
# the tangential spring is mu |g|, ~0.01 mm here, the step moves the plate
# 0.3 mm). Before the solver linearised the surfaces' motion in its
# predictor this cut back to its minimum step and failed; now: no cut-back,
# equilibrium to 1e-8, |F_x| / F_z rising to mu (within 1e-5 at the end,
# from below).
# Usage: block_between_rigid_plates.sh EXECUTABLE SOURCE_DIR NPROC
set -euo pipefail
exe=$1; source_dir=$2; nproc=$3
name=block_between_rigid_plates
bash "$source_dir/tests/model/run_example.sh" "$exe" "$source_dir" \
  $name 2 0 "$nproc" > log.txt
grep "^Finished" log.txt
grep -q "^Finished: .* 0 cut-backs" log.txt || { echo "cut-backs"; exit 1; }
awk -F, '
  function abs(x) { return x < 0 ? -x : x }
  NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
  $c["time"] > 0 {
    t = $c["time"]; N = $c["plate_force_z"]
    x = t > 1 ? 3 * (t - 1) : 0; z = t > 1 ? 9 : 10 - t
    place = abs($c["plate_position_x"] - x) + abs($c["plate_position_z"] - z) + abs($c["floor_position_z"])
    if (place > worst_place) worst_place = place
    balance = (abs($c["plate_force_x"] + $c["floor_force_x"]) + abs(N + $c["floor_force_z"])) / N
    if (balance > worst_balance) worst_balance = balance
    y = (abs($c["plate_force_y"]) + abs($c["floor_force_y"])) / N
    if (y > worst_y) worst_y = y
    ratio = abs($c["plate_force_x"]) / N
    if (t <= 1 + 1e-9 && ratio > worst_before) worst_before = ratio
    if (t >= 1.4 - 1e-9) {
      e = abs(ratio - 0.05); if (e > worst_slide) worst_slide = e
      ++sliding
    }
    printf "t %.2f: plate at x %.3f z %.3f, N %.6g kN, |F_x| / N %.8f, floor %.8f\n", t, $c["plate_position_x"], $c["plate_position_z"], N, ratio, abs($c["floor_force_x"]) / -$c["floor_force_z"]
  }
  END {
    printf "plate place %.1e mm; balance %.2e; y forces %.2e; before the slide |F_x|/N %.1e; sliding (%d rows) |F_x|/N - 0.05: %.2e\n", worst_place, worst_balance, worst_y, worst_before, sliding, worst_slide
    exit (worst_place > 1e-12 || worst_balance > 1e-8 || worst_y > 1e-10 || worst_before > 1e-12 || sliding < 5 || worst_slide > 1e-6)
  }' $name/time_history.csv

sed -e "s/set Friction coefficient = 0.05/set Friction coefficient = 0.2/" \
    -e "s/set Output directory *=.*/set Output directory = mu_0.2/" \
    $name.prm > mu_0.2.prm
"$exe" mu_0.2.prm > log_mu_0.2.txt
grep "^Finished" log_mu_0.2.txt
grep -q "^Finished: .* 0 cut-backs" log_mu_0.2.txt || { echo "cut-backs"; exit 1; }
awk -F, '
  function abs(x) { return x < 0 ? -x : x }
  NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
  $c["time"] > 0 {
    N = $c["plate_force_z"]; ratio = abs($c["plate_force_x"]) / N
    balance = (abs($c["plate_force_x"] + $c["floor_force_x"]) + abs(N + $c["floor_force_z"])) / N
    if (balance > worst_balance) worst_balance = balance
    if (ratio > 0.2 * (1 + 1e-12) || ratio < last - 1e-12) bad = 1
    last = ratio
  }
  END {
    printf "mu 0.2: balance %.2e; |F_x| / N at the end %.8f (rising, never above mu)\n", worst_balance, last
    exit (bad || worst_balance > 1e-8 || 0.2 - last > 1e-5)
  }' mu_0.2/time_history.csv
