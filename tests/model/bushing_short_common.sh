# Sourced by tests/model/bushing_short_plate5.sh and bushing_short_plate4.sh
# (they set exe, source_dir, nproc): the shortened drop-tower tests of
# parameter_files/bushing_test_N.prm (issue 10, doc/bushing.md); and by
# benchmarks/bushing.sh for bushing_variant.
#
# The shortened version of a test: the shipped file on the coarse mesh
# (meshes/bushing_1.msh or bushing_1_plate4.msh, n = 1: 7394 cells), the
# preload in one load step of the whole pseudo-time (10 Newton iterations;
# the shipped four quarter steps take 28 in all), 0.1 ms of impact, a
# history row every 0.002 ms.

# bushing_variant N MESH_N END STEP DIRECTORY [HISTORY_INTERVAL]: writes
# DIRECTORY.prm, parameter_files/bushing_test_N.prm ($source_dir set) on
# the mesh of density MESH_N (1: meshes/bushing_1*.msh; 2: the shipped
# meshes/bushing*.msh), END ms of impact, load steps of STEP (at most 25
# Newton iterations each), its outputs in DIRECTORY and, if given, a
# history row every HISTORY_INTERVAL ms. Every substitution must take.
bushing_variant() {
  local test=$1 mesh_n=$2 end=$3 step=$4 directory=$5 interval=${6:-}
  local suffix=""
  [ "$mesh_n" = 1 ] && suffix="_1"
  sed -e "s|set Mesh file *= *meshes/bushing\(.*\)\.msh|set Mesh file = $source_dir/parameter_files/meshes/bushing$suffix\1.msh|" \
      -e "s|set End time  *= 40|set End time = $end|" \
      ${interval:+-e "s|set History output interval = .*|set History output interval = $interval|"} \
      -e "s|set Output directory  *= output/bushing_test_$test|set Output directory = $directory|" \
      -e "s|set Initial step  *= 0.25|set Initial step = $step|" \
      -e "s|set Maximum step  *= 0.25|set Maximum step = $step\n    set Maximum iterations = 25|" \
      "$source_dir/parameter_files/bushing_test_$test.prm" > "$directory.prm"
  local expected
  for expected in "parameter_files/meshes/bushing$suffix" "End time = $end" \
                  "directory = $directory" "Initial step = $step" \
                  "Maximum iterations = 25" \
                  ${interval:+"interval = $interval"}; do
    grep -q "$expected" "$directory.prm" ||
      { echo "$directory.prm: no '$expected'"; exit 1; }
  done
}

# run_short N: the shortened test N, its log in bushing_test_N.log.
run_short() {
  rm -rf "bushing_test_$1"
  bushing_variant "$1" 1 0.1 1 "bushing_test_$1" 0.002
  if [ "$1" = 3 ] || [ "$1" = 4 ]; then
    # Test 2's preload (the shipped files restart from it).
    mkdir -p "bushing_test_$1/preload"
    cp -r bushing_test_2/preload/checkpoint "bushing_test_$1/preload/"
  fi
  run_prm "bushing_test_$1.prm" "bushing_test_$1.log"
}

# check_short N V0: the acceptance on the shortened test N, whose
# weight falls at V0 (mm/ms) from 0.5 mm above the plate:
#  - no added mass;
#  - the preload: the pretension section's force at the hand-off within
#    0.5 % of 84 kN (measured: 84 to every printed digit), and the cross
#    section 'shank' in the same plane (bolt_axial_force) carries the same
#    force to 1e-6 relative until the weight arrives (statics);
#  - a quiet hand-off: before the weight touches the plate (the rows
#    before the first with a weight_plate force) the deformable parts' kinetic
#    energy is below 1e-10 of their internal energy (the bound is
#    1e-3; measured: about 1e-22, round-off);
#  - the energy error at most 2 % of the largest energy at every row;
#  - the impact: the weight pushed up by the plate (drop_weight_force
#    above 1 kN at some row) and slowed.
check_short() {
  grep -q "added mass 0 kg" "bushing_test_$1.log" ||
    { echo "test $1: added mass (or no mass line) in the log"; exit 1; }
  awk -F, -v test="$1" -v v0="$2" '
    function abs(x) { return x < 0 ? -x : x }
    BEGIN { n = split("bolt nut washer inner_sleeve rubber plastic_sleeve metal_sleeve plate brace", parts, " ") }
    NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
    { t = $c["time"]
      if (NR == 2) preload = $c["bolt_section_force"]
      ke = 0; ie = 0
      for (k = 1; k <= n; ++k) {
        ke += $c[parts[k] "_kinetic_energy"]; ie += $c[parts[k] "_internal_energy"]
      }
      if ($c["weight_plate_normal_force"] > 0) touched = 1
      if (!touched) {
        ++quiet_rows
        if (ke / ie > quiet) quiet = ke / ie
        d = abs($c["bolt_axial_force"] - $c["bolt_section_force"]) / $c["bolt_section_force"]
        if (d > section) section = d
      }
      if ($c["energy_error"] > error) error = $c["energy_error"]
      if ($c["drop_weight_force"] > peak) { peak = $c["drop_weight_force"]; peak_t = t }
      v = $c["drop_weight_velocity_z"] }
    END {
      printf "test %d: preload %.6g kN; before the weight touches the plate (%d rows): kinetic / internal energy of the deformable parts at most %.2g, cross section against pretension section %.2g\n", test, preload, quiet_rows, quiet, section
      printf "test %d: peak drop_weight_force %.4g kN at %.3g ms, the weight at %.4g mm/ms at the end (V0 %s); largest energy error %.3g %%\n", test, peak, peak_t, v, v0, 100 * error
      exit (abs(preload - 84) > 0.005 * 84 || quiet_rows < 5 || quiet > 1e-10 || section > 1e-6 || error > 0.02 || peak < 1 || !(v > -v0))
    }' "bushing_test_$1/time_history.csv"
}
