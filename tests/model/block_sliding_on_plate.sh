#!/usr/bin/env bash
# A rubber block pressed onto a fixed steel plate (a rigid part) and pulled
# across it, through a mortar contact pair with Coulomb friction
# (parameter_files/block_sliding_on_plate.prm: non-matching meshes, the
# top pressed down by 0.5 mm, then pulled along x at v0 = 1 mm/ms from
# 1.5 ms on). Checked against Coulomb's law (bounds of the issue):
#  - it sticks first: after the pull starts, a row with the pair's friction
#    force -F_x between 0 and 0.9 mu F_z and fewer slipping than active
#    nodes;
#  - it slides at mu N: in steady sliding (t >= 3 ms, all active nodes
#    slipping) the pair's -F_x / F_z is mu within 1 % at every row, and
#    the pull's reaction averaged over the phase is mu times the press's
#    within 1 % (the reaction rings with the rubber's shear modes, which
#    nothing damps: rows differ by up to 20 %, the mean does not);
#  - the friction work over the steady phase equals the work of the
#    friction force along the block's path, sum T du_x over the rows (the
#    block's bottom moves with its top once the shear is steady), within
#    2 %;
#  - the decay law mu = FD + (FS - FD) exp(-DC v) is checked with the
#    motion prescribed, in tests/contact/mortar_friction.cc (to 1e-12):
#    in this dynamic run friction that falls with the slip rate makes the
#    block stick and slip in its shear modes (FS = 0.3, FD = 0.15, DC =
#    1 ms/mm at v0 = 1 mm/ms: -F_x / F_z swings between 0.17 and 0.28
#    about a mean of 0.244 against mu(v0) = 0.273 with DC = 0.2; the
#    same with an elastic steel block), the classic rate-weakening
#    instability, which nothing here damps;
#  - the energy error stays below 1 % (energy_error column);
#  - the books balance: the only contributions that are not exactly
#    conservative are the pair and the time discretisation (the Yeoh
#    elements' forces derive from their energy, the pull's and press's
#    work is booked), so the run's signed energy error (kinetic + internal
#    + contact energy + bulk-viscosity and friction work - external work,
#    from its first row) is the pair's energy_error column (the work its
#    forces did on the solid less what its springs and friction took) to
#    1e-3 of the friction work at every row (measured: below 1e-6 of it),
#    and the pair creates less than 0.5 % of its friction work (measured
#    0.12 %: the nodal normals' and the mortar integrals' change is left
#    out of the forces).
# Usage: block_sliding_on_plate.sh EXECUTABLE SOURCE_DIR NPROC
set -euo pipefail
exe=$1; source_dir=$2; nproc=$3
source "$source_dir/tests/model/script_helpers.sh"

# prm NAME FS FD DC V0: the example with these friction constants and
# pulling speed, written to NAME.prm (results in NAME/).
prm() {
  sed -e "s|set Mesh file *= *\(meshes/.*\)|set Mesh file = $source_dir/parameter_files/\1|" \
      -e "s|set Static friction coefficient *=.*|set Static friction coefficient = $2|" \
      -e "s|set Dynamic friction coefficient *=.*|set Dynamic friction coefficient = $3|" \
      -e "s|set Type *= Coulomb|set Type = Coulomb\n    set Decay coefficient = $4|" \
      -e "s|v0 = 1, t1 = 1, t2 = 1.5|v0 = $5, t1 = 1, t2 = 1.5|" \
      -e "s|set Field output interval *=.*|set Field output interval = 0|" \
      -e "s|set Output directory *=.*|set Output directory = $1|" \
      "$source_dir/parameter_files/block_sliding_on_plate.prm" > "$1.prm"
}

# check CSV MU FULL: the checks of one run with the friction coefficient MU
# expected in steady sliding; FULL = 1 adds the stick, reaction and work
# checks.
check() {
  awk -F, -v mu="$2" -v full="$3" '
    NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
    { t = $c["time"]; fx = -$c["sliding_force_x"]; fz = $c["sliding_force_z"]
      active = $c["sliding_active_nodes"]; slipping = $c["sliding_slipping_nodes"]
      if ($c["energy_error"] > worst_energy) worst_energy = $c["energy_error"]
      books = $c["kinetic_energy"] + $c["internal_energy"] + $c["contact_work"] + \
              $c["bulk_viscosity_work"] + $c["friction_work"] - $c["external_work"]
      if (NR == 2) books0 = books
      d = books - books0 - $c["sliding_energy_error"]; if (d < 0) d = -d
      if (d > worst_books) worst_books = d
      created = $c["sliding_energy_error"]; dissipated = $c["sliding_friction_work"]
      if (t > 1.5 && t < 3 && fx > 0 && fx < 0.9 * mu * fz && slipping < active) stuck = 1
      if (t >= 3) {
        if (slipping != active) partial = 1
        r = fx / fz / mu - 1; if (r < 0) r = -r; if (r > worst_ratio) worst_ratio = r
        pull += $c["pull_force_x"]; press += -$c["press_force_z"]; ++rows
        x = t - 1.25 # the pull at v0 = 1 mm/ms: v0 (t - (t1 + t2) / 2)
        if (have) path_work += 0.5 * (T + $c["sliding_tangential_force"]) * (x - x_old)
        else work0 = $c["sliding_friction_work"]
        T = $c["sliding_tangential_force"]; x_old = x; have = 1
        work1 = $c["sliding_friction_work"]
      }
    }
    END {
      printf "mu %.5g: steady -F_x / F_z within %.3f %% of mu; all active nodes slipping: %s\n", mu, 100 * worst_ratio, partial ? "no" : "yes"
      bad = worst_ratio > 0.01 || partial || worst_energy > 0.01
      if (full) {
        reaction = pull / press / mu - 1
        work = (work1 - work0) / path_work - 1
        printf "sticks first: %s; mean pull reaction / (mu press reaction) - 1 = %+.3f %%\n", stuck ? "yes" : "no", 100 * reaction
        printf "friction work %.6g J, friction force along the path %.6g J (%+.3f %%)\n", work1 - work0, path_work, 100 * work
        bad = bad || !stuck || reaction > 0.01 || reaction < -0.01 || work > 0.02 || work < -0.02
      }
      printf "largest energy error %.3g %%\n", 100 * worst_energy
      printf "signed energy error of the run less the pair energy_error: at most %.3g of its friction work; the pair created %.3g %% of it\n", worst_books / dissipated, 100 * created / dissipated
      bad = bad || worst_books > 1e-3 * dissipated || created > 5e-3 * dissipated || created < -5e-3 * dissipated
      exit bad
    }' "$1"
}

prm constant 0.2 0.2 0 1
run_prm constant.prm constant.log
check constant/time_history.csv 0.2 1
