#!/usr/bin/env bash
# Two elastic bars in longitudinal impact through a mortar contact pair
# (parameter_files/two_bars_impact.prm: identical steel bars, L = 100 mm,
# A = 100 mm^2, the striker at v0 = 10 m/s, non-matching end-face meshes
# 4 x 4 against 6 x 6, 0.05 mm apart). One-dimensional wave theory (e.g.
# Graff, Wave Motion in Elastic Solids, 1975, sect. 2.1; the set-up of
# shared/references/contact-and-implicit.md, sect. (iv)): from the touch at
# t0 = 0.05 mm / v0 the interface carries F = rho c A v0 / 2 (c = sqrt(E /
# rho) = 5172 mm/ms: 20.30 kN) for 2 L / c = 0.03867 ms; then the striker
# stands still and the target moves at v0 with all the momentum. Checked
# (bounds of the issue):
#  - the mean normal force over the middle half of the contact within 3 %
#    of F (the 3D bars ring about the plateau: lateral inertia), measured
#    as the impulse over that time, the striker's loss of momentum divided
#    by it (the striker feels no other force). Not the mean of the force
#    column's rows: they sample the ringing, which is fast against the rows
#    at high penalty (at Penalty scale 9, 10, 11 the rows' mean is +26.5,
#    +25.5 and -7.3 % off F, the impulse's -0.08, +0.07 and +0.01 %);
#  - the contact duration, between the interpolated crossings of F / 2 on
#    the way up and down, within 2 % of 2 L / c;
#  - the momenta exchanged: at the end the striker keeps at most 2 % of
#    its initial momentum and the target has it within 2 %;
#  - momentum is exchanged exactly: the sum of the two bars' momenta stays
#    the initial one to 1e-8 relative at every row (the columns hold 9
#    digits; a wrong exchange shows at 1e-3 and above) (the slave nodes get
#    sum_a D_ab t_a and the master nodes -sum_a M_ak t_a, and the rows of D
#    and M have the same sums), and the pair's force has no y, z component
#    (1e-9 of F: the end faces stay flat and normal to x);
#  - the energy error at most 1 % (energy_error column, all rows);
#  - insensitive to the penalty: with Penalty scale 10 instead of 1 the
#    plateau and the duration change by less than 1 %, and the striker's
#    remaining momentum by less than 1 % of p0 (it is 1.6 % at scale 1 and
#    2.1 % at 10: the 3D bars ring laterally and part less cleanly than
#    the 1D theory, so the 2 % bound on it is checked at the default scale
#    only); all the other checks hold at both scales.
# The same pair made symmetric, once as Two-pass and once as self-contact
# (both end faces on both sides: each facet touches the other bar's as
# slave and as master, with half the penalty each), passes the same checks
# and gives the one-pass plateau and duration within 1 %.
# On 2 ranks the contact columns also equal a 1-rank run's to 1e-8
# relative (plus 1e-9 kN, GPa, mm absolute for values that pass through 0).
# Usage: two_bars_impact.sh EXECUTABLE SOURCE_DIR NPROC
set -euo pipefail
exe=$1; source_dir=$2; nproc=$3
source "$source_dir/tests/model/script_helpers.sh"

# prm SCALE DIRECTORY [VARIANT]: the example with the given penalty scale,
# one-pass, or VARIANT two-pass or self.
prm() {
  local variant=()
  case "${3:-}" in
    two-pass) variant=(-e "s|set Type *= frictionless|set Type = frictionless\n    set Two-pass = true|") ;;
    self) variant=(-e "s|set Slave boundary ids *=.*|set Slave boundary ids = 1, 2|"
                   -e "s|set Master boundary ids *=.*|set Master boundary ids = 1, 2|") ;;
  esac
  sed "${variant[@]}" \
      -e "s|set Mesh file *= *\(meshes/.*\)|set Mesh file = $source_dir/parameter_files/\1|" \
      -e "s|set Penalty scale *=.*|set Penalty scale = $1|" \
      -e "s|set History output interval *=.*|set History output interval = 0.0002|" \
      -e "s|set Field output interval *=.*|set Field output interval = 0|" \
      -e "s|set Output directory *=.*|set Output directory = $2|" \
      "$source_dir/parameter_files/two_bars_impact.prm"
}

# metrics CSV STRICT: plateau, duration and the checks of one run (the
# momenta's 2 % bound if STRICT is 1); prints "plateau duration
# striker_momentum/p0" on its last line, exits 1 on a violated bound.
metrics() {
  awk -F, -v strict="$2" '
    NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
    { n = NR - 1; t[n] = $c["time"]; f[n] = $c["impact_normal_force"]
      fx[n] = $c["impact_force_x"]; fy[n] = $c["impact_force_y"]; fz[n] = $c["impact_force_z"]
      ps[n] = $c["striker_momentum_x"]; pt[n] = $c["target_momentum_x"]
      e[n] = $c["energy_error"] }
    END {
      E = 210; rho = 7.85e-6; A = 100; v0 = 10; L = 100
      cbar = sqrt(E / rho); F = rho * cbar * A * v0 / 2; T = 2 * L / cbar; t0 = 0.05 / v0
      p0 = rho * A * L * v0
      for (r = 1; r <= n; ++r)
        if (t[r] >= t0 + 0.25 * T && t[r] <= t0 + 0.75 * T) { if (!a) a = r; b = r }
      plateau = (ps[a] - ps[b]) / (t[b] - t[a])
      for (r = 2; r <= n; ++r) {
        if (!up && f[r - 1] < F / 2 && f[r] >= F / 2) up = t[r - 1] + (t[r] - t[r - 1]) * (F / 2 - f[r - 1]) / (f[r] - f[r - 1])
        if (f[r - 1] >= F / 2 && f[r] < F / 2) down = t[r - 1] + (t[r] - t[r - 1]) * (f[r - 1] - F / 2) / (f[r - 1] - f[r])
      }
      duration = down - up
      for (r = 1; r <= n; ++r) {
        d = (ps[r] + pt[r]) / p0 - 1; if (d < 0) d = -d; if (d > drift) drift = d
        s = (fy[r] < 0 ? -fy[r] : fy[r]) + (fz[r] < 0 ? -fz[r] : fz[r]); if (s > side) side = s
        if (e[r] > worst_energy) worst_energy = e[r]
      }
      printf "plateau %.5g kN (rho c A v0 / 2 = %.5g kN, %+.2f %%)\n", plateau, F, 100 * (plateau / F - 1)
      printf "contact duration %.5g ms (2 L / c = %.5g ms, %+.2f %%), from %.5g ms\n", duration, T, 100 * (duration / T - 1), up
      printf "momenta at the end: striker %.4f p0, target %.4f p0; total drift %.2e\n", ps[n] / p0, pt[n] / p0, drift
      printf "largest lateral pair force %.2e kN; largest energy error %.3g %%\n", side, 100 * worst_energy
      bad = (plateau / F - 1 > 0.03 || plateau / F - 1 < -0.03)
      bad = bad || (duration / T - 1 > 0.02 || duration / T - 1 < -0.02)
      if (strict) bad = bad || (ps[n] / p0 > 0.02 || ps[n] / p0 < -0.02) || (pt[n] / p0 - 1 > 0.02 || pt[n] / p0 - 1 < -0.02)
      bad = bad || drift > 1e-8 || side > 1e-9 * F || worst_energy > 0.01
      printf "%.10g %.10g %.10g\n", plateau, duration, ps[n] / p0
      exit bad
    }' "$1"
}

prm 1 stiff1 > stiff1.prm
prm 10 stiff10 > stiff10.prm
run_prm stiff1.prm stiff1.log
run_prm stiff10.prm stiff10.log
echo "Penalty scale 1:"
metrics stiff1/time_history.csv 1 | tee stiff1.metrics | sed '$d'
echo "Penalty scale 10:"
metrics stiff10/time_history.csv 0 | tee stiff10.metrics | sed '$d'
read -r plateau1 duration1 left1 < <(tail -1 stiff1.metrics)
read -r plateau10 duration10 left10 < <(tail -1 stiff10.metrics)
awk -v a="$plateau1" -v b="$plateau10" -v c="$duration1" -v d="$duration10" \
    -v e="$left1" -v f="$left10" 'BEGIN {
  dp = b / a - 1; dd = d / c - 1; dm = f - e
  printf "penalty x10: plateau %+.3f %%, duration %+.3f %%, striker momentum %+.3f %% of p0\n", 100 * dp, 100 * dd, 100 * dm
  exit (dp > 0.01 || dp < -0.01 || dd > 0.01 || dd < -0.01 || dm > 0.01 || dm < -0.01) }'

for variant in two-pass self; do
  prm 1 "$variant" "$variant" > "$variant.prm"
  run_prm "$variant.prm" "$variant.log"
  echo "$variant:"
  metrics "$variant/time_history.csv" 1 | tee "$variant.metrics" | sed '$d'
  read -r plateau duration left < <(tail -1 "$variant.metrics")
  awk -v a="$plateau1" -v b="$plateau" -v c="$duration1" -v d="$duration" -v v="$variant" 'BEGIN {
    dp = b / a - 1; dd = d / c - 1
    printf "%s against one-pass: plateau %+.3f %%, duration %+.3f %%\n", v, 100 * dp, 100 * dd
    exit (dp > 0.01 || dp < -0.01 || dd > 0.01 || dd < -0.01) }'
done

if [ "$nproc" -gt 1 ]; then
  nproc=1
  prm 1 serial > serial.prm
  run_prm serial.prm serial.log
  bash "$source_dir/tests/model/compare_columns.sh" stiff1/time_history.csv \
    serial/time_history.csv 1e-8 1e-9 impact_normal_force impact_force_x \
    impact_max_pressure impact_min_pressure impact_contact_area \
    impact_max_penetration impact_active_nodes striker_momentum_x \
    target_momentum_x
fi
