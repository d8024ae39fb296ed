#!/usr/bin/env python3
"""Check that rubberdyn's systems include each other one way down.

Every `#include <rubberdyn/SYSTEM/...>` (or "...") in include/rubberdyn/ and
source/ (and app/) must name a system on a lower layer than the including
file's own, or the same system. Systems on the same layer are independent of
each other. The layers are documented in doc/architecture.md; this list is
the one the test enforces:

    base
    io, materials, parameters, geometry
    model
    elements, contact
    time_integration
    postprocess
    simulation
    studies
    app

Usage: check_include_order.py [ROOT]   (ROOT: the source tree, default ..)
Prints one line per violation, "FILE:LINE: ..." naming both systems, and
exits 1 if there is any; prints a one-line summary and exits 0 otherwise.
"""

import os
import re
import sys

LAYERS = [
    ["base"],
    ["io", "materials", "parameters", "geometry"],
    ["model"],
    ["elements", "contact"],
    ["time_integration"],
    ["postprocess"],
    ["simulation"],
    ["studies"],
    ["app"],
]
LAYER_OF = {system: n for n, systems in enumerate(LAYERS) for system in systems}
INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]rubberdyn/([A-Za-z_0-9]+)/')


def system_of(root, path):
    """The system a file belongs to: its folder under include/rubberdyn/ or
    source/, or 'app' for app/."""
    relative = os.path.relpath(path, root).split(os.sep)
    if relative[0] == "include" and len(relative) > 3:
        return relative[2]
    if relative[0] == "source" and len(relative) > 2:
        return relative[1]
    if relative[0] == "app":
        return "app"
    return None


def files_under(root):
    for top in ("include/rubberdyn", "source", "app"):
        for folder, _, names in os.walk(os.path.join(root, top)):
            for name in sorted(names):
                if name.endswith((".h", ".cc")):
                    yield os.path.join(folder, name)


def main():
    root = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else
                           os.path.join(os.path.dirname(__file__), ".."))
    violations = []
    n_files = n_includes = 0
    for path in sorted(files_under(root)):
        own = system_of(root, path)
        shown = os.path.relpath(path, root)
        if own not in LAYER_OF:
            violations.append(f"{shown}:1: the system '{own}' is in no layer "
                              "of scripts/check_include_order.py (add it "
                              "there and in doc/architecture.md)")
            continue
        n_files += 1
        with open(path, encoding="utf-8", errors="replace") as text:
            for number, line in enumerate(text, start=1):
                match = INCLUDE.match(line)
                if not match:
                    continue
                n_includes += 1
                other = match.group(1)
                if other == own:
                    continue
                if other not in LAYER_OF:
                    violations.append(f"{shown}:{number}: includes the "
                                      f"unknown system '{other}'")
                elif LAYER_OF[other] > LAYER_OF[own]:
                    violations.append(
                        f"{shown}:{number}: '{own}' (layer {LAYER_OF[own]}) "
                        f"includes '{other}' (layer {LAYER_OF[other]}), "
                        "which is above it")
                elif LAYER_OF[other] == LAYER_OF[own]:
                    violations.append(
                        f"{shown}:{number}: '{own}' includes '{other}', "
                        f"which is on the same layer ({LAYER_OF[own]}): "
                        "systems on one layer are independent")
    for violation in violations:
        print(violation)
    if violations:
        print(f"{len(violations)} include(s) against the layer order")
        return 1
    print(f"include order: {n_includes} includes in {n_files} files, "
          "all one way down")
    return 0


if __name__ == "__main__":
    sys.exit(main())
