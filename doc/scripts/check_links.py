#!/usr/bin/env python3
"""Check the Markdown links of the documentation: every relative link
[text](path#anchor) in README.md, doc/**/*.md, benchmarks/**/*.md and
parameter_files/**/*.md must name a file that exists and, for a .md file,
a heading of it (GitHub's anchors: lower case, punctuation dropped, spaces
to '-'). Prints each broken link and exits 1 if there is any.

    python3 doc/scripts/check_links.py [SOURCE_DIR]
"""
import glob
import os
import re
import sys

root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(
    os.path.dirname(os.path.abspath(__file__)), "..", "..")
os.chdir(root)


def anchor(title):
    title = title.strip().replace("`", "")
    return re.sub(r"[^\w\- ]", "", title.lower()).replace(" ", "-")


def headings(path):
    out, code = set(), False
    for line in open(path, encoding="utf-8").read().split("\n"):
        if line.startswith("```"):
            code = not code
            continue
        m = re.match(r"^#+ (.*)", line)
        if m and not code:
            out.add(anchor(m.group(1)))
    return out


files = sorted(set(["README.md"] + glob.glob("doc/**/*.md", recursive=True)
                   + glob.glob("benchmarks/**/*.md", recursive=True)
                   + glob.glob("parameter_files/**/*.md", recursive=True)))
link = re.compile(r"\]\(([^)\s]+)\)")
broken = 0
for f in files:
    code = False
    for number, line in enumerate(open(f, encoding="utf-8").read().split("\n"), 1):
        if line.startswith("```"):
            code = not code
        if code:
            continue
        for target in link.findall(line):
            if re.match(r"^[a-z]+:", target):
                continue
            path, _, name = target.partition("#")
            full = os.path.normpath(os.path.join(os.path.dirname(f), path)) if path else f
            if not os.path.exists(full):
                print(f"{f}:{number}: no file {target}")
                broken += 1
            elif name and full.endswith(".md") and name not in headings(full):
                print(f"{f}:{number}: no heading #{name} in {full}")
                broken += 1
print(f"check_links.py: {len(files)} files, {broken} broken links")
sys.exit(1 if broken else 0)
