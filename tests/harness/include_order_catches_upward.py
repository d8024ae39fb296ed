#!/usr/bin/env python3
"""The include-order check fails, naming the file and the line, on an upward
include: a copy of the tree gets `#include <rubberdyn/studies/study.h>` in
model/model.h (model is below studies) and one between the independent
siblings elements and contact; the check must exit 1 and name both. The
unchanged copy must pass (the check itself is not what fails)."""

import os
import shutil
import subprocess
import sys
import tempfile

source_root = sys.argv[1]
checker = os.path.join(source_root, "scripts", "check_include_order.py")

with tempfile.TemporaryDirectory() as copy:
    for top in ("include", "source", "app"):
        shutil.copytree(os.path.join(source_root, top), os.path.join(copy, top))

    def run():
        result = subprocess.run([sys.executable, checker, copy],
                                capture_output=True, text=True)
        return result.returncode, result.stdout

    code, out = run()
    assert code == 0, "the unchanged tree fails:\n" + out

    def append(relative, line):
        path = os.path.join(copy, relative)
        with open(path) as f:
            n_lines = sum(1 for _ in f)
        with open(path, "a") as f:
            f.write(line + "\n")
        return n_lines + 1

    upward = append("include/rubberdyn/model/model.h",
                    "#include <rubberdyn/studies/study.h>")
    sideways = append("source/contact/rigid_surface_forces.cc",
                      "#include \"rubberdyn/elements/solid_hex_forces.h\"")
    code, out = run()
    print(out, end="")
    assert code == 1, f"exit code {code}, expected 1"
    expected = [
        f"include/rubberdyn/model/model.h:{upward}: 'model' (layer 2) "
        "includes 'studies' (layer 7), which is above it",
        f"source/contact/rigid_surface_forces.cc:{sideways}: 'contact' "
        "includes 'elements', which is on the same layer (3): systems on "
        "one layer are independent",
        "2 include(s) against the layer order",
    ]
    for line in expected:
        assert line in out.splitlines(), "missing: " + line
print("OK: the upward and the sideways include are named, file and line")
