#!/usr/bin/env python3
"""List the functions in include/ and source/ longer than a limit (issue 43).

A function's length is counted from the line of its signature (the line that
names the function and opens its parameter list) to its closing brace, both
included. The code is clang-formatted with deal.II's settings, so a function
body's opening brace stands alone on a line at the signature's indentation and
its closing brace is the next line at that indentation that starts with "}";
blocks of control statements are indented further, and class, struct, enum and
namespace bodies are recognised by their keyword and skipped.

Usage: function_lengths.py [--limit N] [ROOT]   (ROOT: the source tree,
default the parent of this script's folder; N: default 150)
Prints "FILE:LINE: LENGTH lines: NAME" for every longer function, longest
first, and a one-line summary. The exit status is 0 either way: this is a
report, not a check.
"""

import argparse
import os
import re
import sys

SOURCE_FOLDERS = ["include", "source"]
EXTENSIONS = (".h", ".cc")

OPEN_BRACE = re.compile(r"^(\s*)\{\s*(//.*)?$")
ATTRIBUTE = re.compile(r"__attribute__\s*\(\(.*?\)\)")
NOT_A_FUNCTION = re.compile(
    r"^\s*(template\s*<.*>\s*)?(class|struct|union|enum|namespace|extern)\b")


def indentation(line):
    return len(line) - len(line.lstrip(" "))


def declaration_before(lines, brace):
    """The lines of the declaration that ends just above line @p brace.

    Walks up from the brace while the lines belong to one declaration: not
    blank, not the end of a statement, a block or a comment, and indented at
    least as far as the brace.
    """
    indent = indentation(lines[brace])
    start = brace
    while start > 0:
        line = lines[start - 1]
        stripped = line.strip()
        if (not stripped or indentation(line) < indent
                or stripped.endswith((";", "}", "*/"))
                or stripped.startswith(("//", "#", "*/", "}"))):
            break
        start -= 1
    return start


def functions_in(lines):
    """(signature line, closing line, name) of each function body in @p lines
    (indices from 0)."""
    result = []
    for brace, line in enumerate(lines):
        match = OPEN_BRACE.match(line)
        if not match:
            continue
        indent = len(match.group(1))
        start = declaration_before(lines, brace)
        if start == brace or NOT_A_FUNCTION.match(" ".join(
                l.strip() for l in lines[start:brace])):
            continue
        signature = None
        for i in range(start, brace):
            text = ATTRIBUTE.sub("", lines[i])
            if (indentation(lines[i]) == indent and "(" in text
                    and not text.lstrip().startswith(
                        ("template", ":", ","))):
                signature = i
                break
        if signature is None:
            continue
        closing = re.compile(r"^ {%d}\}" % indent)
        end = next((i for i in range(brace + 1, len(lines))
                    if closing.match(lines[i])), None)
        if end is None:
            continue
        name = ATTRIBUTE.sub("", lines[signature]).split("(")[0].split()[-1]
        result.append((signature, end, name))
    return result


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--limit", type=int, default=150)
    parser.add_argument("root", nargs="?",
                        default=os.path.join(os.path.dirname(__file__), ".."))
    arguments = parser.parse_args()

    long_functions = []
    n_functions = 0
    for folder in SOURCE_FOLDERS:
        for directory, _, files in os.walk(os.path.join(arguments.root,
                                                        folder)):
            for file in sorted(files):
                if not file.endswith(EXTENSIONS):
                    continue
                path = os.path.join(directory, file)
                with open(path, encoding="utf-8") as stream:
                    lines = stream.read().split("\n")
                for signature, end, name in functions_in(lines):
                    n_functions += 1
                    length = end - signature + 1
                    if length > arguments.limit:
                        long_functions.append(
                            (length, os.path.relpath(path, arguments.root),
                             signature + 1, name))

    for length, path, line, name in sorted(long_functions,
                                           key=lambda f: (-f[0], f[1], f[2])):
        print("%s:%d: %d lines: %s" % (path, line, length, name))
    print("%d of %d functions longer than %d lines" %
          (len(long_functions), n_functions, arguments.limit))
    return 0


if __name__ == "__main__":
    sys.exit(main())
