#!/usr/bin/env bash
# Bolt preload through a pretension section (parameter_files/bolted_plates.prm:
# an M16 steel bolt clamping two aluminium plates, the section z = 3.75
# across the shank, force-controlled to 84 kN at t = 1, then locked), run
# quasi-static only, with
# the load path continued to t = 2 under a separating load: a traction on
# the upper plate's top face rising from 0 at t = 1 to a resultant of 20 kN
# (upwards) at t = 2.
# Requirements:
# - the preload: bolt_section_force = 84 t kN up to t = 1, to 1e-6 relative
#   (the issue asks 0.5 %; the force is an equation of the Newton system);
# - the lock: bolt_section_shortening is constant from t = 1 on (the same
#   9 printed digits) while the force changes;
# - the joint diagram (VDI 2230): under the separating load F_A the bolt
#   force rises by Phi F_A with 0 < Phi < 1 (the plates, not the bolt, take
#   most of it back: measured Phi = 0.044), and the support carries the
#   rest: support_force_z = -pull_force_z to 1e-8 relative (global
#   equilibrium, the pretension being internal);
# - Clapeyron's theorem for the linear elastic joint at t = 1: the stored
#   energy is 1/2 N delta to 1e-3 (the finite-strain elements depart by
#   O(strain) ~ 3e-3 from linearity; measured 1.8e-4), and delta(0.5) /
#   delta(1) = 1/2 to 1e-3;
# - every load step converges in at most 4 Newton iterations;
# - the same shortening prescribed (Control = shortening, Shortening =
#   delta(1) of the first run) gives the force 84 kN to 1e-6 (1 rank).
# Usage: bolted_plates_pretension.sh EXECUTABLE SOURCE_DIR NPROC
set -euo pipefail
exe=$1; source_dir=$2; nproc=$3
name=bolted_plates
# 2348.0064 mm^2: the top face's area (the 24-gon annulus 12 <= r <= 30,
# parameter_files/meshes/README.md).
EXAMPLE_APPEND='subsection Boundary conditions
  set Names = support, pull
  subsection pull
    set Boundary ids        = 2
    set Type                = traction
    set Components          = z
    set Function expression = t < 1 ? 0 : 20 / 2348.0064 * (t - 1)
  end
end
subsection Time integration
  set Scheme                = quasi-static
  set Quasi-static end time = 2
  subsection Quasi-static
    set Maximum step = 0.5
  end
end' bash "$source_dir/tests/model/run_example.sh" "$exe" "$source_dir" \
  $name 1 0 "$nproc" > log.txt
awk '/^    iteration/ { ++k } /^  Step to/ { if (k > most) most = k; k = 0 }
     END { if (k > most) most = k; printf "at most %d Newton iterations per step\n", most; exit (most > 4) }' log.txt
awk -F, '
  function abs(x) { return x < 0 ? -x : x }
  NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
  {
    t = $c["time"]; N = $c["bolt_section_force"]; d = $c["bolt_section_shortening"]
    if (t > 0 && t <= 1 + 1e-9) {
      e = abs(N / (84 * t) - 1); if (e > worst) worst = e
      if (abs(t - 0.5) < 1e-9) half = d
      if (abs(t - 1) < 1e-9) { locked = d; N1 = N; E1 = $c["internal_energy"] }
    }
    if (t > 1 + 1e-9) {
      if ($c["bolt_section_shortening"] != locked) moved = 1
      pull = $c["pull_force_z"]
      b = abs(($c["support_force_z"] + pull) / pull); if (b > balance) balance = b
      p = abs(pull / (20 * (t - 1)) - 1); if (p > load) load = p
      N2 = N; F2 = pull
    }
    ++rows
  }
  END {
    phi = (N2 - N1) / F2
    clapeyron = abs(E1 / (0.5 * N1 * locked) - 1)
    linear = abs(half / locked - 0.5) / 0.5
    printf "%d rows; force vs 84 t: %.2e; at t = 1: N = %.6f kN, delta = %.6f mm\n", rows, worst, N1, locked
    printf "locked shortening constant: %s; Phi = %.4f; support vs pull %.2e; pull vs 20 (t - 1) %.2e\n", moved ? "no" : "yes", phi, balance, load
    printf "Clapeyron: energy / (N delta / 2) - 1 = %.2e; delta(0.5) / delta(1) - 1/2: %.2e\n", clapeyron, linear
    exit (rows < 4 || worst > 1e-6 || moved || !(phi > 0 && phi < 1) || balance > 1e-8 || load > 1e-6 || clapeyron > 1e-3 || linear > 1e-3)
  }' $name/time_history.csv

if [ "$nproc" -eq 1 ]; then
  delta=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
                   $c["time"] == 1 { print $c["bolt_section_shortening"] }' $name/time_history.csv)
  EXAMPLE_APPEND="subsection Pretension sections
  subsection bolt_section
    set Control    = shortening
    set Shortening = $delta
  end
end
subsection Time integration
  set Scheme = quasi-static
  subsection Quasi-static
    set Initial step = 1
    set Maximum step = 1
  end
end" bash "$source_dir/tests/model/run_example.sh" "$exe" "$source_dir" \
    $name 1 0 1 > log_shortening.txt
  awk -F, -v delta="$delta" '
    NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
    $c["time"] == 1 { N = $c["bolt_section_force"]; e = N / 84 - 1; if (e < 0) e = -e
      printf "shortening %s mm prescribed: force %.6f kN, %.2e from 84\n", delta, N, e; found = 1
      exit (e > 1e-6) }
    END { if (!found) exit 1 }' $name/time_history.csv
fi
