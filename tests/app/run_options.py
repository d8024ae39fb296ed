#!/usr/bin/env python3
"""The command-line options of a run (--simulate-crash-at, --trace-pair;
base/run_options.h): listed by --help, and each bad value refused before
anything runs with exit code 2 and one line naming the option. (The crash
itself is exercised by the restart tests, tests/restart/kill_and_restart.sh
and tests/model/*_restart.sh.)

Usage: run_options.py RUBBERDYN SOURCE_DIR WORK_DIRECTORY
"""

import os
import shutil
import subprocess
import sys

executable = os.path.abspath(sys.argv[1])
source = os.path.abspath(sys.argv[2])
work = os.path.abspath(sys.argv[3])
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
study = os.path.join(source, "parameter_files", "material_point_rubber.prm")
failures = []


def run(arguments):
    result = subprocess.run([executable] + arguments, cwd=work,
                            capture_output=True, text=True, timeout=60)
    return result.returncode, result.stdout, result.stderr


code, out, err = run(["--help"])
for option in ("--simulate-crash-at T", "--trace-pair NAME[:EVERY]"):
    if code != 0 or option not in out:
        failures.append("--help does not list " + option)

for arguments, expected in (
        (["--simulate-crash-at", "abc", study],
         "--simulate-crash-at: needs a time in ms (a number >= 0), not 'abc'"),
        (["--simulate-crash-at", "-1", study],
         "--simulate-crash-at: needs a time in ms (a number >= 0), not '-1'"),
        (["--trace-pair", ":5", study],
         "--trace-pair: needs the name of a contact pair"),
        (["--trace-pair", "pair:0", study],
         "--trace-pair: EVERY in NAME:EVERY must be a whole number of steps "
         "from 1 to 1e9, not '0'"),
        (["--trace-pair", "pair"],
         "no parameter file given after the options"),
        (["--simulate-crash-at", "1", "--check", study],
         "unknown option or extra argument in '--check'")):
    code, out, err = run(arguments)
    lines = err.strip().splitlines()
    ok = code in (1, 2) and lines and expected in lines[0] and \
        not os.listdir(work)
    print(f"{' '.join(arguments[:2])}: {'ok' if ok else 'FAILED'} "
          f"(exit code {code}) {lines[0] if lines else ''}")
    if not ok:
        failures.append(" ".join(arguments))

print(f"run options: {len(failures)} failed" +
      (": " + "; ".join(failures) if failures else ""))
sys.exit(1 if failures else 0)
