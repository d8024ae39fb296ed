#!/usr/bin/env bash
# Contact pairs/<name>/Penalty time step (LS-DYNA SOFT = 1; doc/contact.md,
# "The penalty"): the two bars' impact (parameter_files/two_bars_impact.prm,
# one-dimensional wave theory as in tests/model/two_bars_impact.sh: the
# interface carries F = rho c A v0 / 2 = 20.30 kN for 2 L / c = 0.03867
# ms, then the striker stands still and the target moves on with the
# momentum p0 = 0.785 kg mm/ms) with a stiff pair, Penalty scale 30, whose
# springs set the step (796 steps to 0.06 ms; 417 at scale 1), and the
# same pair with Penalty time step = 3e-4 ms. Checked with the bound:
#  - the log names the factor on the penalty, below 1;
#  - the step is the elements' again: at most 0.6 times the steps of the
#    stiff run (measured 455 against 796);
#  - the impact still happens as the theory says: the contact lasts 2 L / c
#    within 3 % (the first crossing of F / 2 up to the last one down: the
#    3D bars ring about the plateau), the striker keeps at most 3 % of p0,
#    the target gets p0 within 3 %, the two momenta sum to p0 within 1e-8
#    at every row, the energy error at most 1 %.
# Usage: penalty_time_step.sh EXECUTABLE SOURCE_DIR NPROC
set -euo pipefail
exe=$1; source_dir=$2; nproc=$3
run() { # run NAME PENALTY_TIME_STEP
  EXAMPLE_APPEND="subsection Contact pairs
  subsection impact
    set Penalty scale     = 30
    set Penalty time step = $2
  end
end" bash "$source_dir/tests/model/run_example.sh" "$exe" "$source_dir" \
    two_bars_impact 0.06 0.0002 "$nproc" > "$1.log"
  rm -rf "$1"; mv two_bars_impact "$1"
}
run stiff 0
run bounded 3e-4
steps() { sed -n 's/.*"time_steps": \([0-9]*\).*/\1/p' "$1/run_summary.json"; }
status=0
grep "Contact pair impact: penalty times" bounded.log || { echo "FAILED: no penalty factor in the log"; status=1; }
factor=$(sed -n 's/Contact pair impact: penalty times \([0-9.e-]*\) .*/\1/p' bounded.log)
awk -v f="${factor:-1}" 'BEGIN { exit !(f < 1) }' || { echo "FAILED: factor $factor"; status=1; }
echo "steps: stiff $(steps stiff), bounded $(steps bounded)"
awk -v a="$(steps stiff)" -v b="$(steps bounded)" 'BEGIN { exit !(b <= 0.6 * a) }' ||
  { echo "FAILED: the bounded run does not take a larger step"; status=1; }
awk -F, '
  NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
  {
    t = $c["time"]; f = -$c["impact_force_x"]; if ($c["impact_force_x"] > 0) f = $c["impact_force_x"]
    ps = $c["striker_momentum_x"]; pt = $c["target_momentum_x"]
    d = ps + pt - 0.785; if (d < 0) d = -d; if (d > drift) drift = d
    e = $c["energy_error"]; if (e > err) err = e
    if (!up && f >= F / 2) { up = tl + (t - tl) * (F / 2 - fl) / (f - fl) }
    if (up && f < F / 2 && fl >= F / 2) { down = tl + (t - tl) * (fl - F / 2) / (fl - f) }
    tl = t; fl = f
  }
  BEGIN { F = 7.85e-6 * sqrt(210 / 7.85e-6) * 100 * 10 / 2; T = 2 * 100 / sqrt(210 / 7.85e-6); p0 = 0.785 }
  END {
    printf "bounded: contact for %.5g ms (2 L / c = %.5g, %+.2f %%), striker keeps %.3g %% of p0, target %.3g %%, momentum drift %.3g, energy error %.3g %%\n", down - up, T, 100 * ((down - up) / T - 1), 100 * ps / p0, 100 * pt / p0, drift, 100 * err
    bad = ((down - up) / T - 1)^2 > 0.03^2
    bad = bad || ps > 0.03 * p0 || (pt / p0 - 1)^2 > 0.03^2 || drift > 1e-8 * p0 || err > 0.01
    exit bad
  }' bounded/time_history.csv || { echo "FAILED: the impact"; status=1; }
exit $status
