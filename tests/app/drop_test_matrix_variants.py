#!/usr/bin/env python3
"""The shipped parameter study parameter_files/drop_test_matrix/ (variants
that include ../drop_test_cylinder.prm and override the impactor's mass and
velocity) runs, each variant shortened by a file that includes it in turn
(two levels of include): 80 cells, the run stopped after the rebound.

Checked per variant, from time_history.csv:
- the variant's values reached the run: the first row's kinetic energy is
  M V0^2 / 2 of the variant's M and V0 (J; exact up to the printed digits,
  1e-8 relative), not the base's 5 kg at 2 m/s (10 J);
- the run is sound: |energy_error| at most 2e-4 in every row (the energy
  balance; measured 1.4e-5 to 5.7e-5 on these four cases at 80 cells, so
  the bound is about three times the largest);
- the impactor came back: after the largest compression its displacement
  (positive into the rubber) is below half of it in the last row (the run
  stops 1 ms after the impactor has left the rubber).

Usage: drop_test_matrix_variants.py RUBBERDYN SOURCE_DIR WORK_DIRECTORY
"""

import csv
import glob
import os
import re
import shutil
import subprocess
import sys

executable = os.path.abspath(sys.argv[1])
source = os.path.abspath(sys.argv[2])
work = os.path.abspath(sys.argv[3])
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)

variants = sorted(glob.glob(os.path.join(source, "parameter_files",
                                         "drop_test_matrix", "*.prm")))
assert variants, "no variants in parameter_files/drop_test_matrix"
failures = []
for variant in variants:
    name = os.path.splitext(os.path.basename(variant))[0]
    with open(variant) as f:
        text = f.read()
    mass = float(re.search(r"set Impactor mass\s*=\s*(\S+)", text).group(1))
    speed = float(re.search(r"set Impact velocity\s*=\s*(\S+)",
                            text).group(1))
    short = os.path.join(work, name + "_short.prm")
    with open(short, "w") as f:
        f.write(f"include {variant}\n"
                "subsection Drop test\n  set Global refinement = 1\nend\n"
                f"subsection Output\n  set Output directory = {name}\nend\n")
    result = subprocess.run([executable, short], cwd=work,
                            capture_output=True, text=True, timeout=300)
    rows = []
    history = os.path.join(work, name, "time_history.csv")
    if result.returncode == 0 and os.path.exists(history):
        with open(history) as f:
            rows = list(csv.DictReader(f))
    if not rows:
        print(f"{name}: FAILED: exit code {result.returncode}\n"
              f"  {result.stderr.strip()[:400]}")
        failures.append(name)
        continue
    kinetic = float(rows[0]["kinetic_energy"])
    expected = 0.5 * mass * speed ** 2
    worst_error = max(abs(float(row["energy_error"])) for row in rows)
    displacement = [float(row["impactor_displacement"]) for row in rows]
    # (impactor_displacement: positive into the rubber.)
    deepest = max(displacement)
    came_back = deepest > 0. and displacement[-1] < 0.5 * deepest
    ok = (abs(kinetic / expected - 1.) < 1e-8 and worst_error <= 2e-4 and
          came_back)
    print(f"{name}: {'ok' if ok else 'FAILED'}: M = {mass} kg, V0 = {speed} "
          f"m/s, first kinetic energy {kinetic} J (M V0^2/2 = {expected} J), "
          f"largest |energy error| {worst_error:.2e}, compression to "
          f"{deepest:.4f} mm then back to {displacement[-1]:.4f} mm")
    if not ok:
        failures.append(name)

print(f"drop-test matrix variants: {len(variants) - len(failures)} passed, "
      f"{len(failures)} failed")
sys.exit(1 if failures else 0)
